#include "design_selection.hpp"

#include "railodd/geometry/fit_alignment.hpp"
#include "curvature_trend.hpp"
#include "parallel_guide.hpp"
#include "segmentation.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

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
    // The design rules' prior on curves: each costs two parameters more
    // than its elements' (a railway is straight unless the terrain forced a
    // curve), so a handful of sparse nodes on a straight, scattered one way,
    // do not buy a shallow curve through them.
    static constexpr double per_curve = 2.0;
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

// Curves of an alignment: runs of elements between lines (a window that
// starts or ends inside a curve counts it too), and within a run each
// change of the curvature's sign: a reverse curve is two curves, and a
// wiggle of short spirals through zero pays for every turn.
std::size_t curves(const Alignment& a) {
    constexpr double straight = 1.0 / 20000.0;
    std::size_t n = 0;
    bool in_curve = false;
    int sign = 0;
    for (const Primitive& p : a.primitives) {
        const bool curved = p.kind != PrimitiveKind::line;
        n += curved && !in_curve ? 1 : 0;
        in_curve = curved;
        if (!curved) {
            sign = 0;
            continue;
        }
        for (const double k : {p.curv_start, p.curv_end}) {
            const int here = k > straight ? 1 : k < -straight ? -1 : 0;
            if (here != 0) {
                n += sign != 0 && here != sign ? 1 : 0;
                sign = here;
            }
        }
    }
    return n;
}

