// `railodd convert` as a user runs it: outputs, exit codes, messages naming the
// file, no half-written output, byte-identical reruns.
#include "test_support.hpp"

#include <nlohmann/json.hpp>

using namespace railodd::test;

namespace {

const char* const small_opl = R"(n1 v1 x10.0000 y48.0000
n2 v1 x10.0010 y48.0000 Trailway=level_crossing
n3 v1 x10.0020 y48.0001
n4 v1 x10.0010 y48.0010
n5 v1 x10.0010 y47.9990
w1 v1 Trailway=rail,maxspeed=100 Nn1,n2,n3
w2 v1 Trailway=rail Nn3,n9
w3 v1 Thighway=tertiary Nn4,n2,n5
)";

CommandResult run_railodd(const std::string& args) { return run_command(std::string{RAILODD_BIN} + " " + args); }

bool has_staging_leftovers(const fs::path& dir) {
    if (!fs::exists(dir)) {
        return false;
    }
    for (const auto& e : fs::directory_iterator(dir)) {
        if (e.path().filename().string().rfind(".railodd-staging", 0) == 0) {
            return true;
        }
    }
    return false;
}

} // namespace

TEST(CliConvert, HelpListsSubcommands) {
    const auto r = run_railodd("--help");
    EXPECT_EQ(r.exit_code, 0);
    EXPECT_NE(r.output.find("convert"), std::string::npos);
    EXPECT_NE(r.output.find("sample"), std::string::npos);
}

TEST(CliConvert, WritesReportWithAccounting) {
    const auto dir = scratch_dir();
    const auto in = write_file(dir / "in.opl", small_opl);
    const auto out = dir / "out";
    const auto r = run_railodd("convert " + quoted(in) + " -o " + quoted(out) + " --debug-outputs");
    ASSERT_EQ(r.exit_code, 0) << r.output;
    const auto report = nlohmann::json::parse(read_file(out / "report.json"));
    EXPECT_EQ(report["input"]["track_ways"], 2);
    EXPECT_EQ(report["output"]["track_ways"], 1);
    EXPECT_EQ(report["input"]["road_ways"], 1);
    ASSERT_EQ(report["dropped"].size(), 1u);
    EXPECT_EQ(report["dropped"][0]["kind"], "track");
    EXPECT_EQ(report["dropped"][0]["osm_type"], "way");
    EXPECT_EQ(report["dropped"][0]["osm_id"], 2);
    EXPECT_FALSE(report["dropped"][0]["reason"].get<std::string>().empty());
    EXPECT_TRUE(report["timings_s"].contains("read_ways"));
    EXPECT_EQ(report["output"]["features_by_kind"]["level_crossing"], 1);
    const auto geo = nlohmann::json::parse(read_file(out / "ingest.geojson"));
    EXPECT_EQ(geo["type"], "FeatureCollection");
    EXPECT_EQ(geo["features"].size(), 3u); // track, road, level crossing
    EXPECT_FALSE(has_staging_leftovers(out));
}

TEST(CliConvert, MissingInputFailsNamingTheFileAndWritesNothing) {
    const auto dir = scratch_dir();
    const auto out = dir / "out";
    const auto r = run_railodd("convert " + quoted(dir / "nope.osm.pbf") + " -o " + quoted(out));
    EXPECT_EQ(r.exit_code, 2);
    EXPECT_NE(r.output.find((dir / "nope.osm.pbf").string() + ": no such file"), std::string::npos) << r.output;
    EXPECT_FALSE(fs::exists(out / "report.json"));
    EXPECT_FALSE(fs::exists(out / "map.xodr"));
    EXPECT_FALSE(has_staging_leftovers(out));
}

TEST(CliConvert, CorruptInputFailsCleanly) {
    const auto dir = scratch_dir();
    const auto in = write_file(dir / "bad.osm", "<osm version=\"0.6\"><way id=\"1\"><nd ref=");
    const auto out = dir / "out";
    const auto r = run_railodd("convert " + quoted(in) + " -o " + quoted(out));
    EXPECT_EQ(r.exit_code, 2);
    EXPECT_NE(r.output.find(in.string()), std::string::npos) << r.output;
    EXPECT_FALSE(fs::exists(out / "report.json"));
    EXPECT_FALSE(has_staging_leftovers(out));
}

