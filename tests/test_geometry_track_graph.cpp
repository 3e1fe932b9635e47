// The track graph on tiny inline OPL inputs and on the sample route: merging
// across way splits, splitting at switches and crossings, rings, clipped ways.
#include "railodd/geometry/track_graph.hpp"
#include "railodd/sample/sample_route.hpp"
#include "graph_test_support.hpp"

#include <algorithm>
#include <set>

using namespace railodd;
using geometry::TrackGraph;
using geometry::VertexKind;
using railodd::test::check_conservation;
using railodd::test::read_opl;

namespace {

TrackGraph graph_of(const ingest::IngestResult& r) {
    TrackGraph g = geometry::build_track_graph(r.tracks, r.features);
    EXPECT_EQ(check_conservation(g, r.tracks), "");
    EXPECT_EQ(test::edge_segments(g), test::way_segments(r.tracks));
    return g;
}

const geometry::GraphVertex* vertex(const TrackGraph& g, std::int64_t node) {
    const auto it = std::find_if(g.vertices.begin(), g.vertices.end(),
                                 [&](const geometry::GraphVertex& v) { return v.node_id == node; });
    return it == g.vertices.end() ? nullptr : &*it;
}

std::vector<std::int64_t> node_ids(const geometry::GraphEdge& e) {
    std::vector<std::int64_t> ids;
    for (const auto& n : e.nodes) {
        ids.push_back(n.id);
    }
    return ids;
}

// Seven nodes eastwards along 48.0 N, about 74 m apart; n8, n9 branch off north-east.
const char* const line_nodes = R"(n1 v1 x10.000 y48.0
n2 v1 x10.001 y48.0
n3 v1 x10.002 y48.0
n4 v1 x10.003 y48.0
n5 v1 x10.004 y48.0
n6 v1 x10.005 y48.0
n7 v1 x10.006 y48.0
n8 v1 x10.003 y48.0005
n9 v1 x10.004 y48.001
)";

} // namespace

TEST(TrackGraph, WaySplitsMergeIntoOneEdge) {
    const auto r = read_opl(std::string{line_nodes} + R"(w1 v1 Trailway=rail,maxspeed=100 Nn1,n2,n3
w2 v1 Trailway=rail,maxspeed=120 Nn3,n4,n5
w3 v1 Trailway=rail,maxspeed=80 Nn5,n6,n7
)");
    const TrackGraph g = graph_of(r);
    ASSERT_EQ(g.edges.size(), 1u);
    ASSERT_EQ(g.vertices.size(), 2u);
    const auto& e = g.edges[0];
    EXPECT_EQ(node_ids(e), (std::vector<std::int64_t>{1, 2, 3, 4, 5, 6, 7}));
    ASSERT_EQ(e.ways.size(), 3u);
    EXPECT_EQ(e.ways[0].way_id, 1);
    EXPECT_EQ(e.ways[1].way_id, 2);
    EXPECT_EQ(e.ways[2].way_id, 3);
    EXPECT_EQ(e.ways[1].first, 2u);
    EXPECT_EQ(e.ways[1].last, 4u);
    EXPECT_FALSE(e.ways[1].reversed);
    EXPECT_EQ(g.vertices[e.from].node_id, 1);
    EXPECT_EQ(g.vertices[e.to].node_id, 7);
    EXPECT_EQ(g.vertices[e.from].kind, VertexKind::end);
    EXPECT_NEAR(e.nodes[6].xy.x - e.nodes[0].xy.x, 447.7, 0.5);
}

TEST(TrackGraph, WayAgainstTheEdgeIsAReversedSpan) {
    const auto r = read_opl(std::string{line_nodes} + R"(w1 v1 Trailway=rail Nn1,n2,n3
w2 v1 Trailway=rail Nn5,n4,n3
w3 v1 Trailway=rail Nn7,n6,n5
)");
    const TrackGraph g = graph_of(r);
    ASSERT_EQ(g.edges.size(), 1u);
    const auto& e = g.edges[0];
    EXPECT_EQ(e.nodes.front().id, 1) << "edges run from their lower-id end";
    ASSERT_EQ(e.ways.size(), 3u);
    EXPECT_FALSE(e.ways[0].reversed);
    EXPECT_TRUE(e.ways[1].reversed);
    EXPECT_TRUE(e.ways[2].reversed);
    EXPECT_EQ(e.ways[2].way_id, 3);
    EXPECT_EQ(e.ways[2].first, 4u);
    EXPECT_EQ(e.ways[2].last, 6u);
}

