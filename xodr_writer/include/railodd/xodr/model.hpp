#pragma once
// The OpenDRIVE map as plain data: what the builders (rail_roads, road_network,
// features) produce and the serializer writes. Ids are strings as in the
// standard; the builders hand them out deterministically. Geometry is in the
// local metric frame of the ingest stage.
#include "railodd/geometry/alignment.hpp"
#include "railodd/geometry/vertical_profile.hpp"

#include <array>
#include <cstdint>
#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace railodd::xodr {

// Minor revision of OpenDRIVE 1.x that is written.
enum class Revision { v1_6 = 6, v1_7 = 7, v1_8 = 8 };

Revision parse_revision(const std::string& text); // "1.6" | "1.7" | "1.8"; throws std::invalid_argument
const char* to_string(Revision revision);

// <userData code value/>: traceability (OSM ids) and railodd's own attributes.
struct UserData {
    std::string code;
    std::string value;
};

// A planView record. Lines, arcs and spirals carry their curvatures as in
// geometry::Primitive; param_poly3 (connecting roads of road junctions only)
// uses u(p) = a + b p + c p^2 + d p^3 with pRange="arcLength".
struct PlanGeometry {
    enum class Kind { line, arc, spiral, param_poly3 };
    Kind kind = Kind::line;
    double s = 0.0;
    double x = 0.0;
    double y = 0.0;
    double hdg = 0.0;
    double length = 0.0;
    double curv_start = 0.0;
    double curv_end = 0.0;
    std::array<double, 4> u{};
    std::array<double, 4> v{};
};

// <superelevation s a b c d> (radians, positive lifts the left side).
struct Superelevation {
    double s = 0.0;
    double a = 0.0;
    double b = 0.0;
    double c = 0.0;
    double d = 0.0;
};

struct LaneLinkIds {
    std::optional<int> predecessor;
    std::optional<int> successor;
};

struct Lane {
    int id = -1;                 // negative: right of the reference line, positive: left
    std::string type = "driving"; // driving, rail, tram, sidewalk, biking, ...
    double width = 3.5;          // constant over the section
    LaneLinkIds link;
    std::string road_mark;       // "solid", "broken" or empty for none
};

struct LaneSection {
    double s = 0.0;
    std::vector<Lane> left;  // ascending id (1, 2, ...)
    std::vector<Lane> right; // descending id (-1, -2, ...)
};

enum class ElementType { none, road, junction };
enum class Contact { start, end };

struct RoadLink {
    ElementType type = ElementType::none;
    std::string id;
    Contact contact = Contact::start; // for type road
};

struct Signal {
    std::string id;
    std::string name;
    double s = 0.0;
    double t = 0.0;
    double z_offset = 0.0;
    std::string orientation = "+"; // "+", "-" or "none"
    bool dynamic = false;
    std::string country;           // ISO 3166-1 alpha-2, e.g. "DE"; empty: none written
    std::string type;              // "-1" where no catalogue type applies
    std::string subtype = "-1";
    std::optional<double> value;
    std::string unit;              // with value: "km/h", ...
    double height = 0.0;
    double width = 0.0;
    std::vector<UserData> user_data;
};

// A road object: platform, barrier, building part, ...
struct Object {
    std::string id;
    std::string name;
    std::string type;    // OpenDRIVE e_objectType: barrier, pole, building, none, ...
    std::string subtype; // finer kind where the type has none ("platform", "buffer_stop"); empty: not written
    double s = 0.0;
    double t = 0.0;
    double z_offset = 0.0;
    double hdg = 0.0;     // relative to the reference line
    double length = 0.0;  // along hdg; 0: not given
    double width = 0.0;
    double height = 0.0;
    std::string orientation = "none";
    std::vector<UserData> user_data;
};

// <tunnel> / <bridge> on a road.
struct Structure {
    enum class Kind { tunnel, bridge };
    Kind kind = Kind::tunnel;
    std::string id;
    std::string name;
    double s = 0.0;
    double length = 0.0;
    std::string type; // tunnel: standard|underpass; bridge: concrete|steel|brick|wood
    std::vector<UserData> user_data;
};

struct TrackRef {
    std::string road_id;
    double s = 0.0;
    std::string dir = "+";
};

// <railroad><switch>: placed on the road that ends (or starts) at the switch
// point and leads into it from the stem (the toe of the points).
struct Switch {
    std::string id;
    std::string name;
    std::string position = "dynamic"; // dynamic | straight | turn
    TrackRef main_track;
    TrackRef side_track;
    std::vector<UserData> user_data;
};

struct Road {
    std::string id;
    std::string name;
    std::string junction = "-1"; // id of the junction a connecting road belongs to
    std::string rule;            // "RHT"/"LHT"; empty: not written
    std::string type = "town";   // <type s="0" type=...>: rural, town, ...
    RoadLink predecessor;
    RoadLink successor;
    std::vector<PlanGeometry> plan_view;
    std::vector<geometry::ElevationPoly> elevation;
    std::vector<Superelevation> superelevation;
    double lane_offset = 0.0;    // <laneOffset a=...> at s = 0
    std::vector<LaneSection> lane_sections;
    std::vector<Object> objects;
    std::vector<Structure> structures;
    std::vector<Signal> signals;
    std::vector<Switch> switches;
    std::vector<UserData> user_data;
    bool rail = false;           // a track: checked for curvature continuity

    double length() const;
};

struct LaneLink {
    int from = 0;
    int to = 0;
};

struct Connection {
    std::string id;
    std::string incoming_road;
    std::string connecting_road;
    Contact contact = Contact::start; // where the connecting road touches the incoming road
    std::vector<LaneLink> lane_links;
};

// For type "crossing" (OpenDRIVE 1.8 level crossings): the s-range of each
// road where crossing traffic can appear, and which road has priority.
struct RoadSection {
    std::string road_id;
    double s_start = 0.0;
    double s_end = 0.0;
};

struct CrossingPriority {
    std::string high;
    std::string low;
};

struct Junction {
    std::string id;
    std::string name;
    std::string type = "default"; // default | crossing (1.8)
    std::vector<Connection> connections;
    std::vector<RoadSection> road_sections; // type crossing
    std::vector<CrossingPriority> priorities;
    std::vector<UserData> user_data;
};

struct PlatformSegment {
    std::string road_id;
    double s_start = 0.0;
    double s_end = 0.0;
    std::string side = "right"; // left | right (of the road)
};

struct Platform {
    std::string id;
    std::string name;
    std::vector<PlatformSegment> segments;
};

struct Station {
    std::string id;
    std::string name;
    std::string type = "medium"; // small | medium | large
    std::vector<Platform> platforms;
    std::vector<UserData> user_data;
};

struct Header {
    std::string name;
    std::string date;        // ISO 8601; fixed by the caller for byte-identical output
    std::string geo_reference; // PROJ string of the local frame
    double north = 0.0, south = 0.0, east = 0.0, west = 0.0;
    std::string vendor = "railodd";
};

struct Map {
    Header header;
    std::vector<Road> roads;
    std::vector<Junction> junctions;
    std::vector<Station> stations;
};

} // namespace railodd::xodr
