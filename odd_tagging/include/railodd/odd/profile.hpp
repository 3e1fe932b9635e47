#pragma once
// A route's ODD profile: every stretch and point of track tagged with the
// taxonomy element it belongs to, its attributes and the sources behind it.
// Written by `railodd convert` as odd_profile.json / .geojson / .csv and read
// back by `railodd profile` (docs/odd.md, "Profile").
//
// odd_profile.json (format_version 2; format 1, one object per element, is still read):
//   {"railodd": {"format": "odd_profile", "format_version": 2}, "taxonomy": {"name", "version", "file"},
//    "route": {"description", "length_m", "tracks", "along_route" (only when true)},
//    "track_ends": [[TRACK, FROM-NODE, TO-NODE, FROM-HEADING, TO-HEADING], ...] (whole networks),
//    "element_kinds": [[PATH, TAXONOMY-ID], ...] (in order of first use),
//    "element_columns": ["kind", "track", "road_id", "s_start", "s_end", "chainage_start",
//                        "chainage_end", "source", "osm_ids", "attributes", "flags"],
//    "elements": [[KIND, EDGE, "12", m, m, m|null, m|null, "osm"|"derived"|"dem"|"osm+derived",
//                  ["way:1", "node:2"], {NAME: number|string|bool, ...}, ["point", "reversed"]], ...],
//    "unparsed": [{"osm_ids", "tag", "value", "reason"}],
//    "summary": {...}}
// KIND indexes element_kinds; positions are metres to the millimetre; a null
// chainage equals the s beside it; "flags" (only where one is set) lists
// "point" and "reversed" (s falls as chainage grows).
// s is along the OpenDRIVE road `road_id`; chainage along the route (the track
// graph edge `track`'s fitted centreline when no route is chosen).
#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <iosfwd>
#include <deque>
#include <string>
#include <variant>
#include <vector>

#include <nlohmann/json.hpp>

namespace railodd::odd {

using AttributeValue = std::variant<double, std::string, bool>;

struct TaggedAttribute {
    std::string name;
    AttributeValue value;
};

// Where something lies on the converted route: on map.xodr's road and s, on
// the track (graph edge) and its chainage, and the OSM objects behind it. A
// tagged element, and a spec check's verdict on one, are places.
struct MapPlace {
    std::string road_id;
    double s_start = 0.0;
    double s_end = 0.0;
    std::size_t track = 0;
    double chainage_start = 0.0;
    double chainage_end = 0.0;
    bool point = false;
    std::vector<std::string> osm_ids;
};

// The place's keys, in this order: road_id, s_start, s_end, track,
// chainage_start, chainage_end, point, osm_ids.
void to_json(nlohmann::ordered_json& j, const MapPlace& place);

struct TaggedElement : MapPlace {
    std::string element;    // taxonomy path
    std::string element_id; // taxonomy id
    std::vector<TaggedAttribute> attributes;
    std::string source;
    std::vector<std::pair<double, double>> lonlat; // geometry for the GeoJSON: a point or the stretch sampled
    bool reversed = false; // s falls as chainage grows (a route running against the road); JSON key only when true

    const AttributeValue* find(const std::string& attribute) const;
};

struct Unparsed {
    std::vector<std::string> osm_ids;
    std::string tag;
    std::string value;
    std::string reason;
};

// Where a track (graph edge) of a whole-network profile starts and ends: the
// OSM node at each end and the heading (rad, in the map's projected frame) of
// travel towards growing chainage there. A scenario uses them to run on across
// a switch onto the track that continues this one.
struct TrackEnd {
    std::size_t track = 0;
    std::int64_t from_node = 0;
    std::int64_t to_node = 0;
    double from_heading = 0.0;
    double to_heading = 0.0;
};

struct OddProfile {
    std::string taxonomy_name;
    std::string taxonomy_version;
    std::string taxonomy_file;
    std::string route;     // description of the route / selection
    double length_m = 0.0; // of all tracks (or the route)
    std::size_t tracks = 0;
    // By track, then chainage, then element path. A deque: a network's
    // elements are its largest structure, and a vector's doubling would hold
    // them twice at once.
    std::deque<TaggedElement> elements;
    std::vector<Unparsed> unparsed;
    nlohmann::ordered_json summary;      // km per radius / gradient class, counts, speed profile
    bool along_route = false; // chainage runs along one route (--from/--to, --relation), not per track
    std::vector<TrackEnd> track_ends; // by track; empty along a route (and in profiles written before them)
};

// Receives a network's profile as it is made (tag_network, tagger.hpp): the head (every
// field but elements, unparsed and summary), the elements in profile order a
// batch at a time (the sink may take them), then the tail (the head with
// unparsed and summary; no elements).
class ProfileSink {
public:
    virtual ~ProfileSink() = default;
    virtual void begin(const OddProfile& head) = 0;
    virtual void add(std::deque<TaggedElement>& batch) = 0;
    virtual void end(const OddProfile& tail) = 0;
};

nlohmann::ordered_json to_json(const OddProfile& profile);
// The same document as text, one element per line, without building the tree.
std::string to_json_text(const OddProfile& profile);
void write_json(const OddProfile& profile, std::ostream& out);
OddProfile profile_from_json(const nlohmann::json& j); // throws std::invalid_argument naming the missing key
// The same keeping the file's key order (attribute order, summary classes);
// nlohmann::json sorts object keys.
OddProfile profile_from_json(const nlohmann::ordered_json& j);
OddProfile read_profile(const std::filesystem::path& file); // throws railodd::InputError naming the file

} // namespace railodd::odd