TEST(TrackGraph, SwitchSplitsIntoThreeEdges) {
    const auto r = read_opl(std::string{line_nodes} + R"(w1 v1 Trailway=rail Nn1,n2,n3,n4,n5
w2 v1 Trailway=rail,service=siding Nn3,n8,n9
)");
    const TrackGraph g = graph_of(r);
    ASSERT_EQ(g.edges.size(), 3u);
    const auto* sw = vertex(g, 3);
    ASSERT_NE(sw, nullptr);
    EXPECT_EQ(sw->kind, VertexKind::switch_);
    EXPECT_EQ(std::string{geometry::to_string(sw->kind)}, "switch");
    EXPECT_EQ(sw->edges, (std::vector<std::size_t>{0, 1, 2}));
    EXPECT_EQ(node_ids(g.edges[0]), (std::vector<std::int64_t>{1, 2, 3}));
    EXPECT_EQ(node_ids(g.edges[1]), (std::vector<std::int64_t>{3, 4, 5})) << "neighbour n4 before n8";
    EXPECT_EQ(node_ids(g.edges[2]), (std::vector<std::int64_t>{3, 8, 9}));
    EXPECT_EQ(g.edges[2].ways[0].way_id, 2);
    EXPECT_EQ(g.vertices.size(), 4u);
}

TEST(TrackGraph, SwitchNodeOfDegreeTwoSplits) {
    std::string opl = line_nodes;
    opl.replace(opl.find("n3 v1 x10.002 y48.0"), 19, "n3 v1 x10.002 y48.0 Trailway=switch");
    const auto r = read_opl(opl + "w1 v1 Trailway=rail Nn1,n2,n3,n4,n5\n");
    const TrackGraph g = graph_of(r);
    ASSERT_EQ(g.edges.size(), 2u);
    const auto* sw = vertex(g, 3);
    ASSERT_NE(sw, nullptr);
    EXPECT_EQ(sw->kind, VertexKind::join) << "a switch with its branch unmapped";
    EXPECT_EQ(node_ids(g.edges[1]), (std::vector<std::int64_t>{3, 4, 5}));
}

TEST(TrackGraph, DiamondCrossingSharingANodeGivesFourEdges) {
    const auto r = read_opl(R"(n1 v1 x10.000 y48.000
n2 v1 x10.001 y48.000
n3 v1 x10.002 y48.000
n4 v1 x10.001 y48.001
n5 v1 x10.001 y47.999
w1 v1 Trailway=rail Nn1,n2,n3
w2 v1 Trailway=tram Nn4,n2,n5
)");
    const TrackGraph g = graph_of(r);
    ASSERT_EQ(g.edges.size(), 4u);
    const auto* x = vertex(g, 2);
    ASSERT_NE(x, nullptr);
    EXPECT_EQ(x->kind, VertexKind::crossing);
    EXPECT_EQ(x->edges.size(), 4u);
    for (const auto& e : g.edges) {
        EXPECT_EQ(e.nodes.size(), 2u);
    }
}

TEST(TrackGraph, RingStartsAtItsSmallestNode) {
    const auto r = read_opl(R"(n11 v1 x10.000 y48.000
n12 v1 x10.001 y48.000
n13 v1 x10.001 y48.001
n14 v1 x10.000 y48.001
n21 v1 x10.010 y48.000
n22 v1 x10.011 y48.000
n23 v1 x10.011 y48.001
n24 v1 x10.010 y48.001
w1 v1 Trailway=rail Nn13,n14,n11,n12,n13
w2 v1 Trailway=rail Nn23,n24,n21
w3 v1 Trailway=rail Nn21,n22,n23
)");
    const TrackGraph g = graph_of(r);
    ASSERT_EQ(g.edges.size(), 2u);
    ASSERT_EQ(g.vertices.size(), 2u);
    const auto& one_way = g.edges[0];
    EXPECT_EQ(node_ids(one_way), (std::vector<std::int64_t>{11, 12, 13, 14, 11}));
    EXPECT_EQ(one_way.from, one_way.to);
    EXPECT_EQ(g.vertices[one_way.from].kind, VertexKind::join);
    EXPECT_EQ(g.vertices[one_way.from].edges, (std::vector<std::size_t>{0, 0}));
    ASSERT_EQ(one_way.ways.size(), 2u) << "the closed way is entered in its middle";
    const auto& two_ways = g.edges[1];
    EXPECT_EQ(node_ids(two_ways), (std::vector<std::int64_t>{21, 22, 23, 24, 21}));
    ASSERT_EQ(two_ways.ways.size(), 2u);
    EXPECT_EQ(two_ways.ways[0].way_id, 3);
    EXPECT_EQ(two_ways.ways[1].way_id, 2);
}