TEST(CliConvert, BadOptionsAreUsageErrors) {
    const auto dir = scratch_dir();
    const auto in = write_file(dir / "in.opl", small_opl);
    const auto r1 = run_railodd("convert " + quoted(in) + " -o " + quoted(dir / "o1") + " --bbox 10,48,9,49");
    EXPECT_EQ(r1.exit_code, 1);
    EXPECT_NE(r1.output.find("--bbox"), std::string::npos) << r1.output;
    EXPECT_FALSE(fs::exists(dir / "o1"));
    const auto r2 = run_railodd("convert " + quoted(in) + " -o " + quoted(dir / "o2") + " --road-corridor -5");
    EXPECT_EQ(r2.exit_code, 1);
    const auto r3 = run_railodd("convert " + quoted(dir / "t.geojson") + " -o " + quoted(dir / "o3"));
    EXPECT_EQ(r3.exit_code, 1);
    EXPECT_NE(r3.output.find("--field-mapping"), std::string::npos) << r3.output;
    const auto r4 = run_railodd("convert " + quoted(in) + " -o " + quoted(dir / "o4") + " --relation 5");
    EXPECT_EQ(r4.exit_code, 2);
    EXPECT_NE(r4.output.find("relation 5 is not in the file"), std::string::npos) << r4.output;
    const auto r5 = run_railodd("convert " + quoted(in) + " -o " + quoted(dir / "o5") + " --fit-method spline");
    EXPECT_EQ(r5.exit_code, 1);
    EXPECT_NE(r5.output.find("--fit-method"), std::string::npos) << r5.output;
    EXPECT_FALSE(fs::exists(dir / "o5"));
}

// The design search by default; --fit-method windowed gives the older fit
// (the sample's noise estimate: the windowed fit's 0.1 m floor, a real one
// from the design search's residuals).
TEST(CliConvert, FitMethodChoosesTheFit) {
    const auto dir = scratch_dir();
    ASSERT_EQ(run_railodd("sample -o " + quoted(dir / "sample")).exit_code, 0);
    const auto osm = dir / "sample" / "sample_route.osm";
    double sigma[2] = {};
    int i = 0;
    for (const char* method : {"", " --fit-method windowed"}) {
        const auto out = dir / std::to_string(i);
        const auto r = run_railodd("convert " + quoted(osm) + " -o " + quoted(out) + " --no-report --no-timings" + method);
        ASSERT_EQ(r.exit_code, 0) << r.output;
        const auto report = nlohmann::json::parse(read_file(out / "report.json"));
        EXPECT_LT(report["geometry"]["summary"]["links"]["max_gap_m"].get<double>(), 1e-3) << method;
        sigma[i++] = report["geometry"]["summary"]["node_noise"]["chain_sigma_p50_m"].get<double>();
    }
    EXPECT_NE(read_file(dir / "0" / "map.xodr"), read_file(dir / "1" / "map.xodr"));
    EXPECT_GT(sigma[0], 0.15);
    EXPECT_EQ(sigma[1], 0.1);
}

TEST(CliConvert, OutputsAreByteIdenticalAcrossRunsAndThreadCounts) {
    const auto dir = scratch_dir();
    fs::path in = write_file(dir / "in.opl", small_opl);
    if (!shared_data().empty()) {
        in = shared_data() / "osm" / "gh_harsdorf.osm.pbf"; // multithreaded PBF decoding
    }
    for (const char* threads : {"1", "2", "4"}) {
        const auto r = run_railodd("convert " + quoted(in) + " -o " + quoted(dir / threads) +
                               " --no-timings --debug-outputs --threads " + threads);
        ASSERT_EQ(r.exit_code, 0) << r.output;
    }
    for (const char* name : {"map.xodr", "report.json", "ingest.geojson", "geometry.geojson", "roads.geojson",
                             "odd_profile.json", "odd_profile.geojson", "odd_profile.csv"}) {
        const std::string a = read_file(dir / "1" / name);
        EXPECT_FALSE(a.empty());
        EXPECT_EQ(a, read_file(dir / "2" / name)) << name;
        EXPECT_EQ(a, read_file(dir / "4" / name)) << name;
    }
    EXPECT_EQ(nlohmann::json::parse(read_file(dir / "1" / "report.json")).count("timings_s"), 0u);
}

// A whole network's profile is tagged and written a batch of tracks at a
// time (the page's elements too); with --odd-user-data map.xodr collects
// each element as a <userData> of its road as the batches pass. The profile
// files, page and report are the same either way, and the map carries one
// entry per element of the profile.
TEST(CliConvert, OddUserDataLeavesTheProfileAsItIs) {
    const auto dir = scratch_dir();
    ASSERT_EQ(run_railodd("sample -o " + quoted(dir / "sample")).exit_code, 0);
    for (const char* variant : {"streamed", "whole"}) {
        fs::create_directories(dir / variant);
        const auto r = run_command("cd " + quoted(dir / variant) + " && " + RAILODD_BIN +
                                   " convert ../sample/sample_route.osm -o out --no-timings" +
                                   (std::string{variant} == "whole" ? " --odd-user-data" : ""));
        ASSERT_EQ(r.exit_code, 0) << r.output;
    }
    for (const char* name : {"odd_profile.json", "odd_profile.geojson", "odd_profile.csv", "report.html", "report.json"}) {
        const std::string a = read_file(dir / "streamed" / "out" / name);
        EXPECT_GT(a.size(), 1000u) << name;
        EXPECT_EQ(a, read_file(dir / "whole" / "out" / name)) << name;
    }
    EXPECT_EQ(read_file(dir / "streamed" / "out" / "map.xodr").find("code=\"odd\""), std::string::npos);
    const std::string map = read_file(dir / "whole" / "out" / "map.xodr");
    std::size_t entries = 0;
    for (auto at = map.find("code=\"odd\""); at != std::string::npos; at = map.find("code=\"odd\"", at + 1)) {
        ++entries;
    }
    const auto profile = nlohmann::json::parse(read_file(dir / "whole" / "out" / "odd_profile.json"));
    EXPECT_EQ(entries, profile.at("elements").size());
    EXPECT_FALSE(has_staging_leftovers(dir / "streamed" / "out"));
}

