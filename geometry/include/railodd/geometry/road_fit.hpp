#pragma once
// Road centrelines: each polyline vertex rounded off by a circular fillet, so
// heading is continuous (G1) and every mapped node stays within a set
// distance. Roads bend at junction corners and are not built with transition
// curves, so the railway fit's G2 model does not suit them.
#include "railodd/geometry/fit_alignment.hpp"
#include "railodd/geometry/track_fit.hpp"

namespace railodd::geometry {

struct RoadFitOptions {
    double max_radius_m = 300.0;    // fillets no wider than this
    double max_deviation_m = 0.5;   // a fillet passes at most this far inside its vertex
};

Alignment fillet_polyline(const std::vector<Point>& points, const RoadFitOptions& options);

// One alignment per road edge (the edges already merge ways across splits).
FittedNetwork fit_road_graph(const TrackGraph& roads, const RoadFitOptions& options);

} // namespace railodd::geometry
