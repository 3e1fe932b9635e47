#pragma once
// Everything a mapper draws around the tracks: platforms, roads (one crossing
// on the level, one under the viaduct, one along the station), the station
// node, and the train route relation tying ways and stops together.
#include "osm_builder.hpp"
#include "route_design.hpp"
#include "track_nodes.hpp"

namespace railodd::sample {

void draw_context(const RouteDesign& design, const DrawnTracks& tracks, OsmBuilder& builder, Rng& rng);

} // namespace railodd::sample
