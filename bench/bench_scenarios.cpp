// Scenario generation throughput on a large synthetic ODD profile: TRACKS
// tracks of 5 km, each tiled by Straight / Curve elements (radius 320-6000 m,
// two OpenDRIVE roads per track), two speed-limit stretches, a level crossing
// with barrier 300 m after a curve, a platform on every second track and a
// tunnel on every third, plus the per-track stretches a real profile carries
// (gauge, electrification, track service). Generation uses the shipped
// data/scenario templates and assets.
//
// Run: build/bench/bench_scenarios (docs/BENCHMARKS.md "Scenario generation").
// BM_FindAnchors, BM_PairwiseRows and BM_PairCoverage time parts of
// generate() on their own, to see where its time goes.
// Counters: scenarios/s (scenarios generated or serialised per second of wall
// time), anchors (over all templates), scenarios (per generation).
#include "railodd/odd/profile.hpp"
#include "railodd/odd/taxonomy.hpp"
#include "railodd/scenario/anchors.hpp"
#include "railodd/scenario/catalog.hpp"
#include "railodd/scenario/generator.hpp"
#include "railodd/scenario/strategies.hpp"
#include "railodd/scenario/templates.hpp"
#include "railodd/scenario/xosc_writer.hpp"

#include <benchmark/benchmark.h>

#include <algorithm>
#include <cstdint>
#include <filesystem>
#include <map>
#include <string>
#include <tuple>
#include <vector>

using namespace railodd;
using namespace railodd::scenario;

namespace {

const std::filesystem::path source_dir{RAILODD_SOURCE_DIR};

struct Inputs {
    odd::Taxonomy taxonomy;
    Catalog catalog;
    TemplateSet templates;
};

const Inputs& inputs() {
    static const Inputs in = [] {
        Inputs i;
        i.taxonomy = odd::load_taxonomy(source_dir / "data/odd/railway_odd.yaml");
        i.catalog = load_catalog(source_dir / "data/scenario/assets.yaml", i.taxonomy);
        i.templates = load_templates(source_dir / "data/scenario/templates.yaml", i.taxonomy, i.catalog);
        return i;
    }();
    return in;
}

constexpr double track_length = 5000.0;
constexpr double road_length = 2500.0; // two roads per track

struct ProfileBuilder {
    const odd::Taxonomy& tax;
    odd::OddProfile p;
    std::size_t track = 0;

