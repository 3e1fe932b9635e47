// Track fitting on real extracts: every mapped track covered, mapped nodes
// close to the fitted line, every branch link continuous (G2), corner chains
// included.
#include "railodd/geometry/track_fit.hpp"
#include "railodd/ingest/osm_reader.hpp"
#include "test_support.hpp"

#include <algorithm>
#include <iostream>

using namespace railodd;
using namespace railodd::geometry;

namespace {

struct Figures {
    double p95 = 0.0, max = 0.0;
    std::size_t edges = 0, covered = 0, corner = 0;
};

Figures fit_extract(const test::fs::path& file, FittedNetwork& net) {
    const ingest::IngestResult r = ingest::read_osm(file, {});
    const TrackGraph g = build_track_graph(r.tracks, r.features);
    net = fit_track_graph(g, {}); // the node scatter estimated per chain, as railodd convert does

    Figures f;
    std::vector<double> d;
    for (const auto& e : net.edges) {
        std::vector<Point> pts;
        for (const auto& n : g.edges[e.edge].nodes) {
            pts.push_back({n.xy.x, n.xy.y});
        }
        const auto de = distances(e.alignment, pts);
        d.insert(d.end(), de.begin(), de.end());
        f.covered += e.alignment.primitives.empty() ? 0 : 1;
    }
    f.edges = g.edges.size();
    f.corner = net.corner_chains.size();
    std::sort(d.begin(), d.end());
    f.p95 = d[d.size() * 95 / 100];
    f.max = d.back();
    return f;
}

} // namespace

TEST(GeometrySharedExtracts, NodesLieWithinTwoThirdsOfAMetreAtP95AndTwoMetresAtMost) {
    RAILODD_REQUIRE_SHARED_DATA();
    for (const char* name : {"gh_harsdorf.osm.pbf", "valhalla_liechtenstein-latest.osm.pbf",
                             "gh_north-bayreuth.osm.gz", "gh_lauf-200115.osm.pbf", "osrm_monaco.osm.pbf",
                             "gh_krems.osm.gz", "valhalla_munchen.osm.pbf"}) {
        SCOPED_TRACE(name);
        FittedNetwork net;
        const Figures f = fit_extract(test::shared_data() / "osm" / name, net);
        std::cout << name << ": p95 " << f.p95 << " m, max " << f.max << " m, " << f.edges << " edges, "
                  << f.corner << " corner chains\n";
        EXPECT_EQ(f.covered, f.edges) << "every mapped track has a centreline";
        // The fit reads a design, not every node: 0.6 m at p95 where the nodes
        // are too sparse to estimate their scatter (Krems' tight curves:
        // 0.59 m), never more than 2 m.
        EXPECT_LE(f.p95, 0.65);
        EXPECT_LE(f.max, 2.0);
        for (const auto& l : net.branch_links) {
            EXPECT_LT(l.gap_m, 1e-3);
            EXPECT_LT(l.heading_rad, 1e-4);
            EXPECT_LT(l.curvature, 1e-6);
        }
    }
}
