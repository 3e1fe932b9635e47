#pragma once
// Lanes of a corridor road from the OSM tags of its way (docs/xodr.md, "Road
// lanes"): lane counts per direction, lane width, lane type and the road type
// of the highway class; right-hand traffic.
#include "railodd/ingest/types.hpp"
#include "railodd/xodr/model.hpp"

#include <string>

namespace railodd::xodr::roads {

// The lanes of one way, counted relative to the way's own direction.
struct LaneLayout {
    std::string highway;          // the class the defaults came from ("" if none)
    int forward = 1;              // lanes driving with the way
    int backward = 1;             // lanes driving against it
    double lane_width = 3.0;      // m, every lane
    std::string lane_type = "driving"; // driving | sidewalk | biking
    std::string road_type = "town";    // OpenDRIVE <type>: motorway, rural, town, lowSpeed, pedestrian, bicycle
    bool edge_lines = false;      // solid marks on the outer edges (motorway ... tertiary)

    bool operator==(const LaneLayout&) const = default;
};

LaneLayout lane_layout(const ingest::Tags& tags);

// A lane section at s for a way running with (along = true) or against the
// road's reference line: lanes with the reference line are right lanes.
LaneSection lane_section(const LaneLayout& layout, bool along, double s);

// Sum of lane widths on the wider side of the reference line.
double half_width(const LaneSection& section);

// Driving lanes of a section side, innermost first (ids 1, 2, ... or -1, -2, ...).
std::vector<int> driving_lanes(const std::vector<Lane>& side);

// Leading decimal number of a tag value ("7", "7.5", "7,5", "7 m"); NaN if the
// value is absent, not a number or in other units.
double parse_metres(const std::string& text);

// A positive lane count ("2"); 0 if absent or not a plain count.
int parse_count(const std::string& text);

} // namespace railodd::xodr::roads
