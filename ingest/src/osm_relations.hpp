#pragma once
// The relations pass of the OSM reader: the rail route relation selected with
// --relation (its ways in member order) and the land-use multipolygons, whose
// member ways the ways pass then reads. Relations follow ways in OSM files, so
// this pass runs first, on relations only.
#include "railodd/ingest/types.hpp"

#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

namespace railodd::ingest {

struct RawLandUseRelation {
    std::int64_t id = 0;
    std::string kind;
    std::string tag;
    std::vector<std::pair<std::int64_t, bool>> ways; // member way, inner role
};

struct RelationScan {
    std::optional<RouteRelation> route;        // the requested rail route
    bool route_text_repaired = false;           // its tag text made valid (osm_scan.hpp tags_of)
    std::vector<std::int64_t> route_ways;       // every way of it and of the relations it holds, sorted
    std::vector<RawLandUseRelation> land_use;   // by id
    std::vector<std::int64_t> land_use_members; // their member ways, sorted, unique
};

// Throws InputError naming the file when `route` is given but absent or no
// rail route (type=route with route=train|railway|tracks|tram|subway|
// light_rail, or a route_master of those).
RelationScan scan_relations(const std::filesystem::path& file, std::optional<std::int64_t> route);

} // namespace railodd::ingest
