// Track fitting on real extracts: every mapped track covered, mapped nodes
// close to the fitted line, every branch link continuous (G2), corner chains
// included.
#include "railodd/geometry/dump.hpp"
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
    double p95_sigmas = 0.0;  // node distances in units of their chain's noise estimate, except on reported chains
    std::size_t beyond = 0;   // nodes further than max(1 m, 4 sigma-hat)
    std::size_t reported = 0; // of those, on chains reported beyond their limit (links.beyond_limit_chains)
    std::size_t on_reported = 0; // nodes on those chains
    nlohmann::ordered_json noise; // report.json's geometry.summary.node_noise
    std::size_t edges = 0, covered = 0, corner = 0, outliers = 0;
};

Figures fit_extract(const test::fs::path& file, FittedNetwork& net) {
    const ingest::IngestResult r = ingest::read_osm(file, {});
    const TrackGraph g = build_track_graph(r.tracks, r.features);
    net = fit_track_graph(g, {}); // the node scatter estimated per chain, as railodd convert does

    Figures f;
    std::vector<double> d, ds;
    for (const auto& e : net.edges) {
        std::vector<Point> pts;
        for (const auto& n : g.edges[e.edge].nodes) {
            pts.push_back({n.xy.x, n.xy.y});
        }
        const auto de = distances(e.alignment, pts);
        d.insert(d.end(), de.begin(), de.end());
        const double sigma = e.quality.noise_sigma_m; // 0 for a degenerate chain
        const bool reported = std::find(net.beyond_limit_chains.begin(), net.beyond_limit_chains.end(), e.chain) !=
                              net.beyond_limit_chains.end();
        f.on_reported += reported ? de.size() : 0;
        for (const double x : de) {
            if (sigma > 0.0 && !reported) {
                ds.push_back(x / sigma);
            }
            const bool far = x > std::max(1.0, 4.0 * sigma);
            f.beyond += far ? 1 : 0;
            f.reported += far && reported ? 1 : 0;
        }
        f.covered += e.alignment.primitives.empty() ? 0 : 1;
    }
    f.edges = g.edges.size();
    f.corner = net.corner_chains.size();
    std::sort(d.begin(), d.end());
    std::sort(ds.begin(), ds.end());
    f.p95 = d[d.size() * 95 / 100];
    f.p95_sigmas = ds[(ds.size() - 1) * 95 / 100]; // as report.json takes its quantiles
    f.max = d.back();
    f.outliers = net.outlier_nodes;
    f.noise = report_section(g, net, nullptr, false)["summary"]["node_noise"];
    return f;
}

} // namespace

TEST(GeometrySharedExtracts, NodesLieWithinTheirNoiseAndOnlyStraysFarOff) {
    RAILODD_REQUIRE_SHARED_DATA();
    for (const char* name : {"gh_harsdorf.osm.pbf", "valhalla_liechtenstein-latest.osm.pbf",
                             "gh_north-bayreuth.osm.gz", "gh_lauf-200115.osm.pbf", "osrm_monaco.osm.pbf",
                             "gh_krems.osm.gz", "valhalla_munchen.osm.pbf"}) {
        SCOPED_TRACE(name);
        FittedNetwork net;
        const Figures f = fit_extract(test::shared_data() / "osm" / name, net);
        std::cout << name << ": p95 " << f.p95 << " m (" << f.p95_sigmas << " sigma-hat), max " << f.max << " m, "
                  << f.beyond << " nodes beyond max(1 m, 4 sigma-hat) (" << f.reported << " on chains reported beyond their limit), "
                  << f.outliers << " left out, " << f.edges
                  << " edges, " << f.corner << " corner chains\n";
        EXPECT_EQ(f.covered, f.edges) << "every mapped track has a centreline";
        // The fit reads a design, not every node: the nodes lie about it as
        // their scatter does (issue 37: p95 within 2.5 sigma-hat, report.json
        // `node_distance_p95_sigmas`, on the chains not reported beyond their
        // limit), and a node far off is one the fit left out as a stray, or
        // one on a chain reported beyond its limit (nodes leaving a tie at an
        // angle that only corners tighter than a track turns would follow).
        EXPECT_LE(f.p95_sigmas, 2.5);
        // The report states the same figure, and how many nodes it leaves out.
        EXPECT_NEAR(f.noise["node_distance_p95_sigmas"].get<double>(), f.p95_sigmas, 1e-3);
        EXPECT_EQ(f.noise["beyond_limit_chain_nodes"].get<std::size_t>(), f.on_reported);
        EXPECT_LE(f.beyond - f.reported, f.outliers);
        for (const auto& l : net.branch_links) {
            EXPECT_LT(l.gap_m, 1e-3);
            EXPECT_LT(l.heading_rad, 1e-4);
            EXPECT_LT(l.curvature, 1e-6);
        }
    }
}
