#pragma once
// The roads in a corridor around the selected tracks: either picked from the
// roads read with the tracks, or read in three corridor passes when the file
// has too many roads to hold them all.
#include "node_locations.hpp"
#include "osm_passes.hpp"
#include "railodd/ingest/selection.hpp"
#include "segment_grid.hpp"

#include <filesystem>

namespace railodd::ingest {

struct RoadContext {
    const std::filesystem::path& file;
    double corridor_m;
    const SegmentGrid& tracks;
    BBox near; // lon/lat prefilter: the tracks' bounds grown by the corridor
};

void select_prefetched_roads(std::vector<RawWay> roads, const NodeLocations& locs, const RoadContext& ctx,
                             IngestResult& result);

void read_corridor_roads(const RoadContext& ctx, IngestResult& result);

} // namespace railodd::ingest
