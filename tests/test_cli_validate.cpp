// `railodd validate` as a user runs it: verdict text, JSON, exit codes 0 / 5 / 2 / 1.
#include "test_support.hpp"
#include "xodr_check_support.hpp"

#include <nlohmann/json.hpp>

using namespace railodd::test;

namespace {

CommandResult run_railodd(const std::string& args) { return run_command(std::string{RAILODD_BIN} + " " + args); }

std::string alignment_doc(double arc_shift_m) {
    auto recs = rail_alignment({100.0, 50.0, 0.2, 0.0});
    recs[2].start.x += arc_shift_m;
    return document(road_xml({"1", total_length(recs), geometries_xml(recs)}));
}

} // namespace

TEST(CliValidate, GoodFilePassesWithExitZero) {
    const auto file = write_file(scratch_dir() / "good.xodr", alignment_doc(0.0));
    const auto r = run_railodd("validate " + quoted(file));
    EXPECT_EQ(r.exit_code, 0) << r.output;
    EXPECT_NE(r.output.find("PASS"), std::string::npos) << r.output;
    EXPECT_NE(r.output.find("roads: 1 (1 rail)"), std::string::npos) << r.output;
    EXPECT_NE(r.output.find("max gap:"), std::string::npos) << r.output;
    EXPECT_EQ(r.output.find("FAIL"), std::string::npos) << r.output;
}

TEST(CliValidate, BadFileFailsWithExitFiveNamingRoadAndCheck) {
    const auto file = write_file(scratch_dir() / "bad.xodr", alignment_doc(0.005));
    const auto r = run_railodd("validate " + quoted(file));
    EXPECT_EQ(r.exit_code, 5) << r.output;
    EXPECT_NE(r.output.find("FAIL"), std::string::npos) << r.output;
    EXPECT_NE(r.output.find("road 1 s=160.000  geometry_gap"), std::string::npos) << r.output;
    EXPECT_NE(r.output.find("EXCEEDED"), std::string::npos) << r.output;
}

TEST(CliValidate, JsonVerdict) {
    const auto file = write_file(scratch_dir() / "bad.xodr", alignment_doc(0.005));
    const auto r = run_railodd("validate --json " + quoted(file));
    EXPECT_EQ(r.exit_code, 5) << r.output;
    const auto j = nlohmann::json::parse(r.output);
    EXPECT_FALSE(j["passed"].get<bool>());
    EXPECT_EQ(j["summary"]["roads"], 1);
    EXPECT_EQ(j["summary"]["geometries_by_kind"]["spiral"], 2);
    ASSERT_GE(j["findings"].size(), 1u);
    EXPECT_EQ(j["findings"][0]["check"], "geometry_gap");
    EXPECT_EQ(j["findings"][0]["id"], "1");
    EXPECT_DOUBLE_EQ(j["findings"][0]["s"].get<double>(), 160.0);
    EXPECT_DOUBLE_EQ(j["summary"]["max_gap_m"]["limit"].get<double>(), 1e-3);
}

TEST(CliValidate, UnreadableFileExitsTwoNamingIt) {
    const auto dir = scratch_dir();
    const auto missing = run_railodd("validate " + quoted(dir / "nope.xodr"));
    EXPECT_EQ(missing.exit_code, 2) << missing.output;
    EXPECT_NE(missing.output.find((dir / "nope.xodr").string() + ": no such file"), std::string::npos) << missing.output;
    const auto broken = write_file(dir / "broken.xodr", "<OpenDRIVE><header revMajor=");
    const auto r = run_railodd("validate " + quoted(broken));
    EXPECT_EQ(r.exit_code, 2) << r.output;
    EXPECT_NE(r.output.find(broken.string()), std::string::npos) << r.output;
}

TEST(CliValidate, UsageErrorsExitOne) {
    EXPECT_EQ(run_railodd("validate").exit_code, 1);
    const auto file = write_file(scratch_dir() / "good.xodr", alignment_doc(0.0));
    const auto r = run_railodd("validate " + quoted(file) + " --xsd-dir /nonexistent-railodd-dir");
    EXPECT_EQ(r.exit_code, 1) << r.output;
}

TEST(CliValidate, NetconvertImportsTheRailRoad) {
    if (run_command("command -v netconvert").exit_code != 0) {
        GTEST_SKIP() << "netconvert (SUMO) is not installed: skipping";
    }
    const auto file = write_file(scratch_dir() / "good.xodr", alignment_doc(0.0));
    const auto r = run_railodd("validate --json --netconvert " + quoted(file));
    EXPECT_EQ(r.exit_code, 0) << r.output;
    const auto j = nlohmann::json::parse(r.output);
    EXPECT_TRUE(j["netconvert"]["passed"].get<bool>()) << r.output;
    EXPECT_GE(j["netconvert"]["rail_edges"].get<int>(), 1) << r.output;
}
