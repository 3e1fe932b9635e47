#include "design_selection.hpp"

#include "railodd/geometry/fit_alignment.hpp"
#include "segmentation.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace railodd::geometry::fit {

namespace {

std::size_t free_parameters(const CurvatureModel& m) { return ParameterMap(m).size(); }

// Penalised likelihood of a fit with k free parameters over n points at
// noise sigma: -2 log L + k log n (BIC), the design with the least wins: a
// parameter must buy log n squared sigmas of residual. The likelihood is
// robust: a node counts at most `cap` squared sigmas (a normal scatter with
// a few gross errors), so that one node out of line can never buy the
// handful of parameters of a reverse-curve wiggle through it.
struct Criterion {
    static constexpr double cap = 25.0; // (5 sigma)^2: 3 sigma let real extracts' designs cut corners
    double sigma = 0.1;
    std::size_t n = 0;
    double per_parameter() const { return std::log(static_cast<double>(std::max<std::size_t>(n, 3))); }
    double score(double rss, std::size_t k) const {
        return rss / (sigma * sigma) + per_parameter() * static_cast<double>(k);
    }
    double score(const std::vector<double>& d, std::size_t k) const {
        double sum = 0.0;
        for (const double x : d) {
            sum += std::min(cap, x * x / (sigma * sigma));
        }
        return sum + per_parameter() * static_cast<double>(k);
    }
    // The residual sum a fit with k parameters must stay below to score under `bound`.
    double rss_below(double bound, std::size_t k) const {
        return (bound - per_parameter() * static_cast<double>(k)) * sigma * sigma;
    }
};

// Joints where one transition runs straight into another away from zero
// curvature: no railway is designed so (between two transitions there is an
// arc, or they meet at zero in a reverse curve). Each costs the criterion as
// much as two parameters: the prior of the design rules, which lets the data
// insist where such a joint is real (curvature read off a badly mapped
// stretch) but not a few noisy nodes.
std::size_t kinked_transitions(const Alignment& a) {
    constexpr double straight = 1.0 / 20000.0;
    std::size_t n = 0;
    for (std::size_t i = 1; i < a.primitives.size(); ++i) {
        const Primitive& u = a.primitives[i - 1];
        const Primitive& v = a.primitives[i];
        if (u.kind == PrimitiveKind::spiral && v.kind == PrimitiveKind::spiral && std::abs(v.curv_start) > straight) {
            ++n;
        }
    }
    return n;
}

// Candidate structures read off the curvature diagram at several noise
// scales and penalties, simplest first, without repeats.
std::vector<std::vector<Piece>> candidate_structures(const std::vector<double>& ks, const std::vector<double>& kk) {
    std::vector<std::vector<Piece>> out{template_structure(ks, kk)};
    const CurvatureDiagram diagram(ks, kk);
    for (double sigma : {2e-4, 1.4e-4, 1e-4, 7e-5, 5e-5, 3.5e-5, 2.5e-5, 1.7e-5}) {
        for (double penalty : {32.0, 8.0, 2.0}) {
            auto pieces = diagram.segment({sigma, penalty});
            const bool seen = std::any_of(out.begin(), out.end(), [&](const auto& o) {
                return o.size() == pieces.size() &&
                       std::equal(o.begin(), o.end(), pieces.begin(), [](const Piece& a, const Piece& b) {
                           return a.kind == b.kind && std::abs(a.length - b.length) < 1.0;
                       });
            });
            if (!seen && !pieces.empty()) {
                out.push_back(std::move(pieces));
            }
        }
    }
    std::stable_sort(out.begin(), out.end(), [](const auto& a, const auto& b) { return a.size() < b.size(); });
    return out;
}

} // namespace

// The design of least penalised-likelihood score among the candidates read
// off the fine spline's curvature diagram (ks, kk); nothing where none is
// near enough the nodes. The fine spline is no design. Candidates come
// simplest first, so the loop stops once even a perfect fit (the fine
// spline's residuals) could not beat the best.
std::optional<WindowFit> best_design(const std::vector<Point2>& p, const std::vector<double>& ks,
                                     const std::vector<double>& kk, const StructureEnds& se,
                                     SolveOptions so, const SolveReport& fine_report, double sigma) {
    const Criterion crit{sigma, p.size()};
    const double rss_f = fine_report.rms_m * fine_report.rms_m * static_cast<double>(p.size());
    // A design may leave a node half a metre (or three sigmas) further than
    // the spline does, no more: the capped likelihood would not see a corner
    // cut. Beyond 1.5 m only two sigmas: a chain straying 2 m from a node
    // goes to the corner construction (chain_fit.cpp), a dozen elements per
    // kilometre more.
    const double max_allowed =
        std::max(fine_report.max_m + 2.0 * sigma, std::min(fine_report.max_m + std::max(0.5, 3.0 * sigma), 1.5));
    std::vector<Point> window_points;
    for (const Point2& q : p) {
        window_points.push_back({q.x, q.y});
    }
    std::optional<WindowFit> best;
    double best_score = std::numeric_limits<double>::infinity();
    for (auto& pieces : candidate_structures(ks, kk)) {
        CurvatureModel m = build_structure(std::move(pieces), se);
        const std::size_t ps = free_parameters(m);
        if (best && crit.score(rss_f, ps) >= best_score) {
            break;
        }
        // The solve's residual sum is not capped: it may exceed the capped
        // one's bound by what a few far nodes add, hence the slack.
        so.give_up_rss = std::isfinite(best_score)
                             ? 2.0 * std::max(0.0, crit.rss_below(best_score, ps)) + rss_f
                             : std::max(4.0 * rss_f, rss_f + 16.0 * sigma * sigma * static_cast<double>(p.size()));
        const SolveReport r = solve(m, p, so);
        if (r.gave_up || !r.end_met || r.max_m > max_allowed || loops_back(m.to_alignment(), window_points)) {
            continue; // too few parameters to reach the tied end, too far off, or a loop
        }
        const double score = crit.score(r.distances_m, ps) +
                             2.0 * crit.per_parameter() * static_cast<double>(kinked_transitions(m.to_alignment()));
        if (score < best_score) {
            best_score = score;
            best = WindowFit{std::move(m), r, false};
        }
    }
    return best;
}

} // namespace railodd::geometry::fit
