// `railodd profile` as a user runs it: summary, verdict against a spec, JSON,
// exit codes 0 / 5 / 2 / 1.
#include "railodd/odd/profile.hpp"

#include "odd_profile_support.hpp"
#include "test_support.hpp"

#include <nlohmann/json.hpp>

using namespace railodd::test;

namespace {

CommandResult run_railodd(const std::string& args) { return run_command(std::string{RAILODD_BIN} + " " + args); }

const fs::path example_spec = fs::path{RAILODD_SOURCE_DIR} / "data/odd/example_odd_spec.yaml";

fs::path map_dir() {
    const auto dir = scratch_dir();
    write_file(dir / "odd_profile.json", railodd::odd::to_json(sample_profile()).dump(1));
    return dir;
}

} // namespace

TEST(CliProfile, SummaryWithoutSpecExitsZero) {
    const auto r = run_railodd("profile " + quoted(map_dir()));
    EXPECT_EQ(r.exit_code, 0) << r.output;
    EXPECT_NE(r.output.find("route: test route"), std::string::npos) << r.output;
    EXPECT_NE(r.output.find("1.60 km"), std::string::npos) << r.output;
    EXPECT_NE(r.output.find("curves by radius class (km)"), std::string::npos) << r.output;
    EXPECT_EQ(r.output.find("ODD spec"), std::string::npos) << r.output;
}

TEST(CliProfile, ExampleSpecOutsideExitsFiveListingViolations) {
    const auto r = run_railodd("profile " + quoted(map_dir()) + " --odd-spec " + quoted(example_spec));
    EXPECT_EQ(r.exit_code, 5) << r.output;
    EXPECT_NE(r.output.find("verdict: OUTSIDE ODD"), std::string::npos) << r.output;
    EXPECT_NE(r.output.find("track 0 ch 100.0-350.0 m  road 12 s 100.0-350.0  Scenery/Track geometry/Horizontal/"
                            "Curve: radius 250 m, spec radius >= 300 m"),
              std::string::npos)
        << r.output;
    EXPECT_NE(r.output.find("Level crossing: barrier no, spec barrier in [half, double_half, full, gate]"),
              std::string::npos)
        << r.output;
    EXPECT_NE(r.output.find("osm node:5"), std::string::npos) << r.output;
    EXPECT_NE(r.output.find("gradient 30 permille"), std::string::npos) << r.output;
}

TEST(CliProfile, PermissiveSpecInsideExitsZero) {
    const auto dir = map_dir();
    const auto spec = write_file(dir / "spec.yaml", "odd_spec: permissive\nelements:\n"
                                                    "  - path: Scenery/Track geometry/Horizontal/Curve\n"
                                                    "    attributes:\n      radius: {min: 150}\n");
    const auto r = run_railodd("profile " + quoted(dir) + " --odd-spec " + quoted(spec));
    EXPECT_EQ(r.exit_code, 0) << r.output;
    EXPECT_NE(r.output.find("verdict: IN ODD"), std::string::npos) << r.output;
}

TEST(CliProfile, JsonVerdict) {
    const auto r = run_railodd("profile --json " + quoted(map_dir()) + " --odd-spec " + quoted(example_spec));
    EXPECT_EQ(r.exit_code, 5) << r.output;
    const auto j = nlohmann::json::parse(r.output);
    EXPECT_FALSE(j["odd_spec"]["passed"].get<bool>());
    ASSERT_EQ(j["odd_spec"]["violations"].size(), 3u);
    EXPECT_EQ(j["odd_spec"]["violations"][1]["road_id"], "12");
    EXPECT_DOUBLE_EQ(j["summary"]["curve_km_by_radius"]["tight"].get<double>(), 0.25);
}

TEST(CliProfile, BadInputExitsTwoNamingTheFile) {
    const auto dir = scratch_dir();
    const auto bad = write_file(dir / "odd_profile.json", "{\"taxonomy\": {");
    const auto r = run_railodd("profile " + quoted(dir));
    EXPECT_EQ(r.exit_code, 2) << r.output;
    EXPECT_NE(r.output.find(bad.string()), std::string::npos) << r.output;
    const auto missing = run_railodd("profile " + quoted(dir / "nowhere"));
    EXPECT_EQ(missing.exit_code, 2) << missing.output;
    EXPECT_NE(missing.output.find("nowhere"), std::string::npos) << missing.output;
    const auto no_spec = run_railodd("profile " + quoted(map_dir()) + " --odd-spec " + quoted(dir / "none.yaml"));
    EXPECT_EQ(no_spec.exit_code, 2) << no_spec.output;
}

TEST(CliProfile, UsageErrorsExitOne) {
    EXPECT_EQ(run_railodd("profile").exit_code, 1);
    EXPECT_EQ(run_railodd("profile " + quoted(map_dir()) + " --no-such-option").exit_code, 1);
}
