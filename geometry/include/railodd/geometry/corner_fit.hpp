#pragma once
// Polyline centrelines that are curvature-continuous (G2) by construction:
// the mapped polyline's straights joined at every vertex by a symmetric
// clothoid corner (spiral, arc, spiral) whose curvature starts and ends at
// zero. Used where the railway fit finds no G2 sequence near every node (tram
// corners, kinks in the mapping) and for roads.
#include "railodd/geometry/fit_alignment.hpp"

#include <optional>
#include <vector>

namespace railodd::geometry {

struct CornerFitOptions {
    double max_radius_m = 1000.0;  // corners no wider than this (arc radius)
    double max_deviation_m = 0.25; // a corner passes at most this far inside its mapped vertex
};

// points: the mapped nodes in order. start / end: poses (x, y, hdg, curvature)
// the alignment must begin / end with exactly (a branch tied to its switch).
// A tied end starts with a spiral from the given curvature to zero, then a
// straight along the resulting heading towards the next node; the corner
// where that straight meets the polyline is sized by room alone, as its
// vertex is no mapped node. A spike (the way doubling back on itself) is
// rounded by a hairpin through its tip. Every mapped vertex is passed within
// max_deviation_m; a tied end's node lies wherever the given pose puts it.
Alignment corner_polyline(const std::vector<Point>& points, const std::optional<Pose>& start,
                          const std::optional<Pose>& end, const CornerFitOptions& options);

} // namespace railodd::geometry
