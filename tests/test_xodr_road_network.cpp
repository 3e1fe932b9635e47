// Corridor roads as OpenDRIVE: lanes from OSM tags, junctions with connecting
// roads that start and end exactly on their legs, direct links, degenerate
// graphs (short edges, loops, many legs), traceability and determinism.
#include "railodd/geometry/road_fit.hpp"
#include "railodd/geometry/track_graph.hpp"
#include "railodd/xodr/road_network.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <map>
#include <numbers>
#include <set>
#include <sstream>
#include <string>
#include <vector>

using namespace railodd;
using xodr::Contact;
using xodr::ElementType;
using xodr::PlanGeometry;

namespace {

constexpr double pi = std::numbers::pi;

ingest::NodeRef node(std::int64_t id, double x, double y) {
    ingest::NodeRef n;
    n.id = id;
    n.xy = {x, y};
    return n;
}

ingest::Way way(std::int64_t id, ingest::Tags tags, std::vector<ingest::NodeRef> nodes) {
    ingest::Way w;
    w.id = id;
    w.tags = std::move(tags);
    w.node_count = nodes.size();
    w.parts.push_back(std::move(nodes));
    return w;
}

const ingest::Tags residential{{"highway", "residential"}};

struct Built {
    geometry::TrackGraph graph;
    xodr::Map map;
    std::vector<xodr::BuiltRoad> roads;
};

Built build(const std::vector<ingest::Way>& ways, const std::vector<ingest::Feature>& features = {},
            xodr::RoadNetworkOptions options = {}) {
    Built b;
    b.graph = geometry::build_track_graph(ways, features);
    const auto fitted = geometry::fit_road_graph(b.graph, geometry::RoadFitOptions{});
    xodr::IdCounter ids;
    b.roads = xodr::add_road_network(b.graph, fitted, ways, options, ids, b.map);
    return b;
}

const xodr::Road& road(const xodr::Map& m, const std::string& id) {
    for (const auto& r : m.roads) {
        if (r.id == id) {
            return r;
        }
    }
    throw std::runtime_error("no road " + id);
}

std::string user(const std::vector<xodr::UserData>& data, const std::string& code) {
    for (const auto& u : data) {
        if (u.code == code) {
            return u.value;
        }
    }
    return {};
}

std::vector<const xodr::Road*> connecting_roads(const xodr::Map& m) {
    std::vector<const xodr::Road*> out;
    for (const auto& r : m.roads) {
        if (r.junction != "-1") {
            out.push_back(&r);
        }
    }
    return out;
}

std::vector<const xodr::Road*> plain_roads(const xodr::Map& m) {
    std::vector<const xodr::Road*> out;
    for (const auto& r : m.roads) {
        if (r.junction == "-1") {
            out.push_back(&r);
        }
    }
    return out;
}

// Pose at p along one planView record, as a reader evaluates it.
geometry::Pose at(const PlanGeometry& g, double p) {
    if (g.kind == PlanGeometry::Kind::param_poly3) {
        const double u = g.u[0] + p * (g.u[1] + p * (g.u[2] + p * g.u[3]));
        const double v = g.v[0] + p * (g.v[1] + p * (g.v[2] + p * g.v[3]));
        const double du = g.u[1] + p * (2 * g.u[2] + 3 * p * g.u[3]);
        const double dv = g.v[1] + p * (2 * g.v[2] + 3 * p * g.v[3]);
        return {g.x + u * std::cos(g.hdg) - v * std::sin(g.hdg), g.y + u * std::sin(g.hdg) + v * std::cos(g.hdg),
                g.hdg + std::atan2(dv, du), 0.0};
    }
    geometry::Primitive prim = g.kind == PlanGeometry::Kind::line  ? geometry::make_line(g.length)
                               : g.kind == PlanGeometry::Kind::arc ? geometry::make_arc(g.length, g.curv_start)
                                                                   : geometry::make_spiral(g.length, g.curv_start, g.curv_end);
    return geometry::evaluate({g.x, g.y, g.hdg, 0.0}, prim, p);
}

// Pose of a road at its start or end, heading along the reference line.
geometry::Pose road_pose(const xodr::Road& r, Contact c) {
    return c == Contact::start ? at(r.plan_view.front(), 0.0) : at(r.plan_view.back(), r.plan_view.back().length);
}

double angle_diff(double a, double b) { return std::abs(std::remainder(a - b, 2 * pi)); }

// Length of a paramPoly3 record by many chords.
double polyline_length(const PlanGeometry& g) {
    constexpr int n = 20000;
    double len = 0.0;
    geometry::Pose prev = at(g, 0.0);
    for (int i = 1; i <= n; ++i) {
        const geometry::Pose p = at(g, g.length * i / n);
        len += std::hypot(p.x - prev.x, p.y - prev.y);
        prev = p;
    }
    return len;
}

std::set<std::int64_t> ways_named(const std::string& value) {
    std::set<std::int64_t> ids;
    std::stringstream in(value);
    std::string item;
    while (std::getline(in, item, ',')) {
        if (item.rfind("way:", 0) == 0) {
            ids.insert(std::stoll(item.substr(4)));
        }
    }
    return ids;
}

// What every built network must satisfy; returns the number of connecting roads.
std::size_t check_network(const Built& b, const std::vector<ingest::Way>& ways) {
    const xodr::Map& m = b.map;
    std::set<std::string> ids;
    for (const auto& r : m.roads) {
        EXPECT_TRUE(ids.insert(r.id).second) << "duplicate road id " << r.id;
        EXPECT_EQ(r.rule, "RHT");
        EXPECT_FALSE(r.lane_sections.empty());
        EXPECT_EQ(r.lane_sections.front().s, 0.0);
        for (std::size_t i = 1; i < r.lane_sections.size(); ++i) {
            EXPECT_GT(r.lane_sections[i].s, r.lane_sections[i - 1].s);
            EXPECT_LT(r.lane_sections[i].s, r.length());
        }
        double s = 0.0;
        for (const auto& g : r.plan_view) {
            EXPECT_NEAR(g.s, s, 1e-9);
            s += g.length;
        }
    }
    // Nothing dropped: every way is named by a road or a junction.
    std::set<std::int64_t> named;
    for (const auto& r : m.roads) {
        for (auto id : ways_named(user(r.user_data, "osm"))) {
            named.insert(id);
        }
    }
    for (const auto& j : m.junctions) {
        for (auto id : ways_named(user(j.user_data, "osm"))) {
            named.insert(id);
        }
    }
    for (const auto& w : ways) {
        EXPECT_TRUE(named.count(w.id)) << "way " << w.id << " is in no road or junction";
    }
    // Built roads are the plain roads, with their alignments.
    EXPECT_EQ(b.roads.size(), plain_roads(m).size());
    for (const auto& br : b.roads) {
        const auto& r = road(m, br.road_id);
        EXPECT_NEAR(geometry::length(br.alignment), r.length(), 1e-9);
        const auto end = geometry::evaluate(br.alignment, geometry::length(br.alignment));
        const auto rend = road_pose(r, Contact::end);
        EXPECT_NEAR(end.x, rend.x, 1e-9);
        EXPECT_NEAR(end.y, rend.y, 1e-9);
    }
    // Connecting roads: exactly on their legs, G1, lanes linked.
    const auto conn = connecting_roads(m);
    std::size_t connections = 0;
    for (const auto& j : m.junctions) {
        connections += j.connections.size();
        for (const auto& c : j.connections) {
            const auto& cr = road(m, c.connecting_road);
            EXPECT_EQ(cr.junction, j.id);
            EXPECT_EQ(cr.predecessor.id, c.incoming_road);
            EXPECT_EQ(c.contact, Contact::start);
            EXPECT_EQ(c.lane_links.size(), cr.lane_sections.front().right.size());
        }
    }
    EXPECT_EQ(connections, conn.size());
    for (const auto* c : conn) {
        EXPECT_EQ(c->plan_view.size(), 1u);
        const PlanGeometry& g = c->plan_view.front();
        EXPECT_EQ(c->predecessor.type, ElementType::road);
        EXPECT_EQ(c->successor.type, ElementType::road);
        const auto& in = road(m, c->predecessor.id);
        const auto& out = road(m, c->successor.id);
        EXPECT_EQ(in.junction, "-1");
        EXPECT_EQ(out.junction, "-1");
        // The legs point to the junction.
        const auto& in_link = c->predecessor.contact == Contact::end ? in.successor : in.predecessor;
        const auto& out_link = c->successor.contact == Contact::end ? out.successor : out.predecessor;
        EXPECT_EQ(in_link.type, ElementType::junction);
        EXPECT_EQ(in_link.id, c->junction);
        EXPECT_EQ(out_link.type, ElementType::junction);
        EXPECT_EQ(out_link.id, c->junction);
        geometry::Pose from = road_pose(in, c->predecessor.contact);
        if (c->predecessor.contact == Contact::start) {
            from.hdg += pi;
        }
        geometry::Pose to = road_pose(out, c->successor.contact);
        if (c->successor.contact == Contact::end) {
            to.hdg += pi;
        }
        const auto p0 = at(g, 0.0);
        const auto p1 = at(g, g.length);
        EXPECT_NEAR(p0.x, from.x, 1e-9);
        EXPECT_NEAR(p0.y, from.y, 1e-9);
        EXPECT_LT(angle_diff(p0.hdg, from.hdg), 1e-9);
        EXPECT_NEAR(p1.x, to.x, 1e-9) << "connecting road " << c->id;
        EXPECT_NEAR(p1.y, to.y, 1e-9) << "connecting road " << c->id;
        EXPECT_LT(angle_diff(p1.hdg, to.hdg), 1e-9) << "connecting road " << c->id;
        if (g.kind == PlanGeometry::Kind::param_poly3) {
            EXPECT_NEAR(polyline_length(g), g.length, 1e-6 * g.length);
            // No cusp: p advances at a speed near the arc length's everywhere.
            for (int i = 0; i <= 100; ++i) {
                const double p = g.length * i / 100;
                const double du = g.u[1] + p * (2 * g.u[2] + 3 * p * g.u[3]);
                const double dv = g.v[1] + p * (2 * g.v[2] + 3 * p * g.v[3]);
                EXPECT_GT(std::hypot(du, dv), 0.3) << "connecting road " << c->id << " at p = " << p;
            }
        } else {
            EXPECT_EQ(g.kind, PlanGeometry::Kind::line);
        }
        // Lanes: -1..-n, linked to lanes that exist on the legs.
        const auto& sec = c->lane_sections.front();
        EXPECT_TRUE(sec.left.empty());
        EXPECT_FALSE(sec.right.empty());
        const auto& in_sec = c->predecessor.contact == Contact::end ? in.lane_sections.back() : in.lane_sections.front();
        const auto& out_sec =
            c->successor.contact == Contact::end ? out.lane_sections.back() : out.lane_sections.front();
        for (std::size_t q = 0; q < sec.right.size(); ++q) {
            const auto& l = sec.right[q];
            EXPECT_EQ(l.id, -static_cast<int>(q + 1));
            if (!l.link.predecessor || !l.link.successor) {
                ADD_FAILURE() << "connecting road " << c->id << " lane " << l.id << " is not linked";
                continue;
            }
            // Entering lanes: right lanes at the incoming road's end, left at its start.
            EXPECT_EQ(*l.link.predecessor < 0, c->predecessor.contact == Contact::end);
            EXPECT_EQ(*l.link.successor < 0, c->successor.contact == Contact::start);
            const auto& in_side = *l.link.predecessor > 0 ? in_sec.left : in_sec.right;
            const auto& out_side = *l.link.successor > 0 ? out_sec.left : out_sec.right;
            EXPECT_LE(static_cast<std::size_t>(std::abs(*l.link.predecessor)), in_side.size());
            EXPECT_LE(static_cast<std::size_t>(std::abs(*l.link.successor)), out_side.size());
        }
    }
    return conn.size();
}

// Movements between the roads' ids: "in>out" for each connecting road.
std::multiset<std::string> movements(const xodr::Map& m) {
    std::multiset<std::string> out;
    for (const auto* c : connecting_roads(m)) {
        out.insert(c->predecessor.id + ">" + c->successor.id);
    }
    return out;
}

// Road built from the way whose "osm" userData is exactly "way:ID".
const xodr::Road& road_of_way(const xodr::Map& m, std::int64_t way_id) {
    for (const auto& r : m.roads) {
        if (r.junction == "-1" && user(r.user_data, "osm") == "way:" + std::to_string(way_id)) {
            return r;
        }
    }
    throw std::runtime_error("no road of way " + std::to_string(way_id));
}

// Does the road touch the junction at its end (true) or its start (false)?
bool ends_at_junction(const xodr::Road& r) { return r.successor.type == ElementType::junction; }

// T junction at node 100 (0, 0): west (way 1), east (way 2), north (way 3).
std::vector<ingest::Way> t_junction(ingest::Tags west, ingest::Tags east, ingest::Tags north) {
    return {way(1, west, {node(1, -200, 0), node(2, -100, 0), node(100, 0, 0)}),
            way(2, east, {node(100, 0, 0), node(4, 100, 0), node(5, 200, 0)}),
            way(3, north, {node(100, 0, 0), node(6, 0, 80), node(7, 0, 160)})};
}

} // namespace

