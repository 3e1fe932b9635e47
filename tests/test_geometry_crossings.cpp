// Road-rail and track-track crossings on tiny inline OPL inputs and on the
// sample route: shared nodes, geometric crossings, grade separation.
#include "railodd/geometry/crossings.hpp"
#include "railodd/sample/sample_route.hpp"
#include "graph_test_support.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

using namespace railodd;
using geometry::Crossings;
using railodd::test::read_opl;

namespace {

// Track w1 runs east along 48.0 N through n1..n5, about 74 m apart.
const char* const track_opl = R"(n1 v1 x10.000 y48.0
n2 v1 x10.001 y48.0
n3 v1 x10.002 y48.0
n4 v1 x10.003 y48.0
n5 v1 x10.004 y48.0
w1 v1 Trailway=rail Nn1,n2,n3,n4,n5
)";

struct Result {
    ingest::IngestResult input;
    geometry::TrackGraph graph;
    Crossings crossings;
};

Result crossings_of(const std::string& opl) {
    Result r;
    r.input = read_opl(opl);
    r.graph = geometry::build_track_graph(r.input.tracks, r.input.features);
    r.crossings = geometry::find_crossings(r.graph, r.input.tracks, r.input.roads, r.input.features);
    return r;
}

const ingest::NodeRef& node(const std::vector<ingest::Way>& ways, std::int64_t id) {
    for (const auto& w : ways) {
        for (const auto& p : w.parts) {
            for (const auto& n : p) {
                if (n.id == id) {
                    return n;
                }
            }
        }
    }
    throw std::runtime_error("no node " + std::to_string(id));
}

// Intersection of lines p1-p2 and q1-q2.
ingest::XY intersect(ingest::XY p1, ingest::XY p2, ingest::XY q1, ingest::XY q2) {
    const double d = (p2.x - p1.x) * (q2.y - q1.y) - (p2.y - p1.y) * (q2.x - q1.x);
    const double t = ((q1.x - p1.x) * (q2.y - q1.y) - (q1.y - p1.y) * (q2.x - q1.x)) / d;
    return {p1.x + t * (p2.x - p1.x), p1.y + t * (p2.y - p1.y)};
}

} // namespace

TEST(Crossings, LevelCrossingAtSharedNode) {
    std::string opl = track_opl;
    opl.replace(opl.find("n3 v1 x10.002 y48.0"), 19, "n3 v1 x10.002 y48.0 Trailway=level_crossing");
    const Result r = crossings_of(opl + R"(n20 v1 x10.002 y48.001
n21 v1 x10.002 y47.999
w10 v1 Thighway=secondary Nn20,n3
w11 v1 Thighway=secondary Nn3,n21
)");
    ASSERT_EQ(r.crossings.road_rail.size(), 1u) << "a road split at the crossing is one crossing";
    const auto& c = r.crossings.road_rail[0];
    EXPECT_EQ(c.edge, 0u);
    EXPECT_EQ(c.road_way_id, 10);
    EXPECT_EQ(c.shared_node, 3);
    EXPECT_EQ(c.level_crossing_node, 3);
    EXPECT_FALSE(c.grade_separated);
    EXPECT_NEAR(c.angle_deg, 90.0, 0.5);
    EXPECT_NEAR(c.s, 149.2, 0.3);
    EXPECT_TRUE(r.crossings.tracks.empty());
}

TEST(Crossings, RoadTouchingTheTrackCrossesOnlyAtATaggedNode) {
    const std::string roads = R"(n20 v1 x10.002 y48.001
w10 v1 Thighway=service Nn20,n3
)";
    EXPECT_TRUE(crossings_of(track_opl + roads).crossings.road_rail.empty()) << "a road ending at the track";
    std::string opl = track_opl;
    opl.replace(opl.find("n3 v1 x10.002 y48.0"), 19, "n3 v1 x10.002 y48.0 Trailway=crossing");
    const Result r = crossings_of(opl + roads);
    ASSERT_EQ(r.crossings.road_rail.size(), 1u) << "the node says the road goes on";
    EXPECT_EQ(r.crossings.road_rail[0].level_crossing_node, 3);
}

