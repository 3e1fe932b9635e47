// The OSM reader on every real extract in ../shared/data/osm: counts against an
// independent reader (osmium-tool), the accounting invariant, the clipped
// extract, and clean failures on truncated copies.
#include "railodd/ingest/osm_reader.hpp"
#include "railodd/util/errors.hpp"
#include "test_support.hpp"

#include <algorithm>
#include <map>

using namespace railodd::ingest;
using namespace railodd::test;

namespace {

std::vector<fs::path> shared_osm_files() {
    std::vector<fs::path> files;
    for (const auto& e : fs::directory_iterator(shared_data() / "osm")) {
        files.push_back(e.path());
    }
    std::sort(files.begin(), files.end());
    return files;
}

// Track ways counted by osmium-tool, which shares no code with railodd's reader.
std::size_t independent_track_count(const fs::path& file) {
    std::string command = "osmium tags-filter -R -f opl -o - ";
    command += quoted(file);
    command += " w/railway=rail,light_rail,tram,subway,narrow_gauge,monorail,funicular | grep -c '^w'";
    const auto r = run_command(command);
    return static_cast<std::size_t>(std::stoul(r.output));
}

std::size_t dropped_of(const IngestResult& r, const std::string& kind) {
    return std::count_if(r.dropped.begin(), r.dropped.end(), [&](const Dropped& d) { return d.kind == kind; });
}

} // namespace

TEST(IngestSharedExtracts, TrackCountsMatchIndependentCountAndInvariantHolds) {
    RAILODD_REQUIRE_SHARED_DATA();
    // Track ways per file as listed in ../shared/data/README.md (five railway values).
    const std::map<std::string, std::size_t> documented{
        {"gh_harsdorf.osm.pbf", 11},        {"valhalla_liechtenstein-latest.osm.pbf", 31},
        {"osrm_monaco.osm.pbf", 69},        {"most_monaco_network_ele.osm", 23},
        {"orr_vde8.2-rail.osm.pbf", 1823},  {"orr_cologne-railway.osm.pbf", 7154},
        {"valhalla_munchen.osm.pbf", 83},   {"gh_krems.osm.gz", 109},
        {"gh_north-bayreuth.osm.gz", 17},   {"gh_lauf-200115.osm.pbf", 66}};
    const auto files = shared_osm_files();
    ASSERT_FALSE(files.empty());
    for (const auto& file : files) {
        SCOPED_TRACE(file.filename().string());
        const IngestResult r = read_osm(file, {});
        EXPECT_EQ(r.counts.input_track_ways, independent_track_count(file));
        if (const auto it = documented.find(file.filename().string()); it != documented.end()) {
            EXPECT_GE(r.counts.input_track_ways, it->second);
        }
        EXPECT_EQ(r.counts.output_track_ways + dropped_of(r, "track"), r.counts.input_track_ways);
        EXPECT_EQ(r.counts.output_road_ways + dropped_of(r, "road"), r.counts.input_road_ways);
        EXPECT_EQ(r.counts.output_features + dropped_of(r, "feature"), r.counts.input_features);
        EXPECT_GE(r.counts.input_nodes, r.counts.input_track_nodes);
    }
}

TEST(IngestSharedExtracts, ClippedLaufExtractKeepsPresentParts) {
    RAILODD_REQUIRE_SHARED_DATA();
    const IngestResult r = read_osm(shared_data() / "osm" / "gh_lauf-200115.osm.pbf", {});
    const auto clipped = std::count_if(r.tracks.begin(), r.tracks.end(), [](const Way& w) { return w.clipped(); });
    // The data README: 8 track ways reference 38 missing nodes.
    EXPECT_EQ(r.counts.missing_track_nodes, 38u);
    EXPECT_EQ(clipped + static_cast<long>(dropped_of(r, "track")), 8);
    const auto clip_repairs = std::count_if(r.repairs.begin(), r.repairs.end(), [](const Repair& x) {
        return x.kind == "track" && x.action.rfind("clipped:", 0) == 0;
    });
    EXPECT_EQ(clip_repairs, clipped);
    for (const auto& w : r.tracks) {
        for (const auto& part : w.parts) {
            EXPECT_GE(part.size(), 2u) << "way " << w.id;
        }
    }
}

TEST(IngestSharedExtracts, RealFeaturesAndRoadsAreFound) {
    RAILODD_REQUIRE_SHARED_DATA();
    const IngestResult r = read_osm(shared_data() / "osm" / "gh_harsdorf.osm.pbf", {});
    std::map<std::string, int> kinds;
    for (const auto& f : r.features) {
        ++kinds[f.kind];
    }
    // The data README: 6 level crossings, 5 signals, a station and a halt.
    EXPECT_EQ(kinds["level_crossing"], 6);
    EXPECT_EQ(kinds["signal"], 5);
    EXPECT_GE(kinds["station"], 1);
    EXPECT_GE(kinds["halt"], 1);
    EXPECT_GT(r.roads.size(), 20u);
    EXPECT_LE(r.roads.size(), 130u) << "only roads in the corridor, of 130 in the file";
}

TEST(IngestSharedExtracts, CorridorPassesAgreeWithPrefetchOnRealRoads) {
    RAILODD_REQUIRE_SHARED_DATA();
    const auto file = shared_data() / "osm" / "valhalla_liechtenstein-latest.osm.pbf";
    IngestOptions passes;
    passes.road_prefetch_refs = 0;
    const IngestResult a = read_osm(file, {});
    const IngestResult b = read_osm(file, passes);
    EXPECT_EQ(a.counts.input_road_ways, b.counts.input_road_ways);
    ASSERT_EQ(a.roads.size(), b.roads.size());
    for (std::size_t i = 0; i < a.roads.size(); ++i) {
        EXPECT_EQ(a.roads[i].id, b.roads[i].id);
        EXPECT_EQ(a.roads[i].parts.size(), b.roads[i].parts.size());
    }
    EXPECT_LT(a.roads.size(), 4660u / 2) << "a corridor, not the whole road network";
}

TEST(IngestSharedExtracts, TruncatedFilesFailCleanly) {
    RAILODD_REQUIRE_SHARED_DATA();
    const auto dir = scratch_dir();
    for (const char* name : {"gh_harsdorf.osm.pbf", "gh_krems.osm.gz", "most_monaco_network_ele.osm"}) {
        SCOPED_TRACE(name);
        const std::string whole = read_file(shared_data() / "osm" / name);
        const auto cut = write_file(dir / name, whole.substr(0, whole.size() / 2));
        try {
            read_osm(cut, {});
            FAIL() << "a truncated file was read without error";
        } catch (const railodd::InputError& e) {
            EXPECT_EQ(e.where(), cut.string());
        }
    }
}