TEST(RoadNetwork, TJunctionOfTwoWayRoads) {
    const auto ways = t_junction(residential, residential, residential);
    const Built b = build(ways);
    ASSERT_EQ(plain_roads(b.map).size(), 3u);
    ASSERT_EQ(b.map.junctions.size(), 1u);
    EXPECT_EQ(check_network(b, ways), 6u); // every ordered pair of distinct legs
    EXPECT_EQ(user(b.map.junctions[0].user_data, "osm"), "node:100");
    for (const auto* c : connecting_roads(b.map)) {
        EXPECT_EQ(user(c->user_data, "osm"), "node:100");
        EXPECT_EQ(c->lane_sections.front().right.size(), 1u);
    }
    // Legs cut back at least the clearance, at most a third.
    for (const auto& br : b.roads) {
        const double full = br.way_ids[0] == 3 ? 160.0 : 200.0;
        EXPECT_LE(geometry::length(br.alignment), full - 4.0 + 1e-9);
        EXPECT_GE(geometry::length(br.alignment), full * 2.0 / 3.0 - 1e-9);
    }
    // West to east straight on: a line; turns: paramPoly3.
    const auto& west = road_of_way(b.map, 1);
    const auto& east = road_of_way(b.map, 2);
    std::size_t lines = 0;
    for (const auto* c : connecting_roads(b.map)) {
        if (c->plan_view[0].kind == PlanGeometry::Kind::line) {
            ++lines;
            EXPECT_TRUE((c->predecessor.id == west.id && c->successor.id == east.id) ||
                        (c->predecessor.id == east.id && c->successor.id == west.id));
        }
    }
    EXPECT_EQ(lines, 2u);
    // Residential default: one 2.75 m lane each way.
    ASSERT_EQ(west.lane_sections.size(), 1u);
    EXPECT_EQ(west.lane_sections[0].left.size(), 1u);
    EXPECT_EQ(west.lane_sections[0].right.size(), 1u);
    EXPECT_DOUBLE_EQ(west.lane_sections[0].right[0].width, 2.75);
    EXPECT_EQ(west.type, "town");
    EXPECT_EQ(user(west.user_data, "osm_edge_nodes").find("100") != std::string::npos, true);
}

