#pragma once
// Land-use areas around the selected tracks (docs/ingest.md "Land use"):
// closed ways and multipolygon relations assembled into rings, projected and
// simplified. Either from the ways read with the tracks, or, when the file
// holds too many, from the ways with a node inside the tracks' bounds.
#include "osm_passes.hpp"
#include "osm_relations.hpp"
#include "way_parts.hpp"

#include "railodd/ingest/selection.hpp"

#include <filesystem>

namespace railodd::ingest {

struct LandUseContext {
    const std::filesystem::path& file;
    BBox near;   // the tracks' lon/lat bounds: areas not reaching into them hold no track
    BBox search; // read_land_use_near: ways with a node in here are read (near grown by a margin)
};

// Assembles the areas whose nodes `locate` knows and keeps those reaching
// into ctx.near; rings that do not close are dropped (report.json "dropped").
void build_land_use(std::vector<RawLandUseWay> ways, const std::vector<RawLandUseRelation>& relations,
                    const Locator& locate, const LandUseContext& ctx, IngestResult& result);

// Three passes for files with too many land-use ways to hold: nodes in
// ctx.search, land-use ways touching them, and the rest of those ways' nodes.
// An area with no node in ctx.search (a forest far larger than the margin
// around the tracks) is missed, and a multipolygon with a member wholly
// outside cannot close and is dropped.
void read_land_use_near(const LandUseContext& ctx, const RelationScan& relations, IngestResult& result);

} // namespace railodd::ingest