TEST(TrackGraph, ClippedWayPartsAreSeparateEdges) {
    const auto r = read_opl(std::string{line_nodes} + "w1 v1 Trailway=rail Nn1,n2,n3,n99,n5,n6,n7\n");
    ASSERT_EQ(r.tracks.size(), 1u);
    ASSERT_EQ(r.tracks[0].parts.size(), 2u);
    const TrackGraph g = graph_of(r);
    ASSERT_EQ(g.edges.size(), 2u);
    EXPECT_EQ(node_ids(g.edges[0]), (std::vector<std::int64_t>{1, 2, 3}));
    EXPECT_EQ(node_ids(g.edges[1]), (std::vector<std::int64_t>{5, 6, 7}));
    EXPECT_EQ(g.vertices.size(), 4u);
    for (const auto& v : g.vertices) {
        EXPECT_EQ(v.kind, VertexKind::end);
    }
}

TEST(TrackGraph, RoadWaysMergeAcrossSplitsToo) {
    const auto r = read_opl(std::string{line_nodes} + R"(w1 v1 Trailway=rail Nn1,n2,n3,n4,n5,n6,n7
w10 v1 Thighway=residential,maxspeed=30 Nn9,n8
w11 v1 Thighway=residential,maxspeed=50 Nn8,n4
)");
    ASSERT_EQ(r.roads.size(), 2u);
    const TrackGraph roads = geometry::build_track_graph(r.roads, {});
    EXPECT_EQ(check_conservation(roads, r.roads), "");
    ASSERT_EQ(roads.edges.size(), 1u);
    EXPECT_EQ(node_ids(roads.edges[0]), (std::vector<std::int64_t>{4, 8, 9}));
    EXPECT_TRUE(roads.edges[0].ways[0].reversed);
}

TEST(TrackGraph, OrderDoesNotDependOnInputOrder) {
    auto r = read_opl(std::string{line_nodes} + R"(w1 v1 Trailway=rail Nn1,n2,n3
w2 v1 Trailway=rail Nn3,n4,n5
w3 v1 Trailway=rail Nn3,n8,n9
w4 v1 Trailway=rail Nn5,n6,n7
)");
    const TrackGraph a = geometry::build_track_graph(r.tracks, r.features);
    std::reverse(r.tracks.begin(), r.tracks.end());
    const TrackGraph b = geometry::build_track_graph(r.tracks, r.features);
    ASSERT_EQ(a.edges.size(), b.edges.size());
    for (std::size_t i = 0; i < a.edges.size(); ++i) {
        EXPECT_EQ(node_ids(a.edges[i]), node_ids(b.edges[i]));
        ASSERT_EQ(a.edges[i].ways.size(), b.edges[i].ways.size());
        EXPECT_EQ(a.edges[i].ways[0].way_id, b.edges[i].ways[0].way_id);
    }
}

TEST(TrackGraph, SampleRouteHasThreeSwitchesAndSixEdges) {
    const auto files = sample::write_sample_route(test::scratch_dir());
    const auto r = ingest::read_osm(files.osm, {});
    ASSERT_EQ(r.tracks.size(), 14u);
    const TrackGraph g = graph_of(r);
    std::set<std::int64_t> switches, ends;
    for (const auto& v : g.vertices) {
        (v.kind == VertexKind::switch_ ? switches : ends).insert(v.node_id);
        EXPECT_TRUE(v.kind == VertexKind::switch_ || v.kind == VertexKind::end);
    }
    EXPECT_EQ(switches, (std::set<std::int64_t>{1000086, 1000089, 1000227}));
    EXPECT_EQ(ends, (std::set<std::int64_t>{1000000, 1000267, 1000289}));
    // Main line: start-switch 1, switch 1-switch 2, switch 2-switch 3, switch 3-end;
    // then the loop and the spur.
    ASSERT_EQ(g.edges.size(), 6u);
    const std::vector<std::pair<std::int64_t, std::int64_t>> ends_of{
        {1000000, 1000086}, {1000086, 1000089}, {1000086, 1000089},
        {1000089, 1000227}, {1000227, 1000267}, {1000227, 1000289}};
    const std::vector<std::vector<std::int64_t>> ways_of{{2000000, 2000001, 2000002}, {2000003}, {2000012},
                                                          {2000004, 2000005, 2000006, 2000007, 2000008, 2000009, 2000010},
                                                          {2000011}, {2000013}};
    std::set<std::int64_t> seen;
    for (std::size_t i = 0; i < g.edges.size(); ++i) {
        const auto& e = g.edges[i];
        EXPECT_EQ(e.nodes.front().id, ends_of[i].first) << "edge " << i;
        EXPECT_EQ(e.nodes.back().id, ends_of[i].second) << "edge " << i;
        std::vector<std::int64_t> ways;
        for (const auto& s : e.ways) {
            ways.push_back(s.way_id);
            EXPECT_FALSE(s.reversed);
            seen.insert(s.way_id);
        }
        EXPECT_EQ(ways, ways_of[i]) << "edge " << i;
    }
    for (const auto& w : r.tracks) {
        EXPECT_TRUE(seen.count(w.id)) << "way " << w.id;
    }
}