TEST(Crossings, RoadCrossingWithoutSharedNodeIsFoundGeometrically) {
    const Result r = crossings_of(std::string{track_opl} + R"(n20 v1 x10.0024 y48.001
n21 v1 x10.0034 y47.999
n30 v1 x10.00291 y48.00003 Trailway=level_crossing
w10 v1 Thighway=tertiary Nn20,n21
)");
    ASSERT_EQ(r.crossings.road_rail.size(), 1u);
    const auto& c = r.crossings.road_rail[0];
    const ingest::XY expect = intersect(node(r.input.tracks, 3).xy, node(r.input.tracks, 4).xy,
                                        node(r.input.roads, 20).xy, node(r.input.roads, 21).xy);
    EXPECT_NEAR(c.point.x, expect.x, 1e-6);
    EXPECT_NEAR(c.point.y, expect.y, 1e-6);
    EXPECT_EQ(c.shared_node, 0);
    EXPECT_EQ(c.road_way_id, 10);
    EXPECT_EQ(c.level_crossing_node, 30) << "a level crossing node 3.4 m away";
    EXPECT_FALSE(c.grade_separated);
    const ingest::XY n1 = node(r.input.tracks, 1).xy;
    EXPECT_NEAR(c.s, std::hypot(expect.x - n1.x, expect.y - n1.y), 1e-3);
    EXPECT_GT(c.angle_deg, 45.0);
    EXPECT_LT(c.angle_deg, 90.0);
}

TEST(Crossings, BridgeOrTunnelOrLayerSeparatesGrades) {
    const std::string road = R"(n20 v1 x10.0025 y48.001
n21 v1 x10.0025 y47.999
)";
    const auto separated = [&](const std::string& track_tags, const std::string& road_tags) {
        std::string opl = track_opl;
        opl.replace(opl.find("Trailway=rail"), 13, "Trailway=rail" + track_tags);
        const Result r = crossings_of(opl + road + "w10 v1 Thighway=primary" + road_tags + " Nn20,n21\n");
        EXPECT_EQ(r.crossings.road_rail.size(), 1u);
        return !r.crossings.road_rail.empty() && r.crossings.road_rail[0].grade_separated;
    };
    EXPECT_FALSE(separated("", ""));
    EXPECT_TRUE(separated("", ",bridge=yes,layer=1"));
    EXPECT_TRUE(separated(",tunnel=yes", ""));
    EXPECT_TRUE(separated("", ",layer=-1"));
    EXPECT_FALSE(separated(",bridge=no", ",layer=0"));
    EXPECT_TRUE(separated(",bridge=viaduct", ",bridge=no"));
    EXPECT_TRUE(separated(",tunnel=yes", ",bridge=yes"));
    EXPECT_FALSE(separated(",bridge=yes,layer=1", ",bridge=yes,layer=1")) << "a tram on the road's bridge deck";
}

TEST(Crossings, ParallelRoadDoesNotCross) {
    const Result r = crossings_of(std::string{track_opl} + R"(n20 v1 x10.000 y48.0002
n21 v1 x10.004 y48.0002
w10 v1 Thighway=residential Nn20,n21
)");
    ASSERT_EQ(r.input.roads.size(), 1u);
    EXPECT_TRUE(r.crossings.road_rail.empty());
}

