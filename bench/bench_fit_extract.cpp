// The fit on a real extract, by each method: report.json's geometry summary
// (design statistics, node noise, links) and the fit's time, for the
// windowed fit and the design search (FitMethod, fit_alignment.hpp) on the
// same track graph. Run: build/bench/bench_fit_extract EXTRACT.osm.pbf
// [--method windowed|design|both] [--threads N] [--shift-mm D] [--list-off]
// (default both, 2 threads, no shift). Prints one JSON object per method;
// --list-off writes each switch node off its fit to stderr.
//
// --shift-mm moves every track node and feature D mm east and 0.7 D mm north
// in the local frame before the fit. A fit is the same up to rounding
// wherever the frame's origin lies, so the spread of the figures over a few
// shifts (bench/extract_spread.sh) is how far rounding alone moves them: a
// change to the fit that moves a figure less than that is not measured by
// one run.
#include "railodd/geometry/dump.hpp"
#include "railodd/geometry/track_fit.hpp"
#include "railodd/geometry/track_graph.hpp"
#include "railodd/ingest/osm_reader.hpp"

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <iostream>
#include <string>
#include <utility>
#include <vector>

using namespace railodd;

namespace {

void shift(ingest::IngestResult& r, double dx, double dy) {
    const auto move = [&](ingest::NodeRef& n) {
        n.xy.x += dx;
        n.xy.y += dy;
    };
    for (ingest::Way& w : r.tracks) {
        for (auto& part : w.parts) {
            for (ingest::NodeRef& n : part) {
                move(n);
            }
        }
    }
    for (ingest::Feature& f : r.features) {
        move(f.position);
        for (ingest::NodeRef& n : f.outline) {
            move(n);
        }
    }
}

// Switch nodes (a vertex where three or more track ends meet) further
// than max(1 m, 4 sigma-hat) from their edge's fit, counted once per edge
// end: where the tracks meet, the mapping is surest, and a branch tied to
// a fit that misses its switch starts off its mapped track.
// With list, each is written to stderr: edge, switch node id, the way at
// that end, distance and the edge's sigma-hat.
std::size_t switch_nodes_off(const geometry::TrackGraph& graph, const geometry::FittedNetwork& net, bool list) {
    std::size_t off = 0;
    for (const geometry::FittedEdge& e : net.edges) {
        const geometry::GraphEdge& ge = graph.edges[e.edge];
        std::vector<geometry::Point> ends;
        std::vector<std::pair<std::int64_t, std::int64_t>> named; // node id, the way at that end
        for (const bool at_end : {false, true}) {
            if (graph.vertices[at_end ? ge.to : ge.from].kind == geometry::VertexKind::switch_) {
                const auto& n = at_end ? ge.nodes.back() : ge.nodes.front();
                ends.push_back({n.xy.x, n.xy.y});
                named.push_back({n.id, (at_end ? ge.ways.back() : ge.ways.front()).way_id});
            }
        }
        const std::vector<double> d = geometry::distances(e.alignment, ends);
        for (std::size_t k = 0; k < d.size(); ++k) {
            const bool is_off = d[k] > std::max(1.0, 4.0 * e.quality.noise_sigma_m);
            off += is_off ? 1 : 0;
            if (is_off && list) {
                std::fprintf(stderr, "edge %zu node %lld way %lld off %.2f m sigma %.2f m\n", e.edge,
                             static_cast<long long>(named[k].first), static_cast<long long>(named[k].second), d[k],
                             e.quality.noise_sigma_m);
            }
        }
    }
    return off;
}

} // namespace

int main(int argc, char** argv) {
    if (argc < 2) {
        std::fprintf(stderr,
                     "usage: bench_fit_extract EXTRACT [--method windowed|design|both] [--threads N] [--shift-mm D] "
                     "[--list-off]\n");
        return 2;
    }
    std::string method = "both";
    unsigned threads = 2;
    double shift_m = 0.0;
    bool list_off = false;
    for (int i = 2; i < argc; ++i) {
        const std::string a = argv[i];
        if (a == "--list-off") {
            list_off = true;
        } else if (a == "--method" && i + 1 < argc) {
            method = argv[++i];
        } else if (a == "--threads" && i + 1 < argc) {
            threads = static_cast<unsigned>(std::stoul(argv[++i]));
        } else if (a == "--shift-mm" && i + 1 < argc) {
            shift_m = std::stod(argv[++i]) / 1000.0;
        }
    }
    ingest::IngestOptions io;
    io.road_corridor_m = 0.0;
    io.land_use = false;
    ingest::IngestResult r = ingest::read_osm(argv[1], io);
    if (shift_m != 0.0) {
        shift(r, shift_m, 0.7 * shift_m);
    }
    const geometry::TrackGraph graph = geometry::build_track_graph(r.tracks, r.features);
    std::vector<std::pair<std::string, geometry::FitMethod>> runs;
    if (method != "design") {
        runs.push_back({"windowed", geometry::FitMethod::windowed});
    }
    if (method != "windowed") {
        runs.push_back({"design", geometry::FitMethod::design_search});
    }
    for (const auto& [name, m] : runs) {
        geometry::FitOptions fo;
        fo.method = m;
        fo.threads = threads;
        const auto t0 = std::chrono::steady_clock::now();
        const geometry::FittedNetwork net = geometry::fit_track_graph(graph, fo);
        const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
        nlohmann::ordered_json out;
        out["method"] = name;
        out["fit_seconds"] = seconds;
        out["summary"] = geometry::report_section(graph, net)["summary"];
        out["switch_nodes_off"] = switch_nodes_off(graph, net, list_off);
        std::cout << out.dump() << "\n";
    }
    return 0;
}
