#pragma once
// The curvature diagram read from the mapped nodes themselves, by an l1 trend
// filter: curvature on a 4 m chainage grid, piecewise linear with few kinks
// (a design's curvature is: zero on straights, constant on arcs, linear on
// transitions) and a weak l1 pull to zero (straights are straight), fitted
// to the nodes' offsets from a reference line by iteratively reweighted
// banded least squares: linear in the window's length, no clothoid
// evaluated. The design structures are read off it by design_selection.
#include "frame_fit.hpp"
#include "least_squares.hpp"

#include <optional>
#include <vector>

namespace railodd::geometry::fit {

struct TrendEnds {
    std::optional<Pose> start;           // tied start pose (x, y, hdg, curvature)
    std::optional<double> end_curvature; // tied end curvature (always a switch: the chain's end)
    bool start_at_switch = false;        // the tied start is a switch, not the previous window's end
};

// The filtered line: its start pose, its curvature diagram (chainage s,
// curvature k, about every 12 m) and the nodes' offsets from it.
struct CurvatureEstimate {
    Pose start;
    std::vector<double> s, k;
    double rss_m2 = 0.0; // sum of squared offsets
    double max_m = 0.0;  // largest offset
    Frame frame;         // the filter's final reference and the nodes on it, for fit_in_frame
};

// Nothing where the window has too few nodes for the filter (fewer than
// five, or shorter than 40 m). sigma: the node noise (m).
std::optional<CurvatureEstimate> estimate_curvature(const std::vector<Point2>& p, const TrendEnds& ends,
                                                    double sigma);

} // namespace railodd::geometry::fit