TEST(RoadNetwork, OnewayLegsAllowFewerMovements) {
    // East leg one-way away from the junction: nothing enters from it.
    auto ways = t_junction(residential, {{"highway", "residential"}, {"oneway", "yes"}}, residential);
    Built b = build(ways);
    EXPECT_EQ(check_network(b, ways), 4u);
    const auto& east = road_of_way(b.map, 2);
    for (const auto* c : connecting_roads(b.map)) {
        EXPECT_NE(c->predecessor.id, east.id);
    }
    // Its one lane drives away from the junction.
    const auto& sec = ends_at_junction(east) ? east.lane_sections.back() : east.lane_sections.front();
    EXPECT_EQ(sec.left.size() + sec.right.size(), 1u);
    EXPECT_EQ(sec.right.size(), ends_at_junction(east) ? 0u : 1u);

    // oneway=-1 on the same way: traffic only towards the junction.
    ways = t_junction(residential, {{"highway", "residential"}, {"oneway", "-1"}}, residential);
    b = build(ways);
    EXPECT_EQ(check_network(b, ways), 4u);
    const auto& east2 = road_of_way(b.map, 2);
    for (const auto* c : connecting_roads(b.map)) {
        EXPECT_NE(c->successor.id, east2.id);
    }
    const auto& sec2 = ends_at_junction(east2) ? east2.lane_sections.back() : east2.lane_sections.front();
    EXPECT_EQ(sec2.left.size() + sec2.right.size(), 1u);
    EXPECT_EQ(sec2.right.size(), ends_at_junction(east2) ? 1u : 0u);

    // Two one-way legs both leading away: only the north leg feeds the junction.
    ways = t_junction({{"highway", "residential"}, {"oneway", "-1"}}, {{"highway", "residential"}, {"oneway", "yes"}},
                      residential);
    b = build(ways);
    EXPECT_EQ(check_network(b, ways), 2u);
}

