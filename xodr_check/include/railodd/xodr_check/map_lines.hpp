#pragma once
// The roads of an OpenDRIVE file as drawable lines: each road's plan-view
// records, elevation polynomials, its OSM ids and whether it is a rail road,
// with the file's geoReference. Read by the same reader as the checks (values
// as written, no repairs), for tools that draw or measure a map: the HTML
// report samples these in closed form (evaluate()) and projects them with the
// geoReference.
#include "railodd/xodr_check/geometry_eval.hpp"

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

namespace railodd::xodr_check {

// z(s) = a + b t + c t^2 + d t^3, t = s - s_start (one <elevation> record).
struct Elevation {
    double s = 0, a = 0, b = 0, c = 0, d = 0;
    double at(double s_road) const {
        const double t = s_road - s;
        return a + t * (b + t * (c + t * d));
    }
};

// One lane's widths: w(ds) = a + b t + c t^2 + d t^3, t = ds - s, ds from
// its lane section's start (Elevation's form, s being @sOffset).
struct MapLane {
    int id = 0;
    std::vector<Elevation> widths;
};

struct MapSection {
    double s = 0.0;
    std::vector<MapLane> lanes;
};

struct MapRoad {
    std::string id;
    std::string name;
    std::string junction = "-1";
    std::string predecessor, successor; // linked roads' ids; empty where a junction or nothing is linked
    double length = 0.0;
    bool rail = false;   // every non-centre lane is "rail" or "tram"
    std::string osm_ids; // <userData code="osm"> value, e.g. "way:1,way:2"
    std::vector<GeometryRecord> geometries;
    std::vector<Elevation> elevations;
    std::vector<Elevation> lane_offsets; // <laneOffset> records
    std::vector<MapSection> sections;

    // The reference line's pose at s (clamped to [0, length]).
    Pose pose(double s) const;
    // Where OpenSCENARIO's LanePosition (road, lane, s, offset from the
    // lane's centre, left +) is on the map: x, y and the road's heading;
    // nullopt where the lane is not in the section at s.
    std::optional<Pose> lane_position(int lane_id, double s, double offset) const;
    // The elevation at s; 0 without an elevation profile.
    double elevation(double s) const;
};

struct MapLines {
    std::string file;
    std::string geo_reference; // PROJ string of the local frame, empty when absent
    std::vector<MapRoad> roads; // in document order
};

// Throws railodd::InputError naming the file when it cannot be read, is not
// XML or not an OpenDRIVE document.
MapLines read_map_lines(const std::filesystem::path& file);

} // namespace railodd::xodr_check
