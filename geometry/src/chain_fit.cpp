// Choosing how one chain is built; see chain_fit.hpp.
#include "chain_fit.hpp"

#include "tie_splice.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace railodd::geometry {

namespace {

// A railway fit straying further than this from a node (beyond what the
// node's noise explains, noise_reach) is not kept.
constexpr double fallback_deviation_m = 2.0;
// A fit with tied ends straying further than this is tried again with free
// ends and the tied stretches spliced on: the ties, not the mapping, are what
// bends it most often (a branch meeting its through track at an angle).
constexpr double retry_deviation_m = 0.5;
// What a railway fit's end may miss its tied pose by (the fit's own
// precision, well inside OpenDRIVE link tolerances of 1 mm / 1e-4 rad).
constexpr double max_gap_m = 1e-4;
constexpr double max_heading_rad = 1e-6;
constexpr double max_curvature = 1e-9;
// Length of a spliced stretch: room for a turnout's worth of heading change.
constexpr double splice_length_m = 40.0;
constexpr CornerFitOptions corner_options{1000.0, 0.25};

// The furthest a node's noise alone takes it from the true track among n
// nodes, at a family-wise 5 %: the two-sided normal quantile at 0.05 / n (13
// nodes: 2.9 sigma; 1,000: 4.1). Sigma is the smaller of the fit's own
// (residual) estimate and the nodes' scatter about their neighbours, which
// a design that cuts a corner does not inflate. A fixed 0.5 or 2 m turned
// most design-search fits at 1 m noise into corners (truth routes tied at
// both ends, dense 1.0 m: elements 194x the design at p95) and spliced tied
// ends that were within the noise (Cologne: 618 of 888 splices below 3
// sigma). The windowed fit estimates no scatter: no reach there.
double noise_reach(std::size_t n, const FitQuality& q) {
    const double sigma = std::min(q.noise_sigma_m, q.scatter_sigma_m);
    if (n == 0 || !(sigma > 0.0)) {
        return 0.0;
    }
    const double tail = 0.05 / static_cast<double>(n);
    double lo = 0.0, hi = 40.0;
    for (int i = 0; i < 60; ++i) {
        const double z = 0.5 * (lo + hi);
        (std::erfc(z / std::sqrt(2.0)) > tail ? lo : hi) = z;
    }
    return lo * sigma;
}

bool misses(const EndMiss& m) {
    return m.gap_m > max_gap_m || m.heading_rad > max_heading_rad || m.curvature > max_curvature;
}

// The fit with free ends, each tied end's stretch rebuilt by corners.
ChainFit spliced_fit(const std::vector<Point>& p, const std::optional<Pose>& start, const std::optional<Pose>& end,
                     const FitOptions& o, const std::vector<IndexedAlignment>& guides) {
    ChainFit f{fit_alignment(p, std::nullopt, std::nullopt, o, guides).alignment, ChainMethod::spliced, 0};
    if (start) {
        f.alignment = splice_start(f.alignment, p, *start, splice_length_m, corner_options);
        ++f.spliced_ends;
    }
    if (end) {
        f.alignment = splice_end(f.alignment, p, *end, splice_length_m, corner_options);
        ++f.spliced_ends;
    }
    return f;
}

} // namespace

ChainFit fit_chain_points(const std::vector<Point>& p, const std::optional<Pose>& start,
                          const std::optional<Pose>& end, const FitOptions& o, const std::vector<IndexedAlignment>& guides) {
    const FitResult r = fit_alignment(p, start, end, o, guides);
    double worst = loops_back(r.alignment, p) ? std::numeric_limits<double>::infinity() : r.quality.followed_max_m;
    ChainFit best{r.alignment, ChainMethod::railway, 0, r.quality.noise_sigma_m, r.quality.outliers};
    const double reach = noise_reach(p.size(), r.quality);
    if ((start || end) && worst > retry_deviation_m + reach) {
        ChainFit s = spliced_fit(p, start, end, o, guides);
        s.noise_sigma_m = best.noise_sigma_m;
        s.outliers = best.outliers;
        const double m = loops_back(s.alignment, p) ? std::numeric_limits<double>::infinity() : measure_fit(s.alignment, p).max_m;
        if (m < worst) {
            best = std::move(s);
            worst = m;
        }
    }
    if (worst > fallback_deviation_m + reach) {
        // No railway-grade sequence came within reach of every mapped node
        // (tram corners, kinks): lines with clothoid corners keep every node
        // close and the ties exact.
        return {corner_polyline(p, start, end, corner_options), ChainMethod::corners, 0, best.noise_sigma_m, 0};
    }
    // The fit holds its end pose as a constraint, but a window whose every
    // model failed to meet it (least-squares fallback) may still miss, and
    // so may the design search's start (its frame ties a start by a weight;
    // only its polish holds it exactly: Cologne, 4 of 3,465 branch starts
    // up to 1.2 m and 0.46 rad off, or at another curvature): then that
    // stretch is rebuilt from the fit's pose there to the tied pose.
    if (best.method == ChainMethod::railway) {
        if (start && misses(start_miss(best.alignment, *start))) {
            best.alignment = splice_start(best.alignment, p, *start, splice_length_m, corner_options);
            ++best.spliced_ends;
        }
        if (end && misses(end_miss(best.alignment, *end))) {
            best.alignment = splice_end(best.alignment, p, *end, splice_length_m, corner_options);
            ++best.spliced_ends;
        }
        best.method = best.spliced_ends > 0 ? ChainMethod::spliced : ChainMethod::railway;
    }
    return best;
}

} // namespace railodd::geometry
