#pragma once
// The engineering design of the fictional Sample Valley Railway: exact
// alignments of its three tracks, the gradient profile, and every chainage at
// which something is mapped (way splits, switches, signals, stops, ...).
#include "osm_model.hpp"
#include "vertical_profile.hpp"

#include "railodd/geometry/alignment.hpp"

#include <string>
#include <vector>

namespace railodd::sample {

struct TrackDesign {
    std::string name;
    geometry::Alignment alignment;
};

// One OSM way of the main line; consecutive spans share their boundary node.
struct WaySpan {
    double s_from;
    double s_to;
    Tags tags;
};

// A tagged node the mapper put on the main line at a known chainage.
struct TrackPoint {
    double s;
    std::string kind; // "switch", "signal", "level_crossing", "milestone", "stop", "halt"
    Tags tags;
};

struct Range {
    double s_from;
    double s_to;
};

// Something drawn beside the main line, parallel to it at a fixed offset.
struct ParallelFeature {
    std::string kind; // "platform", "road"
    Range range;
    double offset; // left positive, m
    Tags tags;
};

// A road crossing the main line: straight through the crossing point, bending
// gently away from it. Node positions are distances along the road.
struct CrossingRoad {
    double s;                  // main-line chainage of the crossing
    double angle;              // road direction minus track heading, rad
    std::vector<double> along; // node distances from the crossing, m (0: shared node)
    double bend;               // lateral drift per square metre of distance
    bool level;                // shares the main line's level crossing node
    Tags tags;
};

// A node beside the main line (the station's own node).
struct BesidePoint {
    double s;
    double offset;
    Tags tags;
};

struct RouteDesign {
    double origin_lon = 10.2;
    double origin_lat = 48.3;

    TrackDesign main;
    TrackDesign loop; // passing loop at Sampleton, left of the main line
    TrackDesign spur; // industrial spur, diverging to the right

    double switch_loop_west = 0.0; // main-line chainage of the loop switches
    double switch_loop_east = 0.0;
    double switch_spur = 0.0;
    double level_crossing = 0.0;
    double station = 0.0; // Sampleton, chainage of its stop position
    double halt = 0.0;    // Brookside
    Range tunnel;
    Range bridge;
    double road_under_bridge = 0.0; // where the tertiary road passes below
    double valley_angle = 0.0;      // brook valley (and its road) minus track heading, rad

    std::vector<WaySpan> main_ways;
    std::vector<TrackPoint> main_points;
    Tags loop_tags;
    Tags spur_tags;
    std::vector<ParallelFeature> parallels;
    std::vector<CrossingRoad> crossing_roads;
    BesidePoint station_node;

    // Placeholder until make_route_design() sets the real profile.
    VerticalProfile profile{{{0.0, 0.0}, {1.0, 0.0}}, 1.0};
};

// Built once from constants; throws std::logic_error if the constants
// contradict each other (a point off the track, unordered way spans).
RouteDesign make_route_design();

// The way-split tags shared by every main-line way.
Tags main_line_tags(int maxspeed);

} // namespace railodd::sample
