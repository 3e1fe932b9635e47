#pragma once
// The checker's own reading of an OpenDRIVE document: only what the checks
// need, with the values as written (no repairs). Internal to xodr_check.
#include "railodd/xodr_check/check.hpp"
#include "railodd/xodr_check/geometry_eval.hpp"
#include "railodd/xodr_check/map_lines.hpp"

#include <cmath>
#include <limits>
#include <map>
#include <string>
#include <vector>

namespace railodd::xodr_check {

inline constexpr double nan = std::numeric_limits<double>::quiet_NaN();

struct Lane {
    int id = 0;
    std::string type;
    std::vector<Elevation> widths; // s: @sOffset
};

struct LaneSection {
    double s = 0.0;
    std::vector<Lane> lanes; // left, center and right
    bool has_lane(int id) const {
        for (const auto& l : lanes) {
            if (l.id == id) {
                return true;
            }
        }
        return false;
    }
};

struct Link {
    bool present = false;
    std::string element_type; // "road" or "junction"
    std::string element_id;
    std::string contact; // "start", "end" or empty
};

// A signal, object or reference placed at s on its road.
struct RoadPoint {
    std::string kind; // "signal", "object", "tunnel", ...
    std::string id;
    double s = 0.0;
    double length = 0.0; // tunnels and bridges
};

struct SwitchTrack {
    bool present = false;
    std::string id;
    double s = 0.0;
};

struct Switch {
    std::string id;
    SwitchTrack main;
    SwitchTrack side;
};

struct Road {
    std::string id;
    std::string junction = "-1";
    double length = 0.0;
    Link predecessor;
    Link successor;
    std::vector<GeometryRecord> geometries;
    std::vector<Elevation> elevations;
    std::vector<LaneSection> sections;
    std::vector<Elevation> lane_offsets;
    std::vector<RoadPoint> points;
    std::vector<Switch> switches;
    bool rail = false; // every non-centre lane is "rail" or "tram"
    std::string name;
    std::string osm_ids; // <userData code="osm">
    // Poses at both ends, filled once the plan view was read.
    bool has_geometry = false;
    Pose start;
    Pose end;
    const Pose& pose(bool at_end) const { return at_end ? end : start; }
    const LaneSection* section(bool at_end) const {
        if (sections.empty()) {
            return nullptr;
        }
        return at_end ? &sections.back() : &sections.front();
    }
};

struct LaneLink {
    int from = 0;
    int to = 0;
};

struct Connection {
    std::string id;
    std::string incoming;
    std::string connecting; // connectingRoad, or linkedRoad of a direct junction
    std::string contact;
    std::vector<LaneLink> lane_links;
};

struct RoadSection {
    std::string road_id;
    double s_start = nan;
    double s_end = nan;
};

struct Junction {
    std::string id;
    std::string type = "default";
    std::vector<Connection> connections;
    std::vector<RoadSection> road_sections; // crossing junctions (1.8)
};

struct Segment {
    std::string road_id;
    double s_start = 0.0;
    double s_end = 0.0;
};

struct Station {
    std::string id;
    std::vector<Segment> segments; // of all its platforms
};

struct Document {
    std::string file;
    int rev_major = 1;
    int rev_minor = 0;
    std::string geo_reference;
    std::vector<Road> roads;
    std::vector<Junction> junctions;
    std::vector<Station> stations;
    std::map<std::string, std::size_t> road_index;
    std::map<std::string, std::size_t> junction_index;
    std::vector<Finding> findings; // problems met while reading (bad numbers, unknown records)

    const Road* road(const std::string& id) const {
        const auto it = road_index.find(id);
        return it == road_index.end() ? nullptr : &roads[it->second];
    }
};

// Parses the document; throws railodd::InputError naming `name` when it is not
// well-formed XML or has no <OpenDRIVE> root.
Document read_document(const std::string& xml, const std::string& name);

} // namespace railodd::xodr_check
