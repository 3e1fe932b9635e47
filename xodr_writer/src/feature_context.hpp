#pragma once
// Shared state of the builders that place railway features on written roads.
#include "railodd/xodr/map_builder.hpp"

#include <optional>

namespace railodd::xodr {

struct FeatureContext {
    const MapInput& in;
    MapBuild& build;
    IdCounter& ids;
    Revision revision;

    // The road and s of a point at alignment s of a graph edge, if the edge was written.
    std::optional<RoadLocation> on_track(std::size_t edge, double s) const {
        if (edge >= build.rail.pieces.size() || build.rail.pieces[edge].empty()) {
            return std::nullopt;
        }
        return build.rail.locate(edge, s);
    }
};

void add_structures(FeatureContext& ctx);      // tunnels and bridges (structures.cpp)
void add_track_features(FeatureContext& ctx);  // signals, buffer stops (track_features.cpp)
void add_stations(FeatureContext& ctx);        // stations with platforms (stations.cpp)
void add_level_crossings(FeatureContext& ctx); // signals, barriers, 1.8 crossing junctions (level_crossings.cpp)

} // namespace railodd::xodr
