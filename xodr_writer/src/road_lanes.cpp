// Lane layouts from OSM highway tags. The defaults are tabled in docs/xodr.md
// ("Road lanes"); keep the two in step.
#include "road_lanes.hpp"

#include <algorithm>
#include <array>
#include <cctype>
#include <cmath>
#include <cstdlib>
#include <limits>
#include <string_view>

namespace railodd::xodr::roads {

namespace {

struct ClassDefaults {
    std::string_view highway;
    int two_way_lanes;  // total lanes of a two-way road; 1 = one shared lane (written as 1 + 1)
    int oneway_lanes;
    double lane_width;  // m; for non-motor ways the whole path width
    std::string_view road_type;
    std::string_view lane_type;
    bool implied_oneway;
    bool edge_lines;
};

// clang-format off
constexpr std::array<ClassDefaults, 25> classes{{
    {"motorway",       4, 2, 3.75, "motorway",   "driving",  true,  true},
    {"motorway_link",  2, 1, 3.5,  "motorway",   "driving",  true,  true},
    {"trunk",          2, 2, 3.5,  "rural",      "driving",  false, true},
    {"trunk_link",     2, 1, 3.5,  "rural",      "driving",  false, true},
    {"primary",        2, 1, 3.5,  "rural",      "driving",  false, true},
    {"primary_link",   2, 1, 3.5,  "rural",      "driving",  false, true},
    {"secondary",      2, 1, 3.25, "rural",      "driving",  false, true},
    {"secondary_link", 2, 1, 3.25, "rural",      "driving",  false, true},
    {"tertiary",       2, 1, 3.0,  "rural",      "driving",  false, true},
    {"tertiary_link",  2, 1, 3.0,  "rural",      "driving",  false, true},
    {"unclassified",   2, 1, 2.75, "rural",      "driving",  false, false},
    {"residential",    2, 1, 2.75, "town",       "driving",  false, false},
    {"living_street",  2, 1, 2.5,  "lowSpeed",   "driving",  false, false},
    {"service",        1, 1, 2.5,  "town",       "driving",  false, false},
    {"track",          1, 1, 2.0,  "rural",      "driving",  false, false},
    {"road",           2, 1, 3.0,  "town",       "driving",  false, false},
    {"busway",         2, 1, 3.25, "town",       "driving",  false, false},
    {"bus_guideway",   2, 1, 3.25, "town",       "driving",  false, false},
    // Non-motor ways: the width is the whole path's, split over two lanes.
    {"pedestrian",     1, 1, 3.0,  "pedestrian", "sidewalk", false, false},
    {"footway",        1, 1, 2.0,  "pedestrian", "sidewalk", false, false},
    {"steps",          1, 1, 2.0,  "pedestrian", "sidewalk", false, false},
    {"corridor",       1, 1, 2.0,  "pedestrian", "sidewalk", false, false},
    {"path",           1, 1, 1.5,  "pedestrian", "sidewalk", false, false},
    {"bridleway",      1, 1, 2.0,  "pedestrian", "sidewalk", false, false},
    {"cycleway",       1, 1, 2.0,  "bicycle",    "biking",   false, false},
}};
// clang-format on

constexpr ClassDefaults fallback{"", 2, 1, 3.0, "town", "driving", false, false};

const ClassDefaults& defaults_of(const std::string& highway) {
    for (const auto& c : classes) {
        if (c.highway == highway) {
            return c;
        }
    }
    return fallback;
}

enum class Oneway { no, forward, backward };

Oneway oneway_of(const ingest::Tags& tags, const ClassDefaults& c) {
    const std::string v = ingest::tag_or(tags, "oneway");
    if (v == "yes" || v == "true" || v == "1") {
        return Oneway::forward;
    }
    if (v == "-1" || v == "reverse") {
        return Oneway::backward;
    }
    if (!v.empty()) {
        return Oneway::no; // no, false, 0, reversible, alternating, anything else
    }
    const std::string junction = ingest::tag_or(tags, "junction");
    return c.implied_oneway || junction == "roundabout" || junction == "circular" ? Oneway::forward : Oneway::no;
}

// Rural classes inside built-up areas: a numeric maxspeed up to 60 km/h or an
// urban speed zone.
bool urban(const ingest::Tags& tags) {
    for (const char* key : {"maxspeed", "source:maxspeed", "zone:maxspeed", "maxspeed:type"}) {
        const std::string v = ingest::tag_or(tags, key);
        if (v.find("urban") != std::string::npos) {
            return true;
        }
    }
    const std::string v = ingest::tag_or(tags, "maxspeed");
    const int kmh = parse_count(v);
    return kmh > 0 && kmh <= 60;
}

} // namespace

double parse_metres(const std::string& text) {
    constexpr double nan = std::numeric_limits<double>::quiet_NaN();
    std::size_t i = 0;
    std::string number;
    while (i < text.size() && (std::isdigit(static_cast<unsigned char>(text[i])) || text[i] == '.' || text[i] == ',')) {
        number += text[i] == ',' ? '.' : text[i];
        ++i;
    }
    while (i < text.size() && text[i] == ' ') {
        ++i;
    }
    const std::string_view unit = std::string_view{text}.substr(i);
    if (number.empty() || !(unit.empty() || unit == "m")) {
        return nan;
    }
    char* end = nullptr;
    const double value = std::strtod(number.c_str(), &end);
    return end == number.c_str() + number.size() && value > 0.0 && std::isfinite(value) ? value : nan;
}

int parse_count(const std::string& text) {
    if (text.empty() || text.size() > 3 ||
        !std::all_of(text.begin(), text.end(), [](char c) { return std::isdigit(static_cast<unsigned char>(c)); })) {
        return 0;
    }
    return std::atoi(text.c_str());
}

LaneLayout lane_layout(const ingest::Tags& tags) {
    const std::string highway = ingest::tag_or(tags, "highway");
    const ClassDefaults& c = defaults_of(highway);
    LaneLayout out;
    out.highway = highway;
    out.lane_type = std::string{c.lane_type};
    out.road_type = std::string{c.road_type};
    out.edge_lines = c.edge_lines;
    if (out.road_type == "rural" && urban(tags)) {
        out.road_type = "town";
    }
    const Oneway oneway = oneway_of(tags, c);
    double width = parse_metres(ingest::tag_or(tags, "width"));
    if (!(width <= 60.0)) {
        width = std::numeric_limits<double>::quiet_NaN(); // absent or implausible
    }

    if (out.lane_type != "driving") {
        // A path: one lane per side sharing the width, or one lane for a
        // one-way cycleway; lane tags do not apply.
        const double total = std::isnan(width) ? c.lane_width : width;
        const bool one = out.lane_type == "biking" && oneway != Oneway::no;
        out.forward = one && oneway == Oneway::backward ? 0 : 1;
        out.backward = one && oneway == Oneway::forward ? 0 : 1;
        out.lane_width = one ? total : total / 2.0;
        return out;
    }

    const int lanes = parse_count(ingest::tag_or(tags, "lanes"));
    const int fwd = parse_count(ingest::tag_or(tags, "lanes:forward"));
    const int bwd = parse_count(ingest::tag_or(tags, "lanes:backward"));
    const int both = parse_count(ingest::tag_or(tags, "lanes:both_ways")); // centre turn lanes: not modelled
    int drawn_total = 0; // lanes the width tag is spread over
    if (oneway != Oneway::no) {
        const int given = oneway == Oneway::forward ? fwd : bwd;
        const int n = given > 0 ? given : (lanes > 0 ? lanes : c.oneway_lanes);
        out.forward = oneway == Oneway::forward ? n : 0;
        out.backward = oneway == Oneway::backward ? n : 0;
        drawn_total = n;
    } else {
        const int through = lanes > both ? lanes - both : lanes;
        if (fwd > 0 && bwd > 0) {
            out.forward = fwd;
            out.backward = bwd;
        } else if (fwd > 0 || bwd > 0) {
            const int given = std::max(fwd, bwd);
            const int other = through > given ? through - given : 1;
            out.forward = fwd > 0 ? fwd : other;
            out.backward = bwd > 0 ? bwd : other;
        } else {
            const int n = through > 0 ? through : c.two_way_lanes;
            // One lane for both directions: one narrow lane each way.
            out.forward = n == 1 ? 1 : (n + 1) / 2;
            out.backward = n == 1 ? 1 : n / 2;
        }
        drawn_total = out.forward + out.backward + (lanes > 0 ? std::min(both, lanes) : 0);
        if (lanes == 1 && fwd == 0 && bwd == 0) {
            drawn_total = 2;
        }
    }
    out.lane_width = std::isnan(width) ? c.lane_width : width / drawn_total;
    return out;
}

LaneSection lane_section(const LaneLayout& layout, bool along, double s) {
    LaneSection section;
    section.s = s;
    const int right = along ? layout.forward : layout.backward;
    const int left = along ? layout.backward : layout.forward;
    const auto side = [&](int count, int sign, std::vector<Lane>& lanes) {
        for (int k = 1; k <= count; ++k) {
            Lane lane;
            lane.id = sign * k;
            lane.type = layout.lane_type;
            lane.width = layout.lane_width;
            // A mark sits on a lane's outer border: broken between lanes of one
            // direction, solid on the carriageway edge of the main classes.
            lane.road_mark = k < count ? "broken" : (layout.edge_lines ? "solid" : "");
            lanes.push_back(lane);
        }
    };
    side(left, 1, section.left);
    side(right, -1, section.right);
    return section;
}

double half_width(const LaneSection& section) {
    double left = 0.0;
    double right = 0.0;
    for (const auto& l : section.left) {
        left += l.width;
    }
    for (const auto& l : section.right) {
        right += l.width;
    }
    return std::max(left, right);
}

std::vector<int> driving_lanes(const std::vector<Lane>& side) {
    std::vector<int> ids;
    for (const auto& l : side) {
        if (l.type == "driving") {
            ids.push_back(l.id);
        }
    }
    std::sort(ids.begin(), ids.end(), [](int a, int b) { return std::abs(a) < std::abs(b); });
    return ids;
}

} // namespace railodd::xodr::roads
