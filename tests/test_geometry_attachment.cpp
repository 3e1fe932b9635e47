// Features onto the track graph: s and offset against known alignments, track
// nodes and vertices, platforms' extents and sides, and the sample route's
// features against its ground truth.
#include "railodd/geometry/feature_attachment.hpp"
#include "railodd/sample/sample_route.hpp"
#include "graph_test_support.hpp"

#include <nlohmann/json.hpp>

#include <cmath>
#include <iostream>
#include <map>

using namespace railodd;
using geometry::Attachment;
using geometry::IndexedAlignment;
using geometry::TrackGraph;
using test::polyline_alignments;

namespace {

ingest::NodeRef node_at(std::int64_t id, double x, double y) {
    ingest::NodeRef n;
    n.id = id;
    n.xy = {x, y};
    return n;
}

// A graph of one edge per polyline, each its own two end vertices; node ids
// are 100 * (edge + 1) + index.
TrackGraph graph_of(const std::vector<std::vector<ingest::XY>>& lines) {
    TrackGraph g;
    for (std::size_t e = 0; e < lines.size(); ++e) {
        geometry::GraphEdge edge;
        edge.id = e;
        for (std::size_t k = 0; k < lines[e].size(); ++k) {
            edge.nodes.push_back(node_at(100 * static_cast<std::int64_t>(e + 1) + static_cast<std::int64_t>(k),
                                         lines[e][k].x, lines[e][k].y));
        }
        edge.ways.push_back({static_cast<std::int64_t>(e + 1), 0, lines[e].size() - 1, false});
        edge.from = g.vertices.size();
        edge.to = g.vertices.size() + 1;
        g.vertices.push_back({edge.nodes.front().id, edge.nodes.front().xy, geometry::VertexKind::end, {e}});
        g.vertices.push_back({edge.nodes.back().id, edge.nodes.back().xy, geometry::VertexKind::end, {e}});
        g.edges.push_back(edge);
    }
    return g;
}

ingest::Feature point(std::int64_t id, const std::string& kind, double x, double y) {
    ingest::Feature f;
    f.osm_type = "node";
    f.id = id;
    f.kind = kind;
    f.position = node_at(id, x, y);
    return f;
}

ingest::Feature platform(std::int64_t id, const std::vector<ingest::XY>& outline) {
    ingest::Feature f;
    f.osm_type = "way";
    f.id = id;
    f.kind = "platform";
    ingest::XY c{0, 0};
    for (std::size_t i = 0; i < outline.size(); ++i) {
        f.outline.push_back(node_at(1000 + static_cast<std::int64_t>(i), outline[i].x, outline[i].y));
        c.x += outline[i].x / static_cast<double>(outline.size());
        c.y += outline[i].y / static_cast<double>(outline.size());
    }
    f.position.xy = c;
    return f;
}

const geometry::AttachedFeature* find(const Attachment& a, std::size_t feature) {
    for (const auto& x : a.attached) {
        if (x.feature == feature) {
            return &x;
        }
    }
    return nullptr;
}

// A straight edge along the x axis from 0 to 200 m, nodes every 100 m.
const std::vector<ingest::XY> straight{{0, 0}, {100, 0}, {200, 0}};

} // namespace

TEST(Attachment, PointsOnAStraightEdge) {
    const TrackGraph g = graph_of({straight});
    const std::vector<IndexedAlignment> al{IndexedAlignment({{0, 0, 0, 0}, {geometry::make_line(200)}})};
    const std::vector<ingest::Feature> f{point(1, "signal", 50, 3), point(2, "milestone", 120, -4),
                                         point(3, "signal", 50, 80), point(4, "station", 50, 80)};
    const Attachment a = geometry::attach_features(g, al, f, 50.0, 500.0);
    ASSERT_EQ(a.attached.size(), 3u);
    ASSERT_EQ(a.unattached.size(), 1u);
    EXPECT_EQ(a.unattached[0].feature, 2u);
    EXPECT_NE(a.unattached[0].reason.find("80.0 m"), std::string::npos) << a.unattached[0].reason;
    const auto* left = find(a, 0);
    ASSERT_NE(left, nullptr);
    EXPECT_EQ(left->edge, 0u);
    EXPECT_NEAR(left->s, 50.0, 1e-9);
    EXPECT_NEAR(left->offset, 3.0, 1e-9);
    EXPECT_NEAR(left->distance, 3.0, 1e-9);
    EXPECT_EQ(left->s_start, left->s);
    EXPECT_EQ(left->s_end, left->s);
    EXPECT_FALSE(left->vertex);
    EXPECT_NEAR(find(a, 1)->s, 120.0, 1e-9);
    EXPECT_NEAR(find(a, 1)->offset, -4.0, 1e-9);
    ASSERT_NE(find(a, 3), nullptr) << "stations have their own, wider limit";
    EXPECT_NEAR(find(a, 3)->offset, 80.0, 1e-9);
    EXPECT_EQ(geometry::attach_features(g, al, f, 50.0).unattached.size(), 2u);
}