TEST(RoadNetwork, LaneCountsFromTags) {
    // Separate ways, no junctions: one road each.
    const std::vector<std::pair<ingest::Tags, std::array<int, 2>>> cases{
        {{{"highway", "primary"}, {"lanes", "4"}}, {2, 2}},
        {{{"highway", "primary"}, {"lanes", "2"}, {"oneway", "yes"}}, {0, 2}},
        {{{"highway", "primary"}, {"lanes", "3"}, {"lanes:forward", "2"}}, {1, 2}},
        {{{"highway", "primary"}}, {1, 1}},
        {{{"highway", "motorway"}}, {0, 2}},
        {{{"highway", "service"}}, {1, 1}},
        {{{"highway", "residential"}, {"lanes", "1"}}, {1, 1}},
        {{{"highway", "footway"}}, {1, 1}},
        {{{"highway", "cycleway"}, {"oneway", "yes"}}, {0, 1}},
        {{{"highway", "secondary"}, {"lanes", "2"}, {"width", "7"}}, {1, 1}},
    };
    std::vector<ingest::Way> ways;
    for (std::size_t i = 0; i < cases.size(); ++i) {
        const double y = 50.0 * static_cast<double>(i);
        const std::int64_t n = 10 * static_cast<std::int64_t>(i + 1);
        ways.push_back(way(static_cast<std::int64_t>(i + 1), cases[i].first, {node(n, 0, y), node(n + 1, 100, y)}));
    }
    const Built b = build(ways);
    EXPECT_EQ(check_network(b, ways), 0u);
    EXPECT_TRUE(b.map.junctions.empty());
    for (std::size_t i = 0; i < cases.size(); ++i) {
        const auto& r = road_of_way(b.map, static_cast<std::int64_t>(i + 1));
        ASSERT_EQ(r.lane_sections.size(), 1u);
        // Each way runs along its road here (the graph walks from the smaller node id).
        EXPECT_EQ(static_cast<int>(r.lane_sections[0].left.size()), cases[i].second[0]) << "case " << i;
        EXPECT_EQ(static_cast<int>(r.lane_sections[0].right.size()), cases[i].second[1]) << "case " << i;
        EXPECT_EQ(r.predecessor.type, ElementType::none);
        EXPECT_EQ(r.successor.type, ElementType::none);
    }
    const auto lane0 = [&](int way_id) { return road_of_way(b.map, way_id).lane_sections[0].right[0]; };
    EXPECT_DOUBLE_EQ(lane0(4).width, 3.5);   // primary default
    EXPECT_DOUBLE_EQ(lane0(5).width, 3.75);  // motorway default
    EXPECT_EQ(road_of_way(b.map, 5).type, "motorway");
    EXPECT_EQ(road_of_way(b.map, 4).type, "rural");
    EXPECT_DOUBLE_EQ(lane0(6).width, 2.5);   // service: one shared lane as one narrow lane each way
    EXPECT_EQ(lane0(8).type, "sidewalk");
    EXPECT_DOUBLE_EQ(lane0(8).width, 1.0);   // footway 2 m split in two
    EXPECT_EQ(road_of_way(b.map, 8).type, "pedestrian");
    EXPECT_EQ(lane0(9).type, "biking");
    EXPECT_DOUBLE_EQ(lane0(10).width, 3.5);  // width=7 over two lanes
    // Lane marks: broken between lanes of one direction, solid edges on main roads.
    const auto& four = road_of_way(b.map, 1).lane_sections[0];
    EXPECT_EQ(four.right[0].road_mark, "broken");
    EXPECT_EQ(four.right[1].road_mark, "solid");
}

