// The track graph and crossings on the real extracts in ../shared/data/osm:
// every segment conserved, switches found, level crossings linked, features
// attached.
#include "railodd/geometry/crossings.hpp"
#include "railodd/geometry/feature_attachment.hpp"
#include "railodd/geometry/track_graph.hpp"
#include "graph_test_support.hpp"

#include <algorithm>
#include <iostream>
#include <map>
#include <set>

using namespace railodd;
using geometry::VertexKind;

namespace {

ingest::IngestResult read_extract(const std::string& name, bool roads) {
    ingest::IngestOptions o;
    if (!roads) {
        o.road_corridor_m = 0;
    }
    return ingest::read_osm(test::shared_data() / "osm" / name, o);
}

} // namespace

TEST(GraphShared, EverySegmentIsInExactlyOneEdgeOnEveryExtract) {
    RAILODD_REQUIRE_SHARED_DATA();
    std::set<std::filesystem::path> files;
    for (const auto& entry : std::filesystem::directory_iterator(test::shared_data() / "osm")) {
        files.insert(entry.path());
    }
    ASSERT_FALSE(files.empty());
    for (const auto& file : files) {
        const auto r = read_extract(file.filename().string(), false);
        const auto g = geometry::build_track_graph(r.tracks, r.features);
        EXPECT_EQ(test::edge_segments(g), test::way_segments(r.tracks)) << file;
        EXPECT_EQ(test::check_conservation(g, r.tracks), "") << file;
        std::map<std::string, int> kinds;
        for (const auto& v : g.vertices) {
            ++kinds[geometry::to_string(v.kind)];
        }
        std::cout << file.filename().string() << ": " << r.tracks.size() << " ways, " << test::way_segments(r.tracks)
                  << " segments -> " << g.edges.size() << " edges, " << g.vertices.size() << " vertices (";
        for (const auto& [k, n] : kinds) {
            std::cout << ' ' << k << ' ' << n;
        }
        std::cout << " )\n";
    }
}

TEST(GraphShared, CologneSwitchFeaturesBecomeSwitchVertices) {
    RAILODD_REQUIRE_SHARED_DATA();
    const auto r = read_extract("orr_cologne-railway.osm.pbf", false);
    const auto g = geometry::build_track_graph(r.tracks, r.features);
    std::map<std::int64_t, VertexKind> vertex_kind;
    std::size_t switch_vertices = 0;
    for (const auto& v : g.vertices) {
        vertex_kind[v.node_id] = v.kind;
        switch_vertices += v.kind == VertexKind::switch_;
    }
    std::size_t features = 0;
    std::map<std::string, std::size_t> as;
    for (const auto& f : r.features) {
        if (f.kind != "switch" || !f.on_track) {
            continue;
        }
        ++features;
        const auto it = vertex_kind.find(f.id);
        ++as[it == vertex_kind.end() ? "no vertex" : geometry::to_string(it->second)];
    }
    std::cout << "cologne: " << features << " railway=switch nodes on track (data README: 3657), "
              << switch_vertices << " switch vertices; the switch nodes became:";
    for (const auto& [k, n] : as) {
        std::cout << ' ' << k << ' ' << n;
    }
    std::cout << '\n';
    EXPECT_GT(features, 3500u);
    EXPECT_EQ(as.count("no vertex"), 0u) << "a tagged switch always splits";
    // Nearly all mapped switches have their three legs; a few are at the
    // extract's edge or are slips (degree 4).
    EXPECT_GT(static_cast<double>(as["switch"]), 0.95 * static_cast<double>(features));
    EXPECT_GE(switch_vertices, as["switch"]);
}

