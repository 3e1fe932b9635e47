#pragma once
// The corridor's roads as drivable OpenDRIVE roads: lanes from the OSM tags
// (see docs/xodr.md, "Road lanes"), roads meeting at a node joined by
// junctions with connecting roads so that a vehicle can drive through. A road
// crossing a track stays one road across it.
#include "railodd/geometry/track_fit.hpp"
#include "railodd/ingest/types.hpp"
#include "railodd/xodr/ids.hpp"
#include "railodd/xodr/model.hpp"

#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

namespace railodd::xodr {

// One written (non-connecting) road made from a road-graph edge, for placing
// things on it later (level-crossing signals and barriers).
struct BuiltRoad {
    std::string road_id;
    std::size_t edge = 0;          // road-graph edge it came from
    geometry::Alignment alignment; // its reference line, s = 0 at the road's start
    std::vector<std::int64_t> way_ids;
};

struct RoadNetworkOptions {
    double min_clearance_m = 4.0; // legs are cut back at least this far from a junction's node
};

// Appends the roads (and their junctions) of the fitted road graph to `map`,
// taking ids from `ids`. `ways` are the road ways the graph was built from.
std::vector<BuiltRoad> add_road_network(const geometry::TrackGraph& graph, const geometry::FittedNetwork& fitted,
                                        const std::vector<ingest::Way>& ways, const RoadNetworkOptions& options,
                                        IdCounter& ids, Map& map);

} // namespace railodd::xodr