TEST(RoadNetwork, FourWayCrossing) {
    const ingest::Tags wide{{"highway", "primary"}, {"lanes", "4"}};
    const std::vector<ingest::Way> ways{
        way(1, wide, {node(1, -150, 0), node(100, 0, 0)}),
        way(2, wide, {node(100, 0, 0), node(3, 150, 0)}),
        way(3, residential, {node(4, 0, -120), node(100, 0, 0)}),
        way(4, residential, {node(100, 0, 0), node(5, 0, 120)}),
    };
    const Built b = build(ways);
    ASSERT_EQ(b.map.junctions.size(), 1u);
    EXPECT_EQ(check_network(b, ways), 12u);
    const auto& w = road_of_way(b.map, 1);
    const auto& e = road_of_way(b.map, 2);
    const auto& s = road_of_way(b.map, 3);
    for (const auto* c : connecting_roads(b.map)) {
        const bool wide_to_wide = (c->predecessor.id == w.id && c->successor.id == e.id) ||
                                  (c->predecessor.id == e.id && c->successor.id == w.id);
        EXPECT_EQ(c->lane_sections[0].right.size(), wide_to_wide ? 2u : 1u) << c->predecessor.id << ">" << c->successor.id;
    }
    // The narrow legs are cut back far enough to clear the wide road (7 m half width).
    EXPECT_LE(s.length(), 120.0 - 7.0 + 1e-9);
    EXPECT_EQ(movements(b.map).count(s.id + ">" + w.id), 1u);
}