TEST(Attachment, PointsBesideACurve) {
    // An arc of radius 500 m turning left from the origin, mapped every 10 m.
    constexpr double radius = 500.0;
    std::vector<ingest::XY> line;
    for (int i = 0; i <= 30; ++i) {
        const double phi = 10.0 * i / radius;
        line.push_back({radius * std::sin(phi), radius - radius * std::cos(phi)});
    }
    const TrackGraph g = graph_of({line});
    const std::vector<IndexedAlignment> al{IndexedAlignment({{0, 0, 0, 0}, {geometry::make_arc(300, 1 / radius)}})};
    std::vector<ingest::Feature> f;
    for (const double s : {20.0, 155.0, 290.0}) {
        for (const double offset : {-6.0, 4.0}) {
            const double phi = s / radius;
            const double r = radius - offset; // the centre is on the left
            f.push_back(point(static_cast<std::int64_t>(s + offset), "signal", r * std::sin(phi), radius - r * std::cos(phi)));
        }
    }
    const Attachment a = geometry::attach_features(g, al, f, 50.0);
    ASSERT_EQ(a.attached.size(), f.size());
    for (std::size_t i = 0; i < f.size(); ++i) {
        const double s = i < 2 ? 20.0 : i < 4 ? 155.0 : 290.0;
        EXPECT_NEAR(a.attached[i].s, s, 1e-6) << i;
        EXPECT_NEAR(a.attached[i].offset, i % 2 ? 4.0 : -6.0, 1e-6) << i;
    }
}

TEST(Attachment, TrackNodesAttachByIdAndVerticesAreNamed) {
    // Two edges meeting end to start at node 102/200 would share it in a real
    // graph; here node 102 is the end vertex of edge 0.
    const TrackGraph g = graph_of({straight, {{0, 4.5}, {200, 4.5}}});
    std::vector<ingest::Feature> f{point(101, "signal", 100, 0.0), point(102, "buffer_stop", 200, 0)};
    f[0].on_track = f[1].on_track = true;
    f.push_back(point(7, "signal", 150, 3.0)); // nearer the other, parallel edge
    const Attachment a = geometry::attach_features(g, polyline_alignments(g), f, 50.0);
    ASSERT_EQ(a.attached.size(), 3u);
    EXPECT_EQ(a.attached[0].edge, 0u);
    EXPECT_NEAR(a.attached[0].s, 100.0, 1e-6);
    EXPECT_FALSE(a.attached[0].vertex);
    EXPECT_EQ(a.attached[1].edge, 0u);
    EXPECT_NEAR(a.attached[1].s, 200.0, 1e-6);
    ASSERT_TRUE(a.attached[1].vertex);
    EXPECT_EQ(*a.attached[1].vertex, g.edges[0].to);
    EXPECT_EQ(a.attached[2].edge, 1u);
    EXPECT_NEAR(a.attached[2].offset, -1.5, 1e-6);
}

TEST(Attachment, PlatformsGetSideAndExtent) {
    const TrackGraph g = graph_of({straight});
    const std::vector<ingest::Feature> f{platform(1, {{30, 3.5}, {80, 3.5}, {80, 8}, {30, 8}, {30, 3.5}}),
                                         platform(2, {{140, -2.5}, {110, -2.6}, {170, -2.4}})};
    const Attachment a = geometry::attach_features(g, polyline_alignments(g), f, 50.0);
    ASSERT_EQ(a.attached.size(), 2u);
    EXPECT_GT(a.attached[0].offset, 0.0) << "left of the track";
    EXPECT_NEAR(a.attached[0].s_start, 30.0, 1e-6);
    EXPECT_NEAR(a.attached[0].s_end, 80.0, 1e-6);
    EXPECT_LT(a.attached[1].offset, 0.0) << "right of the track";
    EXPECT_NEAR(a.attached[1].s_start, 110.0, 1e-6);
    EXPECT_NEAR(a.attached[1].s_end, 170.0, 1e-6);
    EXPECT_NEAR(a.attached[1].s, 140.0, 1e-6);
}

