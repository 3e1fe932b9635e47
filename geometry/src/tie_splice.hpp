#pragma once
// Making a fitted chain meet a tied end pose exactly: the stretch of the fit
// next to that end is replaced by a few curves of design (design_splice.hpp)
// or, where none follows its nodes, the corner construction (corner_fit.hpp)
// where it turns as a track can, from the fit's own pose where the stretch
// begins to the tied pose. The rest of the fit is kept as it is, and the
// joint is G2 because the construction starts (or ends) with the fit's pose
// and curvature there.
#include "railodd/geometry/corner_fit.hpp"
#include "railodd/geometry/indexed_alignment.hpp"

#include <vector>

namespace railodd::geometry {

// Each node's distance along the mapped polyline through `points`.
std::vector<double> polyline_chainage(const std::vector<Point>& points);
// Node k's foot on the fit, searched near where the polyline puts it (its
// chainage t[k], scaled to the fit's length) so that a chain passing
// itself cannot hand it to the wrong pass.
Projection node_on(const IndexedAlignment& fit, const std::vector<Point>& points, const std::vector<double>& t,
                   std::size_t k);

// The furthest the piece passes from the polyline through `nodes` (its
// first and last point where the piece starts and ends), every 2 m.
double off_polyline(const Alignment& piece, std::vector<Point> nodes);

// The node at which splice_start (splice_end) cuts the fit, by the nodes'
// chainage t: the first (last) node at least tail_m from that end, never the
// end node itself; the last (first) node where the whole chain is the stretch.
// The cut lies at its foot or at a knot within a metre of it on the kept side.
std::size_t splice_start_node(const std::vector<double>& t, double tail_m);
std::size_t splice_end_node(const std::vector<double>& t, double tail_m);

// points: the chain's mapped nodes in order. The spliced stretch covers the
// nodes within tail_m of the end (at least the last segment). It is a few
// curves of railway design (design_splice.hpp) where one passes its nodes
// within design_tolerance_m, else corners within the options' deviation;
// where those turn tighter than a track can, the design closest to the
// nodes (closest_design_splice), however far, if one meets both poses.
// Where the stretch is the whole chain and its other end is free
// (end_free, start_free), the fit's pose there is only a first guess.
Alignment splice_start(const Alignment& fit, const std::vector<Point>& points, const Pose& start, double tail_m,
                       const CornerFitOptions& options, double design_tolerance_m, bool end_free = false);
Alignment splice_end(const Alignment& fit, const std::vector<Point>& points, const Pose& end, double tail_m,
                     const CornerFitOptions& options, double design_tolerance_m, bool start_free = false);

// How far the alignment's end misses a pose: position (m), heading (rad,
// modulo full turns) and curvature (1/m).
struct EndMiss {
    double gap_m = 0.0;
    double heading_rad = 0.0;
    double curvature = 0.0;
};
EndMiss start_miss(const Alignment& a, const Pose& start);
EndMiss end_miss(const Alignment& a, const Pose& end);

} // namespace railodd::geometry