TEST(RoadNetwork, WaySplitWithEqualTagsIsOneRoad) {
    const std::vector<ingest::Way> ways{
        way(1, residential, {node(1, 0, 0), node(2, 100, 0)}),
        way(2, residential, {node(2, 100, 0), node(3, 200, 10)}),
    };
    const Built b = build(ways);
    ASSERT_EQ(b.map.roads.size(), 1u);
    EXPECT_EQ(check_network(b, ways), 0u);
    EXPECT_EQ(user(b.map.roads[0].user_data, "osm"), "way:1,way:2");
    EXPECT_EQ(user(b.map.roads[0].user_data, "osm_edge_nodes"), "1,3");
    EXPECT_EQ(b.map.roads[0].lane_sections.size(), 1u);
    EXPECT_EQ(b.roads[0].way_ids, (std::vector<std::int64_t>{1, 2}));
}

TEST(RoadNetwork, WaySplitWithChangingTagsIsALaneSection) {
    const std::vector<ingest::Way> ways{
        way(1, {{"highway", "secondary"}, {"lanes", "4"}}, {node(1, 0, 0), node(2, 100, 0)}),
        way(2, {{"highway", "secondary"}}, {node(2, 100, 0), node(3, 200, 0)}),
    };
    const Built b = build(ways);
    ASSERT_EQ(b.map.roads.size(), 1u);
    check_network(b, ways);
    const auto& r = b.map.roads[0];
    ASSERT_EQ(r.lane_sections.size(), 2u);
    EXPECT_NEAR(r.lane_sections[1].s, 100.0, 1e-6);
    EXPECT_EQ(r.lane_sections[0].right.size(), 2u);
    EXPECT_EQ(r.lane_sections[1].right.size(), 1u);
    EXPECT_EQ(r.lane_sections[0].right[0].link.successor, -1);
    EXPECT_FALSE(r.lane_sections[0].right[1].link.successor); // the outer lane ends
    EXPECT_EQ(r.lane_sections[1].right[0].link.predecessor, -1);
}

TEST(RoadNetwork, TwoEndsMeetingAreLinkedDirectly) {
    // A node the graph keeps as a vertex of degree two (tagged as a feature).
    const std::vector<ingest::Way> ways{
        way(1, residential, {node(1, 0, 0), node(2, 100, 0)}),
        way(2, {{"highway", "residential"}, {"oneway", "yes"}}, {node(2, 100, 0), node(3, 200, 0)}),
    };
    ingest::Feature f;
    f.osm_type = "node";
    f.id = 2;
    f.kind = "switch";
    f.on_track = true;
    const Built b = build(ways, {f});
    ASSERT_EQ(b.map.roads.size(), 2u);
    EXPECT_TRUE(b.map.junctions.empty());
    check_network(b, ways);
    const auto& a = road_of_way(b.map, 1);
    const auto& c = road_of_way(b.map, 2);
    EXPECT_EQ(a.successor.type, ElementType::road);
    EXPECT_EQ(a.successor.id, c.id);
    EXPECT_EQ(a.successor.contact, Contact::start);
    EXPECT_EQ(c.predecessor.id, a.id);
    EXPECT_EQ(c.predecessor.contact, Contact::end);
    EXPECT_EQ(a.lane_sections.back().right[0].link.successor, -1);
    EXPECT_FALSE(a.lane_sections.back().left[0].link.successor); // no left lane on the one-way road
    EXPECT_EQ(c.lane_sections.front().right[0].link.predecessor, -1);
    // Not cut back: the roads meet at the node.
    EXPECT_NEAR(a.length() + c.length(), 200.0, 1e-6);
}

