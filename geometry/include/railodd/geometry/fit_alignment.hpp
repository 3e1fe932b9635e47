#pragma once
// Fits a railway-grade centreline to a mapped polyline: a sequence of lines,
// clothoids and arcs with position, heading and curvature continuous (G2),
// optionally starting and ending at given poses (links to other tracks).
#include "railodd/geometry/alignment.hpp"
#include "railodd/geometry/indexed_alignment.hpp"

#include <cstddef>
#include <optional>
#include <vector>

namespace railodd::geometry {

struct Point {
    double x = 0.0;
    double y = 0.0;
};

// How a chain's design is read from its nodes. `design_search` (the
// default): one L0-penalised search per chain (docs/geometry.md, "Design
// search"); ahead of the windowed fit on 20 of the truth bench's 24 rows
// and on the extracts' structure figures (docs/BENCHMARKS.md). `windowed`:
// the trend filter, candidate structures and LM window by window; kept
// until the design search wins every row (issue 37).
enum class FitMethod { windowed, design_search };

struct FitOptions {
    // Scatter of the mapped nodes about the true centreline; 0: estimated per
    // chain from the nodes themselves (FitQuality::noise_sigma_m).
    double noise_sigma_m = 0.0;
    double knot_spacing_m = 12.0; // of the fine clothoid spline that estimates the curvature diagram
    double window_m = 2500.0;     // long tracks are fitted window by window, each starting where the last ended
    double curvature_sigma = 2e-5; // 1/m: noise scale of the estimated curvature diagram
    double kink_sigma = 5e-4;      // 1/m: allowed change of curvature slope between knots of the fine spline
    double ridge_sigma = 2e-3;     // 1/m: weak pull of the fine spline towards zero curvature
    unsigned threads = 0;          // chains fitted at once by fit_track_graph; 0: one per hardware thread
    bool parallel_guides = true;   // fit_track_graph offers a chain the design of the track it runs beside
    FitMethod method = FitMethod::design_search;
};

struct FitQuality {
    std::size_t points = 0;
    double rms_m = 0.0; // distance of the mapped nodes to the fitted line
    double p95_m = 0.0;
    double max_m = 0.0;
    // The furthest node the fit follows: strays it left out do not count
    // (the windowed fit counts every node).
    double followed_max_m = 0.0;
    std::vector<std::size_t> strays; // indices of those strays, ascending
    std::size_t windows = 0;
    std::size_t fallback_windows = 0; // windows kept as the fine clothoid spline (no design came near the nodes)
    std::size_t outliers = 0;         // mapped nodes left out of the fit as outliers
    double noise_sigma_m = 0.0;       // node scatter the fit assumed: estimated, or FitOptions' override
    // The nodes' scatter about their neighbours' line, which no misfit
    // inflates (the design search's; where under a dozen nodes tell it,
    // noise_sigma_m up to 3 m; 0 where not estimated): with noise_sigma_m,
    // how far noise alone takes a node (chain_fit.cpp).
    double scatter_sigma_m = 0.0;
};

struct FitResult {
    Alignment alignment;
    FitQuality quality;
};

// points: the mapped nodes in order (at least 2). start/end: poses (x, y, hdg,
// curvature) the alignment must begin / end with.
FitResult fit_alignment(const std::vector<Point>& points, const std::optional<Pose>& start,
                        const std::optional<Pose>& end, const FitOptions& options);
// The same with parallel tracks' fitted alignments as guides: where a
// window's nodes run beside one (2.5-6.5 m off), its design, offset to them,
// is a candidate (docs/geometry.md, "Parallel tracks"); the first that does
// is taken. `held`: indices of points the design search never leaves out
// as strays (a switch's node, where three or more track ends meet: the
// mapping's surest point, and the pose its branches are tied to).
FitResult fit_alignment(const std::vector<Point>& points, const std::optional<Pose>& start,
                        const std::optional<Pose>& end, const FitOptions& options,
                        const std::vector<IndexedAlignment>& guides, const std::vector<std::size_t>& held = {});

// Distance of every point to the alignment.
std::vector<double> distances(const Alignment& alignment, const std::vector<Point>& points);
// The same on an alignment already indexed (at 2 m: the same distances).
std::vector<double> distances(const IndexedAlignment& alignment, const std::vector<Point>& points);

// Distances of points to an alignment, summarised (used for residual reports).
FitQuality measure_fit(const Alignment& alignment, const std::vector<Point>& points);

// Does the alignment loop where the mapped polyline through `points` does
// not? More than 5 % + 10 m longer than the polyline, or a full turn more.
// Node distances cannot show it: a loop at the curvature bound keeps every
// node near some part of the curve.
bool loops_back(const Alignment& alignment, const std::vector<Point>& points);
// Whether the points close on themselves (first and last one point): a
// ring, whose first and last foot are the curve's two ends.
bool closes_on_itself(const std::vector<Point>& points);

} // namespace railodd::geometry
