#pragma once
// A candidate design fitted in the trend filter's frame: the nodes' offsets
// from the filter's reference line, against the design's offset from it
// (the double integral of the difference of their curvatures, exact for a
// piecewise-linear curvature: no clothoid is evaluated). The offsets are a
// few sigmas, so the linearisation errs by about offset^2 * curvature, far
// below the noise. Each evaluation costs one pass over the nodes; the exact
// solve (least_squares.hpp) then only polishes the design chosen here.
#include "curvature_model.hpp"
#include "least_squares.hpp"

#include <optional>
#include <vector>

namespace railodd::geometry::fit {

// The filter's reference line (grid points and headings, spacing h) and
// each node's place on it (chainage s, signed offset e, left positive).
struct Frame {
    double h = 4.0;
    std::vector<double> x, y, hdg;
    std::vector<double> s, e;
};

struct FrameFit {
    std::vector<double> distances_m; // |offset of each node from the design|
    bool ok = false; // converged to finite distances, within the small-angle model
};

// Fits m (its free lengths, curvatures and, where free, start pose) to the
// nodes in frame f, robustly (nodes beyond 5 sigma weighted down while few),
// meeting the window's end pose where one is given, else ending at the last
// node. prior_sigma (1/m): how far a curvature variable may stray from its
// first value where the nodes hardly tell it (weak: 1e-3); a parallel
// track's design holds it tighter.
FrameFit fit_in_frame(CurvatureModel& m, const Frame& f, const std::optional<Pose>& end, double sigma,
                      double prior_sigma = 1e-3);

} // namespace railodd::geometry::fit
