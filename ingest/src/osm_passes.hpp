#pragma once
// The individual streaming passes of the OSM reader. Each reads one kind of
// object and keeps only what the selection needs.
#include "node_locations.hpp"
#include "railodd/ingest/selection.hpp"
#include "railodd/ingest/types.hpp"

#include <cstdint>
#include <filesystem>
#include <functional>
#include <string>
#include <vector>

namespace railodd::ingest {

// What the report says of an object whose tag text was made valid
// (osm_scan.hpp tags_of).
inline constexpr const char* text_repair_action =
    "tag text with bytes that are not UTF-8 XML text (invalid sequences, control characters) kept with U+FFFD "
    "in their place";

struct RawWay {
    std::int64_t id = 0;
    Tags tags;
    std::vector<std::int64_t> refs;
    bool text_repaired = false; // tag text made valid (osm_scan.hpp tags_of)
};

// Whether node references close on themselves (first = last, a ring of three or more).
inline bool is_closed(const std::vector<std::int64_t>& refs) { return refs.size() >= 4 && refs.front() == refs.back(); }

struct RawFeature {
    std::string osm_type;
    std::int64_t id = 0;
    std::string kind;
    Tags tags;
    LonLat lonlat;                   // nodes
    std::vector<std::int64_t> refs;  // ways
    bool text_repaired = false;      // tag text made valid (osm_scan.hpp tags_of)
};

// A closed way tagged with a land-use kind, or a member way of a land-use
// multipolygon (kind empty); tags are not kept, only the kind.
struct RawLandUseWay {
    RawWay way;
    std::string kind;
    std::string tag;
};

// Which land-use ways a ways pass keeps: closed tagged ways and the members of
// land-use multipolygons (sorted), up to `refs_cap` node references in all.
struct LandUseWanted {
    const std::vector<std::int64_t>& members;
    std::size_t refs_cap = 0;
};

struct WayScan {
    std::vector<RawWay> tracks;
    std::vector<RawFeature> area_features; // platforms and station areas
    std::vector<RawWay> roads;             // every road way of the file, if roads_complete
    bool roads_complete = false;
    std::vector<RawLandUseWay> land_use;   // every land-use way of the file, if land_use_complete
    bool land_use_complete = false;
};

// Track ways (only `members` if non-null) and platform / station ways. Road
// ways are kept too while all of them together reference at most
// `road_refs_cap` nodes, which saves three passes on all but very large files;
// land-use ways likewise within `land_use.refs_cap`.
// With `near` (sorted node ids), track and platform / station ways only where
// they reference one of those nodes.
WayScan scan_track_ways(const std::filesystem::path& file, const std::vector<std::int64_t>* members,
                        std::size_t road_refs_cap, const LandUseWanted& land_use,
                        const std::vector<std::int64_t>* near = nullptr);

// Sorted ids of the nodes located in `box`.
std::vector<std::int64_t> node_ids_in(const std::filesystem::path& file, const BBox& box);

// Land-use ways with at least one node located in `near`.
std::vector<RawLandUseWay> scan_land_use_ways(const std::filesystem::path& file,
                                              const std::vector<std::int64_t>& members, const NodeLocations& near);

struct NodeScan {
    std::size_t node_count = 0;
    std::vector<RawFeature> point_features;
    struct Duplicate {
        std::int64_t id = 0;
        LonLat ignored; // the later location of a wanted node id met twice
    };
    std::vector<Duplicate> duplicates;
};

// Locates every wanted node and collects railway point feature nodes (only
// those in `feature_box`, if given).
NodeScan scan_nodes(const std::filesystem::path& file, NodeLocations& wanted, const BBox* feature_box = nullptr);

// Locates the wanted nodes only.
void locate_nodes(const std::filesystem::path& file, NodeLocations& wanted, const std::string& pass);

// Every node for which `keep` holds, located.
NodeLocations collect_nodes(const std::filesystem::path& file, const std::function<bool(LonLat)>& keep);

// Road ways with at least one node in `corridor`.
std::vector<RawWay> scan_road_ways(const std::filesystem::path& file, const NodeLocations& corridor);

} // namespace railodd::ingest
