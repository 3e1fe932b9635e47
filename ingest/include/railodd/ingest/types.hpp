#pragma once
// Plain data produced by the ingest stage: what later stages (geometry, tagging,
// OpenDRIVE) consume, with OSM ids kept on everything for traceability.
#include "railodd/ingest/projection.hpp"

#include <cstdint>
#include <limits>
#include <map>
#include <optional>
#include <string>
#include <vector>

namespace railodd::ingest {

// Sorted by key so every dump of them is deterministic.
using Tags = std::map<std::string, std::string>;

std::string tag_or(const Tags& tags, const std::string& key, const std::string& fallback = {});

struct NodeRef {
    std::int64_t id = 0; // OSM node id (synthetic, per distinct vertex, for OGR sources)
    LonLat lonlat;
    XY xy;               // local frame, metres
    double ele = std::numeric_limits<double>::quiet_NaN(); // OSM `ele` tag, NaN if absent
};

// Where a way came from: an OSM way or a feature of an OGR vector layer.
enum class Origin { osm, ogr };

// A track or road way. `parts` are the contiguous runs of its nodes present in
// the input: one part normally, several when a clipped extract lacks nodes.
struct Way {
    Origin origin = Origin::osm;
    std::int64_t id = 0;
    Tags tags;
    std::vector<std::vector<NodeRef>> parts;
    std::size_t node_count = 0;    // nodes the way references
    std::size_t missing_nodes = 0; // referenced nodes absent from the input

    bool clipped() const noexcept { return missing_nodes > 0; }
};

// A railway point feature (signal, switch, level crossing, ...), a platform or
// a station. Nodes have a position only; ways (platforms, station areas) also
// an outline, and their position is its centroid.
struct Feature {
    std::string osm_type; // "node" or "way"
    std::int64_t id = 0;
    std::string kind;     // level_crossing, switch, signal, station, halt, platform, ...
    Tags tags;
    NodeRef position;
    std::vector<NodeRef> outline;
    bool area = false;     // closed outline
    bool on_track = false; // a node of a selected track way
};

// A land-use area (landuse=*, natural=wood|water, waterway=riverbank, ...)
// that may hold a track, its outline projected and simplified to about a
// metre so that memory stays small whatever the mapped detail
// (docs/ingest.md "Land use").
struct LandUseArea {
    std::string osm_type; // "way" (a closed way) or "relation" (a multipolygon)
    std::int64_t id = 0;
    std::string kind;     // urban, suburban, rural, industrial, forest, agricultural or water
    std::string tag;      // what the kind was read from, e.g. "landuse=residential"
    std::vector<std::vector<XY>> rings; // closed (last point != first), inside by the even-odd rule
    double area_m2 = 0.0; // outer rings minus inner rings
};

// The rail route relation selected with --relation: its member ways in member
// order, nested routes expanded in place (a route_master: its first route only,
// as its routes run in both directions).
struct RouteRelation {
    std::int64_t id = 0;
    Tags tags;
    std::vector<std::int64_t> ways;
};

struct Dropped {
    std::string kind;     // "track", "road" or "feature"
    std::string osm_type; // "node", "way", "relation" or "ogr_feature"
    std::int64_t id = 0;
    std::string reason;
};

// A repair of the input made explicitly, e.g. a clipped way cut into parts.
struct Repair {
    std::string kind;
    std::string osm_type;
    std::int64_t id = 0;
    std::string action;
};

struct IngestCounts {
    std::size_t input_track_ways = 0;
    std::size_t input_road_ways = 0;
    std::size_t input_features = 0;
    std::size_t input_nodes = 0;        // node objects read from the file
    std::size_t input_track_nodes = 0;  // distinct nodes referenced by selected track ways
    std::size_t output_track_ways = 0;
    std::size_t output_road_ways = 0;
    std::size_t output_features = 0;
    std::size_t missing_track_nodes = 0;
    std::size_t duplicate_nodes = 0; // later copies of a node id at another location, ignored (repairs lists them)
    std::size_t input_land_use = 0;  // land-use ways and multipolygons read
    std::size_t output_land_use = 0; // of those, assembled and near the tracks
};

struct IngestResult {
    std::string source;   // input file
    std::string selection; // human-readable description of the selection
    std::string timestamp; // the data's date (an OSM header's replication timestamp), empty if unknown
    LocalProjection projection{LonLat{0.0, 0.0}};
    std::vector<Way> tracks;
    std::vector<Way> roads;
    std::vector<Feature> features;
    std::vector<LandUseArea> land_use; // by osm_type, then id
    std::optional<RouteRelation> relation;
    IngestCounts counts;
    std::vector<Dropped> dropped;
    std::vector<Repair> repairs;
    std::vector<std::pair<std::string, double>> timings; // seconds per phase
};

} // namespace railodd::ingest
