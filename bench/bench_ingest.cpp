// Ingest throughput on the shared real extracts, beside the floor of merely
// decoding the same file with libosmium. Run: build/bench/bench_ingest
// (RAILODD_SHARED_DATA overrides ../shared/data). Figures: docs/BENCHMARKS.md.
#include "railodd/ingest/osm_reader.hpp"

#include <benchmark/benchmark.h>
#include <osmium/io/any_input.hpp>

#include <cstdlib>
#include <filesystem>
#include <string>

namespace fs = std::filesystem;

namespace {

fs::path shared_osm(const char* name) {
    const char* env = std::getenv("RAILODD_SHARED_DATA");
    return fs::path{env ? env : RAILODD_SHARED_DATA} / "osm" / name;
}

const char* const files[] = {"gh_harsdorf.osm.pbf", "orr_vde8.2-rail.osm.pbf", "orr_cologne-railway.osm.pbf",
                             "valhalla_liechtenstein-latest.osm.pbf", "gh_north-bayreuth.osm.gz"};

void BM_ReadOsm(benchmark::State& state) {
    const fs::path file = shared_osm(files[state.range(0)]);
    if (!fs::exists(file)) {
        state.SkipWithError(("missing " + file.string()).c_str());
        return;
    }
    state.SetLabel(file.filename().string());
    std::size_t nodes = 0, tracks = 0;
    for (auto _ : state) {
        const auto r = railodd::ingest::read_osm(file, {});
        nodes = r.counts.input_nodes;
        tracks = r.counts.output_track_ways;
        benchmark::DoNotOptimize(r.tracks.data());
    }
    state.counters["track_ways"] = static_cast<double>(tracks);
    state.counters["nodes/s"] = benchmark::Counter(static_cast<double>(nodes), benchmark::Counter::kIsIterationInvariantRate);
    state.counters["MB/s"] = benchmark::Counter(static_cast<double>(fs::file_size(file)) / 1e6,
                                                benchmark::Counter::kIsIterationInvariantRate);
}

// The floor: decode every object of the file once, keeping nothing.
void BM_DecodeFloor(benchmark::State& state) {
    const fs::path file = shared_osm(files[state.range(0)]);
    if (!fs::exists(file)) {
        state.SkipWithError(("missing " + file.string()).c_str());
        return;
    }
    state.SetLabel(file.filename().string());
    for (auto _ : state) {
        osmium::io::Reader reader{file.string()};
        std::size_t n = 0;
        while (osmium::memory::Buffer buffer = reader.read()) {
            n += buffer.committed();
        }
        reader.close();
        benchmark::DoNotOptimize(n);
    }
}

} // namespace

BENCHMARK(BM_ReadOsm)->DenseRange(0, 4)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_DecodeFloor)->DenseRange(0, 4)->Unit(benchmark::kMillisecond);

BENCHMARK_MAIN();