TEST(Crossings, DiamondCrossingAndTrackOnABridge) {
    const Result r = crossings_of(std::string{track_opl} + R"(n10 v1 x10.001 y48.001
n11 v1 x10.001 y47.999
n12 v1 x10.0035 y48.001
n13 v1 x10.0035 y47.999
w2 v1 Trailway=tram Nn10,n2,n11
w3 v1 Trailway=rail,bridge=yes,layer=1 Nn12,n13
)");
    ASSERT_EQ(r.graph.edges.size(), 5u);
    ASSERT_EQ(r.crossings.tracks.size(), 2u);
    const auto diamond = std::find_if(r.crossings.tracks.begin(), r.crossings.tracks.end(),
                                      [](const auto& c) { return c.shared_node != 0; });
    ASSERT_NE(diamond, r.crossings.tracks.end());
    EXPECT_EQ(diamond->shared_node, 2);
    EXPECT_FALSE(diamond->grade_separated);
    EXPECT_NEAR(diamond->angle_deg, 90.0, 0.5);
    EXPECT_LT(diamond->edge_a, diamond->edge_b);
    const auto bridge = std::find_if(r.crossings.tracks.begin(), r.crossings.tracks.end(),
                                     [](const auto& c) { return c.shared_node == 0; });
    ASSERT_NE(bridge, r.crossings.tracks.end());
    EXPECT_TRUE(bridge->grade_separated);
    EXPECT_NEAR(bridge->angle_deg, 90.0, 0.5);
    const auto& on_bridge = r.graph.edges[bridge->edge_b];
    EXPECT_EQ(on_bridge.ways[0].way_id, 3);
    EXPECT_NEAR(bridge->s_b, 111.2, 0.5) << "halfway along the bridge";
}

TEST(Crossings, SampleRouteLevelCrossingAndRoadUnderTheBridge) {
    const auto files = sample::write_sample_route(test::scratch_dir());
    const auto input = ingest::read_osm(files.osm, {});
    const auto graph = geometry::build_track_graph(input.tracks, input.features);
    const Crossings c = geometry::find_crossings(graph, input.tracks, input.roads, input.features);
    EXPECT_TRUE(c.tracks.empty()) << "the loop's noisy polyline crosses the main line's near switch 2";
    ASSERT_EQ(c.road_rail.size(), 2u);
    const auto& mill = c.road_rail[0];
    EXPECT_EQ(mill.road_way_id, 2000017);
    EXPECT_EQ(mill.shared_node, 1000042);
    EXPECT_EQ(mill.level_crossing_node, 1000042);
    EXPECT_FALSE(mill.grade_separated);
    EXPECT_NEAR(mill.angle_deg, 80.0, 5.0);
    EXPECT_EQ(graph.edges[mill.edge].nodes.front().id, 1000000);
    EXPECT_NEAR(mill.s, 1650.0, 5.0);
    const auto& valley = c.road_rail[1];
    EXPECT_EQ(valley.road_way_id, 2000018);
    EXPECT_EQ(valley.shared_node, 0);
    EXPECT_EQ(valley.level_crossing_node, 0);
    EXPECT_TRUE(valley.grade_separated);
    EXPECT_NEAR(valley.angle_deg, 75.0, 5.0);
    EXPECT_EQ(graph.edges[valley.edge].nodes.front().id, 1000089);
    EXPECT_NEAR(valley.s, 5425.0 - 3566.69, 10.0);
}

TEST(Crossings, TurnoutLegsCrossingNearTheSwitchAreNoCrossing) {
    // The branch leaves n3 about 0.4 m south of the main line, crosses it 37 m
    // later and only then turns away north: a sloppily drawn turnout.
    const Result sloppy = crossings_of(std::string{track_opl} + R"(n40 v1 x10.0022 y47.999996
n41 v1 x10.0026 y48.00001
n42 v1 x10.0032 y48.0006
w2 v1 Trailway=rail Nn3,n40,n41,n42
)");
    EXPECT_TRUE(sloppy.crossings.tracks.empty());
    // A branch that spreads 40 m south before crossing the main line on a
    // bridge (a flying junction) does cross it.
    const Result flying = crossings_of(std::string{track_opl} + R"(n40 v1 x10.0025 y47.9996
n41 v1 x10.0035 y48.0010
w2 v1 Trailway=rail,bridge=yes,layer=1 Nn3,n40,n41
)");
    ASSERT_EQ(flying.crossings.tracks.size(), 1u);
    EXPECT_TRUE(flying.crossings.tracks[0].grade_separated);
}
