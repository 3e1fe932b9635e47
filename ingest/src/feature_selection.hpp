#pragma once
// Keeps the railway point features, platforms and stations that lie on or near
// the selected tracks; those in the selection but far from every track are
// listed as dropped with their distance limit.
#include "node_locations.hpp"
#include "osm_passes.hpp"
#include "railodd/ingest/osm_reader.hpp"
#include "segment_grid.hpp"

namespace railodd::ingest {

struct FeatureContext {
    const Selection& selection;
    const IngestOptions& options;
    const SegmentGrid& grid;
    const LocalProjection& projection;
    std::vector<std::int64_t> track_nodes; // sorted ids of selected track nodes
};

void select_features(std::vector<RawFeature> points, std::vector<RawFeature> areas, const NodeLocations& locs,
                     const FeatureContext& ctx, IngestResult& result);

} // namespace railodd::ingest