    // A stretch (or a point when c0 == c1) on the current track; s along its road.
    odd::TaggedElement& add(const std::string& path, double c0, double c1,
                            std::vector<odd::TaggedAttribute> attrs = {}) {
        odd::TaggedElement e;
        e.element = path;
        const odd::Element* el = tax.find(path);
        e.element_id = el ? el->id : "";
        e.attributes = std::move(attrs);
        const int road = static_cast<int>(c0 >= road_length && c0 > 0.0 ? 1 : 0);
        e.road_id = std::to_string(2 * track + static_cast<std::size_t>(road) + 1);
        e.s_start = c0 - road * road_length;
        e.s_end = c1 - road * road_length;
        e.track = track;
        e.chainage_start = c0;
        e.chainage_end = c1;
        e.point = c0 == c1;
        e.osm_ids = {"way:" + std::to_string(1000000 + track)};
        e.source = "osm";
        p.elements.push_back(std::move(e));
        return p.elements.back();
    }
};

// Horizontal geometry of one track: straights and curves that never straddle
// the road boundary at 2500 m, so that every piece lies on one road.
// (start, end, radius; 0 = straight)
struct Piece {
    double c0, c1, radius;
};

std::vector<Piece> geometry_of(std::size_t track) {
    const double r = 400.0 + static_cast<double>((track * 7919) % 37) * 100.0; // 400 .. 4000 m
    return {{0, 1000, 0},    {1000, 1500, r},          {1500, 2500, 0}, {2500, 2600, 0},
            {2600, 3000, r * 1.5}, {3000, 3900, 0}, {3900, 4300, r * 0.8}, {4300, 5000, 0}};
}

odd::OddProfile synthetic_profile(std::size_t tracks) {
    ProfileBuilder b{inputs().taxonomy, {}, 0};
    b.p.taxonomy_name = inputs().taxonomy.name;
    b.p.taxonomy_version = inputs().taxonomy.version;
    b.p.route = "synthetic: " + std::to_string(tracks) + " tracks of 5 km";
    b.p.length_m = static_cast<double>(tracks) * track_length;
    b.p.tracks = tracks;
    const char* barriers[] = {"full", "half", "no", "gate"};
    const char* sides[] = {"left", "right"};
    for (std::size_t t = 0; t < tracks; ++t) {
        b.track = t;
        for (const double c0 : {0.0, road_length}) {
            b.add("Operational Conditions/Speed/Speed limit", c0, c0 + road_length,
                  {{"maxspeed", c0 == 0.0 ? 120.0 : 80.0}, {"maxspeed_class", std::string("regional")},
                   {"kind", std::string("posted")}});
            b.add("Operational Conditions/Usage/Track service", c0, c0 + road_length,
                  {{"service", std::string("running")}});
            b.add("Scenery/Track geometry/Gauge", c0, c0 + road_length,
                  {{"gauge", 1435.0}, {"gauge_class", std::string("standard")}, {"dual_gauge", false}});
            b.add("Scenery/Trackside equipment/Electrification", c0, c0 + road_length,
                  {{"system", std::string("contact_line")}, {"voltage", 15000.0}});
        }
        for (const auto& g : geometry_of(t)) {
            if (g.radius > 0.0) {
                b.add("Scenery/Track geometry/Horizontal/Curve", g.c0, g.c1,
                      {{"radius", g.radius}, {"direction", std::string(t % 2 ? "left" : "right")},
                       {"length", g.c1 - g.c0}});
            } else {
                b.add("Scenery/Track geometry/Horizontal/Straight", g.c0, g.c1, {{"length", g.c1 - g.c0}});
            }
        }
        b.add("Scenery/Crossings/Level crossing", 1800, 1800,
              {{"barrier", std::string(barriers[t % 4])}, {"lights", t % 3 != 0},
               {"road_class", std::string("secondary")}, {"angle", 80.0}});
        if (t % 2 == 0) {
            b.add("Scenery/Stations and stops/Platform", 3100, 3320,
                  {{"length", 220.0}, {"length_class", std::string("medium")}, {"side", std::string(sides[t % 4 / 2])}});
        }
        if (t % 3 == 0) {
            b.add("Scenery/Structures/Tunnel", 4350, 4800, {{"length", 450.0}, {"length_class", std::string("short")}});
        }
    }
    // The profile's order: by track, then chainage, then element path.
    std::stable_sort(b.p.elements.begin(), b.p.elements.end(), [](const auto& x, const auto& y) {
        return std::tie(x.track, x.chainage_start, x.element) < std::tie(y.track, y.chainage_start, y.element);
    });
    return b.p;
}

const odd::OddProfile& profile(std::size_t tracks) {
    static std::map<std::size_t, odd::OddProfile> cache;
    auto it = cache.find(tracks);
    if (it == cache.end()) {
        it = cache.emplace(tracks, synthetic_profile(tracks)).first;
    }
    return it->second;
}

void report(benchmark::State& state, const odd::OddProfile& p, const Generation& g, std::size_t total) {
    std::size_t anchors = 0;
    for (const auto& r : g.runs) {
        anchors += r.anchors;
    }
    state.counters["scenarios/s"] = benchmark::Counter(static_cast<double>(total), benchmark::Counter::kIsRate);
    state.counters["scenarios"] = static_cast<double>(g.scenarios.size());
    state.counters["anchors"] = static_cast<double>(anchors);
    state.counters["elements"] = static_cast<double>(p.elements.size());
}

void run_generate(benchmark::State& state, Strategy strategy, std::size_t count, std::size_t max_anchors) {
    const auto& p = profile(static_cast<std::size_t>(state.range(0)));
    GenerateOptions o;
    o.strategy = strategy;
    o.count = count;
    o.max_anchors = max_anchors;
    o.map_file = "map.xodr";
    Generation g;
    std::size_t total = 0;
    for (auto _ : state) {
        g = generate(p, inputs().templates, inputs().catalog, inputs().taxonomy, o);
        total += g.scenarios.size();
        benchmark::DoNotOptimize(g.scenarios.data());
    }
    report(state, p, g, total);
}

// `railodd scenarios` default: pairwise over every anchor.
void BM_GeneratePairwise(benchmark::State& state) { run_generate(state, Strategy::pairwise, 0, 0); }
// `--strategy cover` (the default): the set cover over all anchors, pairwise
// rows of the parameters, and pairwise over all anchors for the report.
void BM_GenerateCover(benchmark::State& state) { run_generate(state, Strategy::cover, 0, 0); }
// `--strategy random --count 100`.
void BM_GenerateRandom100(benchmark::State& state) { run_generate(state, Strategy::random, 100, 0); }
// `--max-anchors 50`: pairwise over 50 anchors per template, spread along the route.
void BM_GeneratePairwiseMax50(benchmark::State& state) { run_generate(state, Strategy::pairwise, 0, 50); }

// The parts of generate(), to see where its time goes.
void BM_FindAnchors(benchmark::State& state) {
    const auto& p = profile(static_cast<std::size_t>(state.range(0)));
    std::size_t anchors = 0;
    for (auto _ : state) {
        const LineIndex lines(p);
        anchors = 0;
        for (const auto& t : inputs().templates.templates) {
            anchors += find_anchors(p, lines, t).anchors.size();
        }
        benchmark::DoNotOptimize(anchors);
    }
    state.counters["anchors"] = static_cast<double>(anchors);
    state.counters["elements"] = static_cast<double>(p.elements.size());
}

// Pairwise rows and their pair coverage for a template shaped like
// curve_track_worker: anchors x speed 2 x worker 1 x rail head 3 x time of day 2.
void BM_PairwiseRows(benchmark::State& state) {
    const std::vector<std::size_t> sizes{static_cast<std::size_t>(state.range(0)), 2, 1, 3, 2};
    const Validity valid = [](const Row&) { return true; };
    std::size_t rows = 0;
    for (auto _ : state) {
        rows = pairwise(sizes, valid).size();
        benchmark::DoNotOptimize(rows);
    }
    state.counters["rows"] = static_cast<double>(rows);
}

void BM_PairCoverage(benchmark::State& state) {
    const std::vector<std::size_t> sizes{static_cast<std::size_t>(state.range(0)), 2, 1, 3, 2};
    const Validity valid = [](const Row&) { return true; };
    const auto rows = pairwise(sizes, valid);
    for (auto _ : state) {
        benchmark::DoNotOptimize(pair_coverage(sizes, valid, rows));
    }
    state.counters["rows"] = static_cast<double>(rows.size());
}

// xosc_text() on the scenarios of a random --count 100 generation (500 scenarios).
void BM_XoscText(benchmark::State& state) {
    GenerateOptions o;
    o.strategy = Strategy::random;
    o.count = 100;
    o.map_file = "map.xodr";
    const Generation g = generate(profile(200), inputs().templates, inputs().catalog, inputs().taxonomy, o);
    std::size_t total = 0, bytes = 0;
    for (auto _ : state) {
        for (const auto& r : g.scenarios) {
            const std::string text = xosc_text(r.scenario);
            bytes += text.size();
            benchmark::DoNotOptimize(text.data());
        }
        total += g.scenarios.size();
    }
    state.SetBytesProcessed(static_cast<std::int64_t>(bytes));
    state.counters["scenarios/s"] = benchmark::Counter(static_cast<double>(total), benchmark::Counter::kIsRate);
    state.counters["scenarios"] = static_cast<double>(g.scenarios.size());
}

} // namespace

BENCHMARK(BM_GenerateCover)->Arg(200)->Arg(600)->Arg(2000)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_GeneratePairwise)->Arg(200)->Arg(600)->Arg(2000)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_GenerateRandom100)->Arg(200)->Arg(600)->Arg(2000)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_GeneratePairwiseMax50)->Arg(200)->Arg(2000)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_FindAnchors)->Arg(200)->Arg(2000)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_PairwiseRows)->Arg(200)->Arg(2000)->Arg(6000)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_PairCoverage)->Arg(200)->Arg(2000)->Arg(6000)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_XoscText)->Unit(benchmark::kMillisecond);

BENCHMARK_MAIN();