TEST(CrossingsShared, LevelCrossingNodesOfRoadsAreFound) {
    RAILODD_REQUIRE_SHARED_DATA();
    for (const std::string name : {"valhalla_munchen.osm.pbf", "gh_harsdorf.osm.pbf"}) {
        const auto r = read_extract(name, true);
        const auto g = geometry::build_track_graph(r.tracks, r.features);
        const auto c = geometry::find_crossings(g, r.tracks, r.roads, r.features);
        std::set<std::int64_t> road_nodes;
        for (const auto& w : r.roads) {
            for (const auto& p : w.parts) {
                for (const auto& n : p) {
                    road_nodes.insert(n.id);
                }
            }
        }
        std::set<std::int64_t> level_crossings_on_roads;
        for (const auto& f : r.features) {
            if (f.kind == "level_crossing" && f.osm_type == "node" && road_nodes.count(f.id)) {
                level_crossings_on_roads.insert(f.id);
            }
        }
        std::size_t at_grade = 0, at_grade_linked = 0, shared = 0, separated = 0;
        for (const auto& x : c.road_rail) {
            shared += x.shared_node != 0;
            separated += x.grade_separated;
            at_grade += !x.grade_separated;
            at_grade_linked += !x.grade_separated && level_crossings_on_roads.count(x.level_crossing_node);
        }
        std::cout << name << ": " << r.roads.size() << " roads; " << c.road_rail.size() << " road-rail crossings ("
                  << shared << " at shared nodes, " << separated << " grade-separated, " << at_grade << " at grade, "
                  << at_grade_linked << " at grade with a level crossing node); " << level_crossings_on_roads.size()
                  << " railway=level_crossing nodes on roads; " << c.tracks.size() << " track-track crossings\n";
        EXPECT_GE(at_grade_linked, level_crossings_on_roads.size()) << name;
        EXPECT_GT(level_crossings_on_roads.size(), 0u) << name;
    }
}

TEST(CrossingsShared, TrackCrossingsAreMostlyDiamondsOrBridges) {
    RAILODD_REQUIRE_SHARED_DATA();
    for (const std::string name : {"orr_cologne-railway.osm.pbf", "valhalla_munchen.osm.pbf", "orr_vde8.2-rail.osm.pbf"}) {
        const auto r = read_extract(name, false);
        const auto g = geometry::build_track_graph(r.tracks, r.features);
        const auto c = geometry::find_crossings(g, r.tracks, {}, r.features);
        std::size_t crossing_vertices = 0, shared = 0, separated = 0, flat_geometric = 0;
        for (const auto& v : g.vertices) {
            crossing_vertices += v.kind == VertexKind::crossing;
        }
        for (const auto& x : c.tracks) {
            shared += x.shared_node != 0;
            separated += x.grade_separated;
            if (x.shared_node == 0 && !x.grade_separated) {
                ++flat_geometric;
                std::cout << "  at grade without a shared node: ways " << g.edges[x.edge_a].ways.front().way_id << ", "
                          << g.edges[x.edge_b].ways.front().way_id << " (edges " << x.edge_a << ", " << x.edge_b << ") at ("
                          << x.point.x << ", " << x.point.y << "), " << x.angle_deg << " deg\n";
            }
        }
        std::cout << name << ": " << crossing_vertices << " crossing vertices; " << c.tracks.size()
                  << " track-track crossings (" << shared << " at shared nodes, " << separated
                  << " grade-separated, " << flat_geometric << " at grade without a shared node)\n";
        EXPECT_LE(shared, crossing_vertices);
        EXPECT_GT(shared, crossing_vertices / 2) << "most crossing vertices are diamonds";
    }
}

TEST(AttachmentShared, FeaturesKeptByIngestAllAttach) {
    RAILODD_REQUIRE_SHARED_DATA();
    for (const std::string name : {"orr_cologne-railway.osm.pbf", "valhalla_munchen.osm.pbf", "gh_lauf-200115.osm.pbf"}) {
        const auto r = read_extract(name, false);
        const auto g = geometry::build_track_graph(r.tracks, r.features);
        // Ingest keeps features within 50 m (stations 500 m) of a track polyline.
        const auto a = geometry::attach_features(g, test::polyline_alignments(g), r.features, 50.0, 500.0);
        std::size_t on_vertex = 0, by_node = 0;
        for (const auto& x : a.attached) {
            on_vertex += x.vertex.has_value();
            by_node += r.features[x.feature].on_track;
        }
        std::cout << name << ": " << r.features.size() << " features, " << a.attached.size() << " attached ("
                  << by_node << " track nodes, " << on_vertex << " at vertices), " << a.unattached.size()
                  << " unattached\n";
        for (std::size_t i = 0; i < std::min<std::size_t>(a.unattached.size(), 5); ++i) {
            std::cout << "  " << r.features[a.unattached[i].feature].id << ": " << a.unattached[i].reason << '\n';
        }
        EXPECT_EQ(a.attached.size() + a.unattached.size(), r.features.size());
        EXPECT_LE(a.unattached.size(), r.features.size() / 100) << name;
    }
}