TEST(Attachment, FarFeatureAndMismatchedAlignments) {
    const TrackGraph g = graph_of({straight});
    const Attachment a = geometry::attach_features(g, polyline_alignments(g), {point(1, "signal", 100, -60)}, 50.0);
    EXPECT_TRUE(a.attached.empty());
    ASSERT_EQ(a.unattached.size(), 1u);
    EXPECT_NE(a.unattached[0].reason.find("signal is 60.0 m from the nearest track"), std::string::npos)
        << a.unattached[0].reason;
    EXPECT_THROW(geometry::attach_features(g, {}, {}, 50.0), std::invalid_argument);
    const Attachment none = geometry::attach_features(TrackGraph{}, {}, {point(1, "signal", 0, 0)}, 50.0);
    ASSERT_EQ(none.unattached.size(), 1u);
}

TEST(Attachment, SampleRouteFeaturesMatchTheTruth) {
    const auto files = sample::write_sample_route(test::scratch_dir());
    const auto input = ingest::read_osm(files.osm, {});
    const nlohmann::json truth = nlohmann::json::parse(test::read_file(files.truth));
    const TrackGraph g = geometry::build_track_graph(input.tracks, input.features);
    ASSERT_EQ(g.edges.size(), 6u);
    const Attachment a = geometry::attach_features(g, polyline_alignments(g), input.features, 50.0, 500.0);
    EXPECT_TRUE(a.unattached.empty()) << a.unattached.size() << " unattached, first: "
                                      << (a.unattached.empty() ? "" : a.unattached[0].reason);

    // Where each edge starts on its truth track (edges as in the track graph test).
    const std::vector<std::pair<std::string, double>> edge_start{
        {"main", 0.0}, {"main", 3020.0}, {"loop", 0.0}, {"main", 3566.6935581407715}, {"main", 7700.0}, {"spur", 0.0}};
    std::map<std::int64_t, std::size_t> feature_of;
    for (std::size_t i = 0; i < input.features.size(); ++i) {
        feature_of[input.features[i].id] = i;
    }
    // Truth positions are in the truth's own frame: through lon/lat into ours.
    const nlohmann::json& frame = truth["frame"];
    const ingest::LocalProjection truth_frame({frame["origin_lon"], frame["origin_lat"]});
    ASSERT_EQ(truth_frame.proj_string(), frame["proj"].get<std::string>());

    int checked = 0;
    double worst_s = 0.0, worst_offset = 0.0;
    for (const char* list : {"switches", "signals", "level_crossings", "stations", "milestones", "buffer_stops"}) {
        for (const auto& t : truth["features"][list]) {
            const std::int64_t id = t["id"];
            ASSERT_TRUE(feature_of.count(id)) << list << " " << id;
            const auto& f = input.features[feature_of[id]];
            const ingest::XY ours = input.projection.forward(truth_frame.inverse({t["x"], t["y"]}));
            EXPECT_LT(std::hypot(ours.x - f.position.xy.x, ours.y - f.position.xy.y), 1.5) << "mapping noise only";
            const auto* at = find(a, feature_of[id]);
            ASSERT_NE(at, nullptr) << list << " " << id;
            const auto& [track, start] = edge_start[at->edge];
            EXPECT_EQ(track, t["track"].get<std::string>()) << list << " " << id;
            EXPECT_NEAR(at->s + start, t["s"].get<double>(), 4.0) << list << " " << id << " on edge " << at->edge;
            EXPECT_NEAR(at->offset, t["offset"].get<double>(), 1.5) << list << " " << id;
            EXPECT_EQ(at->vertex.has_value(), std::string{list} == "switches" || std::string{list} == "buffer_stops")
                << list << " " << id;
            worst_s = std::max(worst_s, std::abs(at->s + start - t["s"].get<double>()));
            worst_offset = std::max(worst_offset, std::abs(at->offset - t["offset"].get<double>()));
            ++checked;
        }
    }
    std::cout << checked << " point features: largest error " << worst_s << " m in s, " << worst_offset
              << " m in offset (polyline stand-in for the fitted alignment)\n";
    EXPECT_EQ(checked, 3 + 4 + 1 + 2 + 9 + 1);
    for (const auto& t : truth["features"]["platforms"]) {
        const auto* at = find(a, feature_of.at(t["way"]));
        ASSERT_NE(at, nullptr);
        const double start = edge_start[at->edge].second;
        EXPECT_NEAR(at->s_start + start, t["s_from"].get<double>(), 4.0) << t["name"];
        EXPECT_NEAR(at->s_end + start, t["s_to"].get<double>(), 4.0) << t["name"];
        EXPECT_EQ(at->offset > 0, t["offset"].get<double>() > 0) << t["name"];
    }
}
