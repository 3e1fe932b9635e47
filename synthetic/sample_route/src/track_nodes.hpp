#pragma once
// Draws the three tracks as OSM: the main line split into ways at every tag
// change, the passing loop and the spur hanging off their switch nodes.
#include "osm_builder.hpp"
#include "route_design.hpp"

#include <cstdint>
#include <vector>

namespace railodd::sample {

struct DrawnTracks {
    std::vector<std::int64_t> main_ways; // in chainage order
    std::vector<std::int64_t> stops;     // stop position and halt nodes, in chainage order
    std::int64_t level_crossing = 0;
};

DrawnTracks draw_tracks(const RouteDesign& design, OsmBuilder& builder, Rng& rng);

} // namespace railodd::sample
