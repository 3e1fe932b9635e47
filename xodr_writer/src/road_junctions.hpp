#pragma once
// Geometry of corridor road junctions: how far each leg is cut back from the
// junction node, and the connecting road's reference line from an incoming
// leg's end pose to an outgoing leg's start pose.
#include "railodd/geometry/alignment.hpp"
#include "railodd/xodr/model.hpp"

#include <vector>

namespace railodd::xodr::roads {

// One leg of a junction as seen from its node.
struct LegShape {
    double direction = 0.0;  // rad: from the node along the leg
    double half_width = 0.0; // m: carriageway width on the wider side of the reference line
    double length = 0.0;     // m: of the whole road-graph edge
};

// Distance each leg is cut back from the node: at least min_clearance_m and
// far enough that the leg's end cross-section lies outside every other leg's
// carriageway (legs at acute angles need more), at most a third of the leg.
std::vector<double> cut_back(const std::vector<LegShape>& legs, double min_clearance_m);

// The reference line from `from` to `to` (s = 0): a <line> if `to` lies
// straight ahead with the same heading, otherwise a cubic Hermite curve as
// <paramPoly3 pRange="arcLength"> whose p runs over [0, length] and whose
// length is the curve's arc length. Starts exactly at `from` with its heading
// and ends at `to` (to rounding) with its heading: G1 at both ends.
PlanGeometry connecting_geometry(const geometry::Pose& from, const geometry::Pose& to);

// Point and heading of a planView record at p in [0, length] (paramPoly3 and
// line only; used by tests and checks).
geometry::Pose evaluate_connecting(const PlanGeometry& g, double p);

} // namespace railodd::xodr::roads
