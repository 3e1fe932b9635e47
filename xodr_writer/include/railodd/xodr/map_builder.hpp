#pragma once
// Assembles the whole OpenDRIVE map from the geometry stage's results: the
// rail network, the corridor's roads, the railway features on them (signals,
// tunnels, bridges, stations with platforms, level crossings) and the header.
#include "railodd/geometry/fitted_map.hpp"
#include "railodd/xodr/rail_network.hpp"
#include "railodd/xodr/road_network.hpp"

#include <nlohmann/json.hpp>

#include <optional>
#include <string>

namespace railodd::xodr {

// What the map is built from: the ingest and the geometry stages' results.
struct MapInput {
    const ingest::IngestResult& ingest;
    const geometry::FittedMap& geometry;
};

struct MapOptions {
    Revision revision = Revision::v1_7;
    std::string name;
    std::string date; // header date; the caller fixes it (e.g. from the input file) for reproducible output
    RailOptions rail;
    RoadNetworkOptions roads;
};

// What was written where, for report.json and for the ODD tagger.
struct MapBuild {
    Map map;
    RailNetwork rail;
    std::vector<BuiltRoad> roads;
    std::size_t signals = 0;
    std::size_t structures = 0;
    std::size_t stations = 0;
    std::size_t platforms = 0;
    std::size_t level_crossings = 0;
    struct MissingRoadSide {
        std::int64_t road_way = 0;
        std::int64_t node = 0;
        std::string reason;
    };
    std::vector<MissingRoadSide> level_crossings_without_road; // track side written, road side not
    std::vector<std::pair<std::size_t, std::string>> features_not_written; // feature index, reason
};

MapBuild build_map(const MapInput& input, const MapOptions& options);

// The written road a road way crosses a track on, at the crossing point: the
// lanes a road user takes onto the crossing. Nothing where the point lies on
// no road of that way (cut back inside a road junction, or not written).
struct CrossingRoad {
    std::string road_id;
    double s = 0.0;           // the crossing point's s on the road
    double length = 0.0;      // the road's length
    int forward_lane = 0;     // driving lane travelling in +s (0: none)
    int backward_lane = 0;    // driving lane travelling in -s (0: none)
    int forward_walk = 0;     // sidewalk lane on the forward side (0: none)
    int backward_walk = 0;    // sidewalk lane on the backward side
};
std::optional<CrossingRoad> crossing_road(const MapBuild& build, std::int64_t way_id, const ingest::XY& point);

// report.json's "opendrive" section.
nlohmann::ordered_json map_report(const MapBuild& build, const MapInput& input);

} // namespace railodd::xodr