TEST(CliConvert, SampleRouteGeometrySections) {
    const auto dir = scratch_dir();
    ASSERT_EQ(run_railodd("sample -o " + quoted(dir / "sample")).exit_code, 0);
    const auto osm = dir / "sample" / "sample_route.osm";
    const auto dem = dir / "sample" / "sample_route_dem.tif";
    const auto r =
        run_railodd("convert " + quoted(osm) + " -o " + quoted(dir / "out") + " --dem " + quoted(dem) + " --debug-outputs");
    ASSERT_EQ(r.exit_code, 0) << r.output;
    const auto report = nlohmann::json::parse(read_file(dir / "out" / "report.json"));
    EXPECT_EQ(report["geometry"]["summary"]["switch_vertices"], 3);
    EXPECT_EQ(report["geometry"]["summary"]["links"]["corner_chains"], 0);
    EXPECT_EQ(report["geometry"]["summary"]["links"]["beyond_limit_chains"], 0);
    EXPECT_EQ(report["vertical"]["sources"]["dem"], report["geometry"]["summary"]["edges"]);
    EXPECT_EQ(report["cant"]["curves_with_tagged_cant"], 1);
    EXPECT_EQ(report["cant"]["max_cant_mm"], 100.0);
    EXPECT_EQ(report["topology"]["road_rail_crossings"]["at_grade_with_level_crossing_node"], 1);
    EXPECT_EQ(report["topology"]["road_rail_crossings"]["grade_separated"], 1);
    EXPECT_TRUE(report["topology"]["features_unattached"].empty());
    EXPECT_TRUE(fs::exists(dir / "out" / "geometry.geojson"));

    const auto est = run_railodd("convert " + quoted(osm) + " -o " + quoted(dir / "est") + " --estimate-cant");
    ASSERT_EQ(est.exit_code, 0) << est.output;
    const auto report2 = nlohmann::json::parse(read_file(dir / "est" / "report.json"));
    EXPECT_GT(report2["cant"]["curves_with_estimated_cant"], 0);
    EXPECT_EQ(report2["cant"]["max_cant_mm"], 160.0);
    EXPECT_EQ(report2["vertical"]["sources"]["flat"], report2["geometry"]["summary"]["edges"]);
}

// The diagnostic GeoJSON files only with --debug-outputs; a rerun without it
// (or with --no-report) removes what an earlier run left, which would
// describe another map.
TEST(CliConvert, DiagnosticFilesOnlyWhenAskedAndNoStaleOnes) {
    const auto dir = scratch_dir();
    const auto in = write_file(dir / "in.opl", small_opl);
    const auto out = dir / "out";
    const std::vector<std::string> debug = {"ingest.geojson", "geometry.geojson", "roads.geojson"};
    auto r = run_railodd("convert " + quoted(in) + " -o " + quoted(out) + " --no-timings");
    ASSERT_EQ(r.exit_code, 0) << r.output;
    for (const auto& f : debug) {
        EXPECT_FALSE(fs::exists(out / f)) << f;
    }
    EXPECT_TRUE(fs::exists(out / "report.html"));
    const std::string map = read_file(out / "map.xodr");
    r = run_railodd("convert " + quoted(in) + " -o " + quoted(out) + " --no-timings --debug-outputs");
    ASSERT_EQ(r.exit_code, 0) << r.output;
    for (const auto& f : debug) {
        EXPECT_TRUE(fs::exists(out / f)) << f;
        EXPECT_NE(r.output.find(f), std::string::npos) << r.output;
    }
    EXPECT_EQ(read_file(out / "map.xodr"), map); // the flag changes no other output
    r = run_railodd("convert " + quoted(in) + " -o " + quoted(out) + " --no-timings --no-report");
    ASSERT_EQ(r.exit_code, 0) << r.output;
    for (const auto& f : debug) {
        EXPECT_FALSE(fs::exists(out / f)) << f;
    }
    EXPECT_FALSE(fs::exists(out / "report.html"));
    EXPECT_EQ(read_file(out / "map.xodr"), map);
}
