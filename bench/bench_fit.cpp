// Fitting throughput: railway-grade centrelines for synthetic tracks of
// growing length (lines, transitions and arcs of 300-3000 m radius, 0.3 m node
// noise, mapper-like node spacing). Run: build/bench/bench_fit. The counter
// km/s is track length fitted per second; its growth with length shows the
// cost per kilometre stays flat (the fit works window by window).
// BM_CornerPolyline times the clothoid-corner construction on the same nodes.
#include "railodd/geometry/corner_fit.hpp"
#include "railodd/geometry/fit_alignment.hpp"
#include "railodd/geometry/indexed_alignment.hpp"

#include <benchmark/benchmark.h>

#include <cmath>
#include <cstdint>
#include <numbers>

using namespace railodd::geometry;

namespace {

std::uint64_t lcg(std::uint64_t& s) {
    s = s * 6364136223846793005ULL + 1442695040888963407ULL;
    return s >> 11;
}
double uniform(std::uint64_t& s) { return (static_cast<double>(lcg(s)) + 0.5) / 9007199254740992.0; }
double normal(std::uint64_t& s, double sigma) {
    const double a = uniform(s), b = uniform(s);
    return sigma * std::sqrt(-2 * std::log(a)) * std::cos(2 * std::numbers::pi * b);
}

Alignment track_of_length(double km) {
    Alignment a;
    a.start = {0, 0, 0, 0};
    std::uint64_t seed = 42;
    double total = 0.0;
    for (int i = 0; total < km * 1000.0; ++i) {
        const double r = 300 + 2700 * uniform(seed);
        const double k = (i % 2 ? 1 : -1) / r;
        const double line = 300 + 700 * uniform(seed), tr = 60 + 90 * uniform(seed), arc = 150 + 450 * uniform(seed);
        a.primitives.push_back(make_line(line));
        a.primitives.push_back(make_spiral(tr, 0, k));
        a.primitives.push_back(make_arc(arc, k));
        a.primitives.push_back(make_spiral(tr, k, 0));
        total += line + 2 * tr + arc;
    }
    return a;
}

std::vector<Point> nodes_of(const Alignment& truth) {
    const IndexedAlignment ia(truth);
    std::uint64_t seed = 7;
    std::vector<Point> pts;
    for (double s = 0;; ) {
        const Pose p = ia.evaluate(s);
        pts.push_back({p.x + normal(seed, 0.3), p.y + normal(seed, 0.3)});
        if (s >= ia.length()) {
            break;
        }
        s = std::min(ia.length(), s + (std::abs(p.curvature) > 0 ? 8 + 17 * uniform(seed) : 60 + 190 * uniform(seed)));
    }
    return pts;
}

void BM_FitTrack(benchmark::State& state) {
    const double km = static_cast<double>(state.range(0));
    const Alignment truth = track_of_length(km);
    const std::vector<Point> pts = nodes_of(truth);
    std::size_t primitives = 0;
    for (auto _ : state) {
        const FitResult r = fit_alignment(pts, std::nullopt, std::nullopt, {});
        primitives = r.alignment.primitives.size();
        benchmark::DoNotOptimize(r.alignment.primitives.data());
    }
    state.counters["km/s"] = benchmark::Counter(length(truth) / 1000.0, benchmark::Counter::kIsIterationInvariantRate);
    state.counters["nodes"] = static_cast<double>(pts.size());
    state.counters["primitives"] = static_cast<double>(primitives);
}

// The corner construction on the same nodes: the fallback for chains the
// fit cannot follow, and every road. It is linear in the node count.
void BM_CornerPolyline(benchmark::State& state) {
    const double km = static_cast<double>(state.range(0));
    const Alignment truth = track_of_length(km);
    const std::vector<Point> pts = nodes_of(truth);
    for (auto _ : state) {
        const Alignment a = corner_polyline(pts, std::nullopt, std::nullopt, {});
        benchmark::DoNotOptimize(a.primitives.data());
    }
    state.counters["km/s"] = benchmark::Counter(length(truth) / 1000.0, benchmark::Counter::kIsIterationInvariantRate);
    state.counters["nodes"] = static_cast<double>(pts.size());
}

} // namespace

BENCHMARK(BM_FitTrack)->Arg(1)->Arg(4)->Arg(16)->Arg(64)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_CornerPolyline)->Arg(1)->Arg(16)->Arg(64)->Unit(benchmark::kMillisecond);

BENCHMARK_MAIN();
