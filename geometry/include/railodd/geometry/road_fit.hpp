#pragma once
// Road centrelines: the mapped polyline with a clothoid corner at every vertex
// (corner_fit.hpp), so position, heading and curvature are continuous (G2)
// and every mapped node stays within a set distance. Roads bend at junction
// corners and are not designed with railway transitions, so the railway fit's
// structure search does not suit them.
#include "railodd/geometry/fit_alignment.hpp"
#include "railodd/geometry/track_fit.hpp"

namespace railodd::geometry {

struct RoadFitOptions {
    double max_radius_m = 300.0;    // corners no wider than this
    double max_deviation_m = 0.5;   // a corner passes at most this far inside its vertex
};

// One alignment per road edge (the edges already merge ways across splits);
// every chain is a corner chain.
FittedNetwork fit_road_graph(const TrackGraph& roads, const RoadFitOptions& options);

} // namespace railodd::geometry
