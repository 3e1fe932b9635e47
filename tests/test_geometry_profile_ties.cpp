// Heights meet where tracks meet: two tracks whose own elevation data
// disagree at their common vertex are bent to one height and one grade there;
// a track without data takes its height from the network, not 0 (a 447 m
// step between linked roads in every reader).
#include "railodd/geometry/profiles.hpp"
#include "railodd/geometry/track_fit.hpp"
#include "railodd/ingest/osm_reader.hpp"
#include "test_support.hpp"

#include <cmath>
#include <string>

using namespace railodd;
using namespace railodd::geometry;

namespace {

// Two ways in line, 1.5 km each, meeting at node 100, where a short spur
// without data leaves northwards (so node 100 is a vertex); `ele_a` / `ele_b`
// tag every node of each way (empty: no tag).
std::string two_ways(const std::string& ele_a, const std::string& ele_b) {
    std::string osm = "<?xml version=\"1.0\"?>\n<osm version=\"0.6\">\n";
    auto node = [&](int id, double lat, double lon, const std::string& ele) {
        osm += "<node id=\"" + std::to_string(id) + "\" version=\"1\" lat=\"" + std::to_string(lat) + "\" lon=\"" +
               std::to_string(lon) + "\">" + (ele.empty() ? "" : "<tag k=\"ele\" v=\"" + ele + "\"/>") + "</node>\n";
    };
    for (int i = 1; i <= 199; ++i) {
        node(i, 48.0, 10.0 + i * 2e-4, i < 100 ? ele_a : i > 100 ? ele_b : "");
    }
    for (int i = 1; i <= 10; ++i) {
        node(1000 + i, 48.0 + i * 1e-4, 10.02 - i * 1e-4, "");
    }
    auto way = [&](int id, const std::vector<int>& refs) {
        osm += "<way id=\"" + std::to_string(id) + "\" version=\"1\">";
        for (const int r : refs) {
            osm += "<nd ref=\"" + std::to_string(r) + "\"/>";
        }
        osm += "<tag k=\"railway\" v=\"rail\"/></way>\n";
    };
    std::vector<int> a, b, spur{100};
    for (int i = 1; i <= 199; ++i) {
        (i <= 100 ? a : b).push_back(i);
    }
    b.insert(b.begin(), 100);
    for (int i = 1; i <= 10; ++i) {
        spur.push_back(1000 + i);
    }
    way(1, a);
    way(2, b);
    way(3, spur);
    return osm + "</osm>\n";
}

struct Ends {
    double z_a, z_b, g_a, g_b; // height and grade (along the direction of travel a -> b) at the common vertex
    std::vector<VerticalProfile> profiles;
    std::vector<double> lengths;
};

Ends profiles_of(const std::string& osm) {
    const auto dir = test::scratch_dir();
    const ingest::IngestResult in = ingest::read_osm(test::write_file(dir / "two.osm", osm), {});
    const TrackGraph g = build_track_graph(in.tracks, in.features);
    const FittedNetwork net = fit_track_graph(g, FitOptions{});
    Ends e;
    e.profiles = fit_profiles(g, net, in.tracks, in.projection, nullptr);
    EXPECT_EQ(g.edges.size(), 3u);
    for (const FittedEdge& f : net.edges) {
        e.lengths.push_back(length(f.alignment));
    }
    // The edge holding way 1 is "a", way 2's is "b"; at their common vertex
    // (node 100) a train runs from a into b.
    const auto holds = [&](std::size_t e, std::int64_t way) { return g.edges[e].ways.front().way_id == way; };
    std::size_t a = 0, b = 0;
    for (std::size_t i = 0; i < g.edges.size(); ++i) {
        a = holds(i, 1) ? i : a;
        b = holds(i, 2) ? i : b;
    }
    const std::size_t v = g.edges[a].from == g.edges[b].from || g.edges[a].from == g.edges[b].to ? g.edges[a].from
                                                                                              : g.edges[a].to;
    const auto at_vertex = [&](std::size_t i, double& z, double& g_out) {
        const Alignment& al = net.edges[i].alignment;
        const double l = length(al);
        const bool start = (net.edges[i].reversed ? g.edges[i].to : g.edges[i].from) == v;
        const double s = start ? 1e-3 : l - 1e-3;
        const auto& p = e.profiles[i].polys;
        z = elevation_at(p, start ? 0.0 : l);
        const double slope = (elevation_at(p, s + 1e-4) - elevation_at(p, s - 1e-4)) / 2e-4;
        g_out = start ? slope : -slope;
    };
    at_vertex(a, e.z_a, e.g_a);
    at_vertex(b, e.z_b, e.g_b);
    e.g_b = -e.g_b; // along the direction of travel a -> b
    return e;
}

} // namespace

TEST(ProfileTies, AWayWithoutEleTakesItsNeighboursHeight) {
    const Ends e = profiles_of(two_ways("447", ""));
    EXPECT_NEAR(e.z_a, 447.0, 1e-6);
    EXPECT_NEAR(e.z_b, e.z_a, 1e-9);
    int interpolated = 0;
    for (const auto& p : e.profiles) {
        interpolated += p.source == ElevationSource::interpolated ? 1 : 0;
        EXPECT_NEAR(elevation_at(p.polys, 50.0), 447.0, 1e-6) << "one datum: the whole network at its height";
        EXPECT_LT(p.max_gradient_permille, 1e-6);
    }
    EXPECT_EQ(interpolated, 2) << "way 2 and the spur";
}

TEST(ProfileTies, DisagreeingTracksMeetInHeightAndGrade) {
    const Ends e = profiles_of(two_ways("440", "452"));
    EXPECT_NEAR(e.z_a, 446.0, 1e-6) << "the mean of the two ends";
    EXPECT_NEAR(e.z_b, e.z_a, 1e-9);
    EXPECT_NEAR(e.g_a, e.g_b, 1e-6);
    // The data still rule away from the vertex.
    double lo = 1e300, hi = -1e300;
    for (std::size_t i = 0; i < e.profiles.size(); ++i) {
        for (int k = 0; k <= 100; ++k) { // both ends exactly: a sum of steps can stop short of the last
            const double s = e.lengths[i] * k / 100.0;
            lo = std::min(lo, elevation_at(e.profiles[i].polys, s));
            hi = std::max(hi, elevation_at(e.profiles[i].polys, s));
        }
    }
    EXPECT_NEAR(lo, 440.0, 1e-3);
    EXPECT_NEAR(hi, 452.0, 1e-3);
}

TEST(ProfileTies, NoDataAnywhereStaysFlatAndSaysSo) {
    const Ends e = profiles_of(two_ways("", ""));
    for (const auto& p : e.profiles) {
        EXPECT_EQ(p.source, ElevationSource::flat);
        EXPECT_EQ(elevation_at(p.polys, 100.0), 0.0);
    }
}