// Candidate structures read off the curvature diagram at several noise
// scales and penalties, simplest first, without repeats.
std::vector<std::vector<Piece>> candidate_structures(const std::vector<double>& ks, const std::vector<double>& kk) {
    std::vector<std::vector<Piece>> out{template_structure(ks, kk)};
    const CurvatureDiagram diagram(ks, kk);
    // A segmentation depends on penalty * sigma^2 only (its cost divided by
    // 1 / sigma^2 is the residual sum plus that per parameter): of the 24
    // pairs, those with a product already segmented are skipped.
    std::vector<double> done;
    for (double sigma : {2e-4, 1.4e-4, 1e-4, 7e-5, 5e-5, 3.5e-5, 2.5e-5, 1.7e-5}) {
        for (double penalty : {32.0, 8.0, 2.0}) {
            const double product = penalty * sigma * sigma;
            if (std::any_of(done.begin(), done.end(), [&](double d) { return std::abs(d - product) < 1e-6 * d; })) {
                continue;
            }
            done.push_back(product);
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

// Solves again, from where the fit stands, with every node beyond the
// criterion's cap (5 sigma) weighted down by (cap / distance)^2, while only a
// few nodes are so far: iteratively reweighted least squares for the capped
// likelihood, so that an outlier node no longer bends the design towards it.
// (Many far nodes mean the structure is wrong, not the nodes.)
SolveReport reweighted(CurvatureModel& m, const std::vector<Point2>& p, SolveOptions so, SolveReport r,
                       const Criterion& crit) {
    const double cap = std::sqrt(Criterion::cap) * crit.sigma;
    std::vector<std::size_t> previous;
    for (int round = 0; round < 3 && far_point_scale(r.distances_m, cap, previous, so.point_scale); ++round) {
        CurvatureModel trial = m;
        SolveReport t = solve(trial, p, so);
        if (t.gave_up || !t.end_met) {
            break;
        }
        m = std::move(trial);
        r = std::move(t);
    }
    return r;
}

// Is a candidate's fit near enough the nodes to be taken? Every node within
// max_allowed, but for a few isolated far nodes (far_nodes: outliers the
// window is then fitted again without).
bool near_enough(const std::vector<double>& d, double max_allowed, double sigma) {
    const std::vector<std::size_t> far = far_nodes(d, sigma);
    if (far.size() > 1 + d.size() / 100) {
        return false;
    }
    for (std::size_t i = 0, f = 0; i < d.size(); ++i) {
        if (f < far.size() && far[f] == i) {
            ++f;
        } else if (d[i] > max_allowed) {
            return false;
        }
    }
    return true;
}

} // namespace

std::vector<std::size_t> far_nodes(const std::vector<double>& d, double sigma) {
    const double limit = std::max(2.0, 5.0 * sigma);
    std::vector<std::size_t> out;
    for (std::size_t i = 2; i + 2 < d.size(); ++i) {
        const bool single = d[i] > limit && d[i] > 1.5 * d[i - 1] && d[i] > 1.5 * d[i + 1];
        // Two outliers side by side: neither is far beyond the other, both
        // beyond the nodes around the pair.
        const bool pair_first = i + 3 < d.size() && d[i] > limit && d[i + 1] > limit &&
                                std::min(d[i], d[i + 1]) > 1.5 * std::max(d[i - 1], d[i + 2]);
        if (single) {
            out.push_back(i);
        } else if (pair_first) {
            out.push_back(i);
            out.push_back(++i);
        }
    }
    return out;
}

namespace {

// What every candidate of a window is judged by.
struct Selection {
    const std::vector<Point2>& p;
    std::vector<Point> window_points;
    Criterion crit;
    double rss_floor = 0.0;  // the smooth line's residual sum: no design does better
    double max_allowed = 0.0; // no node may be further (but a few isolated far nodes)
    SolveOptions so;

    // The floor's fit: rms and largest distance of the smooth line the
    // diagram came from (a fine spline, or the trend filter).
    Selection(const std::vector<Point2>& points, double floor_rms, double floor_max, double sigma, SolveOptions o)
        : p(points), crit{sigma, points.size()}, so(std::move(o)) {
        rss_floor = floor_rms * floor_rms * static_cast<double>(p.size());
        // A design may leave a node half a metre (or three sigmas) further
        // than the smooth line does, no more: the capped likelihood would
        // not see a corner cut. Beyond 1.5 m only two sigmas: a chain
        // straying 2 m from a node goes to the corner construction
        // (chain_fit.cpp), a dozen elements per kilometre more.
        max_allowed = std::max(floor_max + 2.0 * sigma, std::min(floor_max + std::max(0.5, 3.0 * sigma), 1.5));
        for (const Point2& q : p) {
            window_points.push_back({q.x, q.y});
        }
    }

    double score(const std::vector<double>& d, const CurvatureModel& m) const {
        const Alignment a = m.to_alignment();
        return crit.score(d, free_parameters(m)) +
               2.0 * crit.per_parameter() * static_cast<double>(kinked_transitions(a)) +
               Criterion::per_curve * crit.per_parameter() * static_cast<double>(curves(a));
    }

    // The candidate fitted exactly from where it stands, with its score;
    // nothing where it cannot beat best_score, misses the tied end, is too
    // far from the nodes or loops.
    // `guided`: the design is a parallel track's (parallel_guide.hpp): its
    // lengths and curves were paid for there; only the start pose (where
    // free) and the track's offset are new parameters.
    std::optional<WindowFit> exact(CurvatureModel m, double best_score, double& score, bool guided = false) {
        const std::size_t ps = guided ? (m.start_free ? 3 : 0) + 1 : free_parameters(m);
        // The solve's residual sum is not capped: it may exceed the capped
        // one's bound by what a few far nodes add, hence the slack.
        so.give_up_rss =
            std::isfinite(best_score)
                ? 2.0 * std::max(0.0, crit.rss_below(best_score, ps)) + rss_floor
                : std::max(4.0 * rss_floor, rss_floor + 16.0 * crit.sigma * crit.sigma * static_cast<double>(p.size()));
        SolveReport r = solve(m, p, so);
        if (!r.gave_up && r.end_met) {
            r = reweighted(m, p, so, std::move(r), crit);
        }
        if (r.gave_up || !r.end_met || !near_enough(r.distances_m, max_allowed, crit.sigma) ||
            loops_back(m.to_alignment(), window_points)) {
            return std::nullopt;
        }
        score = guided ? crit.score(r.distances_m, ps) : this->score(r.distances_m, m);
        return WindowFit{std::move(m), std::move(r), false};
    }
};

// Every candidate solved exactly, simplest first; the loop stops once even
// the floor's residuals could not beat the best.
std::optional<WindowFit> best_exact(Selection& sel, std::vector<std::vector<Piece>> candidates,
                                    const StructureEnds& se, std::optional<WindowFit> best, double best_score) {
    for (auto& pieces : candidates) {
        CurvatureModel m = build_structure(std::move(pieces), se);
        if (best && sel.crit.score(sel.rss_floor, free_parameters(m)) >= best_score) {
            break;
        }
        double score = 0.0;
        if (auto f = sel.exact(std::move(m), best_score, score); f && score < best_score) {
            best_score = score;
            best = std::move(f);
        }
    }
    return best;
}

// Every candidate fitted in the trend filter's frame (frame_fit.hpp), a
// pass over the nodes per evaluation, and ranked by its score there; then
// solved exactly in that order, from the frame's fit, until one is taken
// and the next ranks more than two parameters' worth worse (at most three
// taken). Only where the frame's ranking is no guide (every candidate fails
// exactly) are all solved.
std::optional<WindowFit> best_screened(Selection& sel, std::vector<std::vector<Piece>> candidates,
                                       const StructureEnds& se, const Frame& frame, std::optional<WindowFit> best,
                                       double best_score) {
    struct Screened {
        CurvatureModel m;
        double score = 0.0;
        bool near = false;
    };
    std::vector<Screened> screened;
    auto fit = [&](Screened& c) {
        const FrameFit ff = fit_in_frame(c.m, frame, sel.so.end, sel.crit.sigma);
        c.score = ff.ok ? sel.score(ff.distances_m, c.m) : std::numeric_limits<double>::infinity();
        c.near = ff.ok && near_enough(ff.distances_m, sel.max_allowed, sel.crit.sigma);
    };
    auto order = [](const Screened& a, const Screened& b) { return a.near != b.near ? a.near : a.score < b.score; };
    for (auto& pieces : candidates) {
        Screened c{build_structure(std::move(pieces), se)};
        fit(c);
        if (std::isfinite(c.score)) {
            screened.push_back(std::move(c));
        }
    }
    std::stable_sort(screened.begin(), screened.end(), order);
    double taken_at = 0.0;
    int taken = 0;
    for (Screened& c : screened) {
        if (taken > 0 && (taken >= 3 || c.score > taken_at + 2.0 * sel.crit.per_parameter())) {
            break;
        }
        double score = 0.0;
        if (auto f = sel.exact(std::move(c.m), best_score, score)) {
            taken_at = taken++ == 0 ? c.score : taken_at;
            if (score < best_score) {
                best_score = score;
                best = std::move(f);
            }
        }
    }
    return best;
}

// Curvature variables made fixed knots at their current values.
void fix_curvatures(CurvatureModel& m) {
    for (std::size_t k = 0; k < m.knot_var.size(); ++k) {
        if (m.knot_var[k] >= 0) {
            m.knot_fixed[k] = m.curv[static_cast<std::size_t>(m.knot_var[k])];
            m.knot_var[k] = -1;
        }
    }
    m.curv.clear();
}

// The guided candidate (parallel_guide.hpp): the neighbour's design, from
// the window's tied start or the offset neighbour's pose (its heading
// turned by whole turns to the nodes' own). In the filter's frame its
// curvatures may move within a prior of 5e-6 1/m of the neighbour's (half a
// percent at R 1,000 m: room for the tied start's heading, not for a design
// of its own), and are then fixed for the exact solve of lengths and start.
// Without a frame they stay the neighbour's.
std::optional<CurvatureModel> guided_model(const GuidedStructure& g, const StructureEnds& se,
                                           const std::vector<Point2>& p, const Frame* frame, const SolveOptions& so,
                                           double sigma) {
    constexpr double guided_prior = 5e-6;
    StructureEnds ends = se;
    if (!se.start_fixed) {
        ends.start = g.start;
        const double dir = std::atan2(p[1].y - p[0].y, p[1].x - p[0].x);
        ends.start.hdg += 2 * std::numbers::pi * std::round((dir - g.start.hdg) / (2 * std::numbers::pi));
    }
    CurvatureModel m = build_structure(g.pieces, ends);
    if (frame && !fit_in_frame(m, *frame, so.end, sigma, guided_prior).ok) {
        return std::nullopt;
    }
    fix_curvatures(m);
    return m;
}

// The candidate design of least penalised-likelihood score, read off the
// curvature diagram (ks, kk) and fitted from the start pose se; nothing
// where none is near enough the nodes. `floor_rms`, `floor_max`: the fit of
// the smooth line the diagram came from, whose residuals bound what a design
// can reach. `frame`: the trend filter's, where the diagram is its.
// `guided`: a parallel track's design, tried first.
std::optional<WindowFit> best_candidate(const std::vector<Point2>& p, const std::vector<double>& ks,
                                        const std::vector<double>& kk, const StructureEnds& se, SolveOptions so,
                                        double floor_rms, double floor_max, double sigma, const Frame* frame,
                                        const GuidedStructure* guided) {
    Selection sel(p, floor_rms, floor_max, sigma, std::move(so));
    std::optional<WindowFit> best;
    double best_score = std::numeric_limits<double>::infinity();
    if (guided) {
        if (auto m = guided_model(*guided, se, p, frame, sel.so, sigma)) {
            double score = 0.0;
            best = sel.exact(std::move(*m), best_score, score, true);
            best_score = best ? score : best_score;
        }
    }
    if (frame) {
        if (auto screened = best_screened(sel, candidate_structures(ks, kk), se, *frame, best, best_score)) {
            return screened;
        }
    }
    return best_exact(sel, candidate_structures(ks, kk), se, std::move(best), best_score);
}

} // namespace

std::optional<WindowFit> best_design(const std::vector<Point2>& p, const std::vector<double>& ks,
                                     const std::vector<double>& kk, const StructureEnds& se,
                                     SolveOptions so, const SolveReport& fine_report, double sigma,
                                     const GuidedStructure* guided) {
    return best_candidate(p, ks, kk, se, std::move(so), fine_report.rms_m, fine_report.max_m, sigma, nullptr,
                          guided);
}

std::optional<WindowFit> trend_design(const std::vector<Point2>& p, const StructureEnds& se, bool start_at_switch,
                                      SolveOptions so, double sigma, const GuidedStructure* guided) {
    TrendEnds te;
    if (se.start_fixed) {
        te.start = se.start;
        te.start_at_switch = start_at_switch;
    }
    te.end_curvature = se.end_curvature;
    const std::optional<CurvatureEstimate> e = estimate_curvature(p, te, sigma);
    if (!e) {
        return std::nullopt;
    }
    StructureEnds from = se;
    if (!se.start_fixed) {
        from.start = e->start;
    }
    const double rms = std::sqrt(e->rss_m2 / static_cast<double>(p.size()));
    if (rms > 1.5 * sigma) {
        // The filter could not follow the nodes (a turnout drawn as a kink
        // beside a tied switch pose, short chains of a few nodes): its
        // diagram would be no guide, nor its residuals a bound.
        return std::nullopt;
    }
    return best_candidate(p, e->s, e->k, from, std::move(so), rms, e->max_m, sigma, &e->frame, guided);
}

} // namespace railodd::geometry::fit