TEST(RoadNetwork, RingIsLinkedToItself) {
    // Closed way starting halfway along a side: its ends continue each other.
    const std::vector<ingest::Way> ways{way(1, residential,
                                            {node(1, 50, 0), node(2, 100, 0), node(3, 100, 100), node(4, 0, 100),
                                             node(5, 0, 0), node(1, 50, 0)})};
    const Built b = build(ways);
    ASSERT_EQ(b.map.roads.size(), 1u);
    check_network(b, ways);
    const auto& r = b.map.roads[0];
    EXPECT_EQ(r.successor.id, r.id);
    EXPECT_EQ(r.successor.contact, Contact::start);
    EXPECT_EQ(r.predecessor.id, r.id);
    EXPECT_EQ(r.predecessor.contact, Contact::end);
    EXPECT_EQ(r.lane_sections.back().right[0].link.successor, -1);
    EXPECT_EQ(r.lane_sections.front().left[0].link.predecessor, 1);
}

TEST(RoadNetwork, RingStartingAtACornerGetsAJunction) {
    // The ends meet at a right angle: a direct link would kink, so a junction
    // with one connecting road per direction rounds the corner.
    const std::vector<ingest::Way> ways{way(
        1, residential, {node(1, 0, 0), node(2, 100, 0), node(3, 100, 100), node(4, 0, 100), node(1, 0, 0)})};
    const Built b = build(ways);
    ASSERT_EQ(b.map.junctions.size(), 1u);
    EXPECT_EQ(plain_roads(b.map).size(), 1u);
    EXPECT_EQ(check_network(b, ways), 2u);
    // The same as a footway: no movement, so neither a junction nor a kinked link.
    const std::vector<ingest::Way> foot{way(1, {{"highway", "footway"}}, ways[0].parts[0])};
    const Built f = build(foot);
    EXPECT_TRUE(f.map.junctions.empty());
    EXPECT_EQ(f.map.roads[0].predecessor.type, ElementType::none);
    EXPECT_EQ(f.map.roads[0].successor.type, ElementType::none);
}

TEST(RoadNetwork, DuplicateWaysBetweenTwoJunctions) {
    // Two ways over the same 3 m between nodes 100 and 101: their cut ends
    // coincide, so no connecting road leads from one to the other.
    const std::vector<ingest::Way> ways{
        way(1, residential, {node(1, -150, 0), node(100, 0, 0)}),
        way(2, residential, {node(100, 0, 0), node(101, 3, 0)}),
        way(3, residential, {node(100, 0, 0), node(101, 3, 0)}),
        way(4, residential, {node(101, 3, 0), node(4, 150, 0)}),
    };
    const Built b = build(ways);
    ASSERT_EQ(b.map.junctions.size(), 2u);
    EXPECT_EQ(plain_roads(b.map).size(), 4u);
    EXPECT_EQ(check_network(b, ways), 8u);
    for (const auto* c : connecting_roads(b.map)) {
        EXPECT_GT(c->length(), 0.5);
    }
}

TEST(RoadNetwork, ShortEdgeBetweenTwoNodesIsFoldedIntoOneJunction) {
    // Two T nodes 0.5 m apart (a typical mapping of a staggered crossing).
    const std::vector<ingest::Way> ways{
        way(1, residential, {node(1, -150, 0), node(100, 0, 0)}),
        way(2, residential, {node(100, 0, 0), node(101, 0.5, 0)}),
        way(3, residential, {node(101, 0.5, 0), node(3, 150, 0)}),
        way(4, residential, {node(100, 0, 0), node(4, 0, 120)}),
        way(5, residential, {node(101, 0.5, 0), node(5, 0.5, -120)}),
    };
    const Built b = build(ways);
    ASSERT_EQ(b.map.junctions.size(), 1u);
    EXPECT_EQ(plain_roads(b.map).size(), 4u);
    EXPECT_EQ(check_network(b, ways), 12u);
    EXPECT_EQ(user(b.map.junctions[0].user_data, "osm"), "node:100,node:101,way:2");
}

TEST(RoadNetwork, ShortEdgeBetweenJunctionsStaysAShortRoad) {
    // 6 m between two T nodes: kept, cut back by at most a third at each end.
    const std::vector<ingest::Way> ways{
        way(1, residential, {node(1, -150, 0), node(100, 0, 0)}),
        way(2, residential, {node(100, 0, 0), node(101, 6, 0)}),
        way(3, residential, {node(101, 6, 0), node(3, 150, 0)}),
        way(4, residential, {node(100, 0, 0), node(4, 0, 120)}),
        way(5, residential, {node(101, 6, 0), node(5, 6, -120)}),
    };
    const Built b = build(ways);
    ASSERT_EQ(b.map.junctions.size(), 2u);
    EXPECT_EQ(check_network(b, ways), 12u);
    const auto& mid = road_of_way(b.map, 2);
    EXPECT_NEAR(mid.length(), 2.0, 1e-9);
    EXPECT_EQ(mid.predecessor.type, ElementType::junction);
    EXPECT_EQ(mid.successor.type, ElementType::junction);
    EXPECT_NE(mid.predecessor.id, mid.successor.id);
}

