// Design constants of the Sample Valley Railway. Chainage s runs west to east
// from km 0.0; "left" is left when facing increasing s.
#include "route_design.hpp"

#include <cmath>
#include <numbers>
#include <stdexcept>
#include <string>

namespace railodd::sample {

namespace {

using geometry::make_arc;
using geometry::make_line;
using geometry::make_spiral;

constexpr double turnout_radius = 300.0; // EW 60-300 turnouts at the loop
constexpr double loop_offset = 4.5;      // track centre distance in the station
constexpr double loop_straight = 400.0;

// Straight -> clothoid -> arc -> clothoid -> straight; negative radius turns right.
void append_curve(std::vector<geometry::Primitive>& p, double transition, double arc,
                  double signed_radius) {
    const double k = 1.0 / signed_radius;
    p.push_back(make_spiral(transition, 0.0, k));
    p.push_back(make_arc(arc, k));
    p.push_back(make_spiral(transition, k, 0.0));
}

geometry::Alignment main_alignment() {
    geometry::Alignment a;
    a.start = {-4300.0, -300.0, 0.25, 0.0};
    auto& p = a.primitives;
    p.push_back(make_line(850.0));
    append_curve(p, 80.0, 520.0, 2500.0); // 850 .. 1530
    p.push_back(make_line(520.0));         // level crossing
    append_curve(p, 120.0, 360.0, -600.0); // 2050 .. 2650, canted
    p.push_back(make_line(1450.0));        // Sampleton with its passing loop
    append_curve(p, 100.0, 800.0, 1200.0); // 4100 .. 5100, tunnel inside
    p.push_back(make_line(650.0));         // bridge
    append_curve(p, 130.0, 260.0, -300.0); // 5750 .. 6270, 80 km/h
    p.push_back(make_line(700.0));         // Brookside halt
    append_curve(p, 90.0, 320.0, 600.0);   // 6970 .. 7470
    p.push_back(make_line(700.0));         // spur switch
    append_curve(p, 80.0, 400.0, -2500.0); // 8170 .. 8730
    p.push_back(make_line(600.0));
    return a;
}

// A reverse curve of two turnout arcs shifts the loop by loop_offset, so the
// loop leaves and rejoins the straight main line exactly at its switches.
double turnout_angle() { return std::acos(1.0 - loop_offset / (2.0 * turnout_radius)); }

geometry::Alignment loop_alignment(const geometry::Alignment& main, double s_switch) {
    const double k = 1.0 / turnout_radius;
    const double a = turnout_radius * turnout_angle();
    geometry::Alignment loop;
    loop.start = geometry::evaluate(main, s_switch);
    loop.primitives = {make_arc(a, k), make_arc(a, -k), make_line(loop_straight), make_arc(a, -k),
                       make_arc(a, k)};
    return loop;
}

geometry::Alignment spur_alignment(const geometry::Alignment& main, double s_switch) {
    geometry::Alignment spur;
    spur.start = geometry::evaluate(main, s_switch);
    spur.primitives = {make_arc(40.0, -1.0 / 190.0), make_line(30.0), make_arc(90.0, -1.0 / 150.0),
                       make_line(150.0)};
    return spur;
}

Tags with(Tags base, const Tags& extra) {
    base.insert(base.end(), extra.begin(), extra.end());
    return base;
}

Tags signal_tags(bool main_signal, bool forward, const std::string& ref) {
    const std::string kind = main_signal ? "main" : "distant";
    return {{"railway", "signal"},
            {"railway:signal:direction", forward ? "forward" : "backward"},
            {"railway:signal:position", "right"},
            {"railway:signal:" + kind, main_signal ? "DE-ESO:hp" : "DE-ESO:vr"},
            {"railway:signal:" + kind + ":form", "light"},
            {"ref", ref}};
}

Tags switch_tags(const std::string& ref, const std::string& side) {
    return {{"railway", "switch"}, {"railway:switch", "default"}, {"railway:turnout_side", side},
            {"ref", ref}};
}

void add_points(RouteDesign& d) {
    auto& pts = d.main_points;
    for (int km = 1; km <= 9; ++km) {
        pts.push_back({1000.0 * km, "milestone",
                       {{"railway", "milestone"}, {"railway:position", std::to_string(km) + ".0"}}});
    }
    pts.push_back({d.level_crossing, "level_crossing",
                   {{"railway", "level_crossing"}, {"crossing:barrier", "full"}, {"crossing:light", "yes"}}});
    // Entry signals 200 m outside the switches, distant signals 1000 m before them.
    pts.push_back({d.switch_loop_west - 1200.0, "signal", signal_tags(false, true, "a")});
    pts.push_back({d.switch_loop_west - 200.0, "signal", signal_tags(true, true, "A")});
    pts.push_back({d.switch_loop_east + 200.0, "signal", signal_tags(true, false, "F")});
    pts.push_back({d.switch_loop_east + 1200.0, "signal", signal_tags(false, false, "f")});
    pts.push_back({d.switch_loop_west, "switch", switch_tags("1", "left")});
    pts.push_back({d.switch_loop_east, "switch", switch_tags("2", "left")});
    pts.push_back({d.switch_spur, "switch", switch_tags("3", "right")});
    pts.push_back({d.station, "stop",
                   {{"railway", "stop"}, {"public_transport", "stop_position"}, {"train", "yes"},
                    {"name", "Sampleton"}}});
    pts.push_back({d.halt, "halt",
                   {{"railway", "halt"}, {"public_transport", "station"}, {"train", "yes"},
                    {"name", "Brookside"}}});
}

void add_ways(RouteDesign& d, double end) {
    const Tags cant{{"railway:cant", "100"}};
    const Tags station{{"railway:track_ref", "1"}};
    const Tags tunnel{{"tunnel", "yes"}, {"layer", "-1"}, {"tunnel:name", "Sample Hill Tunnel"}};
    const Tags bridge{{"bridge", "yes"}, {"layer", "1"}, {"bridge:name", "Brook Viaduct"}};
    d.main_ways = {
        {0.0, 2010.0, main_line_tags(160)},
        {2010.0, 2700.0, with(main_line_tags(120), cant)},
        {2700.0, d.switch_loop_west, main_line_tags(120)},
        {d.switch_loop_west, d.switch_loop_east, with(main_line_tags(100), station)},
        {d.switch_loop_east, d.tunnel.s_from, main_line_tags(160)},
        {d.tunnel.s_from, d.tunnel.s_to, with(main_line_tags(160), tunnel)},
        {d.tunnel.s_to, d.bridge.s_from, main_line_tags(160)},
        {d.bridge.s_from, d.bridge.s_to, with(main_line_tags(160), bridge)},
        {d.bridge.s_to, 5700.0, main_line_tags(160)},
        {5700.0, 6320.0, main_line_tags(80)},
        {6320.0, d.switch_spur, main_line_tags(120)},
        {d.switch_spur, end, main_line_tags(160)},
    };
}

void add_parallels(RouteDesign& d) {
    d.parallels = {
        {"platform", {3180.0, 3400.0}, -3.2,
         {{"railway", "platform"}, {"public_transport", "platform"}, {"ref", "1"}, {"name", "Sampleton"}}},
        {"platform", {6530.0, 6670.0}, 3.2,
         {{"railway", "platform"}, {"public_transport", "platform"}, {"ref", "1"}, {"name", "Brookside"}}},
        {"road", {2880.0, 3720.0}, -40.0,
         {{"highway", "residential"}, {"name", "Station Road"}, {"maxspeed", "30"}, {"surface", "asphalt"}}},
    };
}

void add_context(RouteDesign& d) {
    constexpr double deg = std::numbers::pi / 180.0;
    d.crossing_roads = {
        {d.level_crossing, 80.0 * deg, {-450.0, -270.0, -120.0, -30.0, 0.0, 35.0, 140.0, 290.0, 460.0},
         1.5e-4, true,
         {{"highway", "secondary"}, {"lanes", "2"}, {"maxspeed", "70"}, {"name", "Mill Road"},
          {"surface", "asphalt"}}},
        // Passes below the viaduct: no shared node, explicit ground layer.
        {d.road_under_bridge, d.valley_angle, {-620.0, -400.0, -180.0, -45.0, 50.0, 200.0, 410.0, 630.0},
         -2.0e-5, false,
         {{"highway", "tertiary"}, {"layer", "0"}, {"name", "Valley Road"}, {"surface", "asphalt"}}},
    };
    d.station_node = {d.station, -15.0,
                      {{"railway", "station"}, {"public_transport", "station"}, {"train", "yes"},
                       {"name", "Sampleton"}}};
}

void check(const RouteDesign& d) {
    const double end = geometry::length(d.main.alignment);
    double at = 0.0;
    for (const auto& w : d.main_ways) {
        if (w.s_from != at || !(w.s_to > w.s_from)) {
            throw std::logic_error("sample design: main-line way spans are not contiguous at s " +
                                   std::to_string(w.s_from));
        }
        at = w.s_to;
    }
    if (at != end) {
        throw std::logic_error("sample design: way spans end at " + std::to_string(at) +
                               ", main line at " + std::to_string(end));
    }
    for (const auto& p : d.main_points) {
        if (!(p.s > 0.0 && p.s < end)) {
            throw std::logic_error("sample design: " + p.kind + " at s " + std::to_string(p.s) +
                                   " lies off the main line");
        }
    }
}

} // namespace

Tags main_line_tags(int maxspeed) {
    return {{"railway", "rail"},
            {"usage", "main"},
            {"gauge", "1435"},
            {"electrified", "contact_line"},
            {"voltage", "15000"},
            {"frequency", "16.7"},
            {"maxspeed", std::to_string(maxspeed)},
            {"railway:preferred_direction", "both"},
            {"name", "Sample Valley Railway"}};
}

RouteDesign make_route_design() {
    RouteDesign d;
    d.main = {"main", main_alignment()};
    d.switch_loop_west = 3020.0;
    d.switch_loop_east = d.switch_loop_west + 4.0 * turnout_radius * std::sin(turnout_angle()) + loop_straight;
    d.switch_spur = 7700.0;
    d.level_crossing = 1650.0;
    d.station = 3290.0;
    d.halt = 6600.0;
    d.tunnel = {4300.0, 4900.0};
    d.bridge = {5350.0, 5500.0};
    d.road_under_bridge = 5425.0;
    d.valley_angle = 75.0 * std::numbers::pi / 180.0;
    d.loop = {"loop", loop_alignment(d.main.alignment, d.switch_loop_west)};
    d.spur = {"spur", spur_alignment(d.main.alignment, d.switch_spur)};

    d.loop_tags = with(main_line_tags(60), {{"service", "siding"}, {"railway:track_ref", "2"}});
    // A siding is not main line: usage goes, the name stays with the line.
    std::erase_if(d.loop_tags, [](const auto& t) { return t.first == "usage"; });
    d.spur_tags = {{"railway", "rail"}, {"service", "spur"},     {"usage", "industrial"},
                   {"gauge", "1435"},   {"electrified", "no"},   {"maxspeed", "25"},
                   {"name", "Sawmill Siding"}};

    add_points(d);
    add_ways(d, geometry::length(d.main.alignment));
    add_parallels(d);
    add_context(d);
    d.profile = VerticalProfile({{0.0, 470.0},
                                 {900.0, 474.5},
                                 {2300.0, 491.3},
                                 {3950.0, 491.3},
                                 {5300.0, 480.5},
                                 {6600.0, 485.7},
                                 {9330.0, 469.32}},
                                15000.0);
    check(d);
    return d;
}

} // namespace railodd::sample