TEST(RoadNetwork, LoopAtAJunction) {
    // A stem into node 100 and a loop leaving and returning to it.
    const std::vector<ingest::Way> ways{
        way(1, residential, {node(1, -150, 0), node(100, 0, 0)}),
        way(2, residential, {node(100, 0, 0), node(2, 100, 60), node(3, 100, -60), node(100, 0, 0)}),
    };
    const Built b = build(ways);
    ASSERT_EQ(b.map.junctions.size(), 1u);
    EXPECT_EQ(plain_roads(b.map).size(), 2u);
    EXPECT_EQ(check_network(b, ways), 6u); // three legs, all two-way
    const auto& loop = road_of_way(b.map, 2);
    EXPECT_EQ(loop.predecessor.type, ElementType::junction);
    EXPECT_EQ(loop.successor.type, ElementType::junction);
}

TEST(RoadNetwork, FiveLegsAndDeterminism) {
    std::vector<ingest::Way> ways;
    for (int k = 0; k < 5; ++k) {
        const double a = 2 * pi * k / 5 + 0.1;
        ways.push_back(way(k + 1, k == 2 ? ingest::Tags{{"highway", "footway"}} : residential,
                           {node(100, 0, 0), node(k + 1, 100 * std::cos(a), 100 * std::sin(a))}));
    }
    const Built b = build(ways);
    ASSERT_EQ(b.map.junctions.size(), 1u);
    EXPECT_EQ(check_network(b, ways), 12u); // 4 driving legs: 4 x 3; the footway joins no movement
    const auto& foot = road_of_way(b.map, 3);
    EXPECT_EQ((ends_at_junction(foot) ? foot.successor : foot.predecessor).type, ElementType::junction);
    const Built again = build(ways);
    ASSERT_EQ(again.map.roads.size(), b.map.roads.size());
    for (std::size_t i = 0; i < b.map.roads.size(); ++i) {
        EXPECT_EQ(again.map.roads[i].id, b.map.roads[i].id);
        EXPECT_EQ(again.map.roads[i].plan_view[0].x, b.map.roads[i].plan_view[0].x);
        EXPECT_EQ(again.map.roads[i].length(), b.map.roads[i].length());
    }
    EXPECT_EQ(movements(again.map), movements(b.map));
}

TEST(RoadNetwork, NonMotorJunctionWithoutMovementsIsNoJunction) {
    const ingest::Tags foot{{"highway", "footway"}};
    const auto ways = t_junction(foot, foot, foot);
    const Built b = build(ways);
    EXPECT_TRUE(b.map.junctions.empty());
    EXPECT_EQ(check_network(b, ways), 0u);
    double total = 0.0;
    for (const auto& r : b.map.roads) {
        total += r.length();
    }
    EXPECT_NEAR(total, 560.0, 1e-6); // nothing cut
}

TEST(RoadNetwork, JunctionWhoseCutEndsHaveNoMovementIsUndone) {
    // Footways whose last 2 m before node 100 are mapped as residential: at
    // the node west and east could be driven through, but the cut ends are
    // footway, so no connecting road can be built and nothing is cut.
    const ingest::Tags foot{{"highway", "footway"}};
    const std::vector<ingest::Way> ways{
        way(1, foot, {node(1, -200, 0), node(11, -2, 0)}),
        way(2, residential, {node(11, -2, 0), node(100, 0, 0)}),
        way(3, residential, {node(100, 0, 0), node(12, 2, 0)}),
        way(4, foot, {node(12, 2, 0), node(5, 200, 0)}),
        way(5, foot, {node(100, 0, 0), node(7, 0, 160)}),
    };
    const Built b = build(ways);
    EXPECT_TRUE(b.map.junctions.empty());
    EXPECT_EQ(check_network(b, ways), 0u);
    double total = 0.0;
    for (const auto& r : b.map.roads) {
        total += r.length();
        EXPECT_EQ(r.predecessor.type, ElementType::none);
        EXPECT_EQ(r.successor.type, ElementType::none);
    }
    EXPECT_NEAR(total, 560.0, 1e-6);
}
