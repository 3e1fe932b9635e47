// JSON that `report` and `merge` read back from other commands' folders,
// made hostile: nested a million levels deep, fields of the wrong type, and
// an output that cannot be placed. Each must end as bad input (exit 2) or an
// output problem (exit 3) naming the file, never as a crash or exit 4, and a
// failed run must leave the folders it wrote into usable.
#include "test_support.hpp"

#include <nlohmann/json.hpp>

#include <string>
#include <vector>

using namespace railodd::test;
using ojson = nlohmann::ordered_json;

namespace {

CommandResult run_railodd(const std::string& args) { return run_command(std::string{RAILODD_BIN} + " " + args); }

class CliHostileReadback : public ::testing::Test {
protected:
    static fs::path root() {
        return fs::temp_directory_path() / "railodd-tests" / ("CliHostileReadback-" + std::to_string(::getpid()));
    }
    static void SetUpTestSuite() {
        fs::remove_all(root());
        fs::create_directories(root());
        ASSERT_EQ(run_railodd("sample -o " + quoted(root() / "sample")).exit_code, 0);
        auto c = run_railodd("convert " + quoted(root() / "sample" / "sample_route.osm") + " -o " + quoted(root() / "map") +
                             " --no-timings");
        ASSERT_EQ(c.exit_code, 0) << c.output;
        c = run_railodd("scenarios --map " + quoted(root() / "map") + " -o " + quoted(root() / "scen") +
                        " --strategy random --count 1 --quiet");
        ASSERT_EQ(c.exit_code, 0) << c.output;
    }
    static void TearDownTestSuite() { fs::remove_all(root()); }

    // A copy of the map and scenario folders with `file` (relative to the copy) replaced.
    static fs::path copy_with(const std::string& file, const std::string& content) {
        const fs::path dir = scratch_dir();
        fs::copy(root() / "map", dir / "map", fs::copy_options::recursive);
        fs::copy(root() / "scen", dir / "scen", fs::copy_options::recursive);
        write_file(dir / file, content);
        return dir;
    }
    static std::string report_of(const fs::path& dir, const std::string& more = "") {
        return "report " + quoted(dir / "map") + " --scenarios " + quoted(dir / "scen") + " -o " +
               quoted(dir / "out" / "r.html") + more;
    }
};

void expect_input_error(const CommandResult& r, const std::vector<std::string>& says) {
    EXPECT_EQ(r.exit_code, 2) << r.output;
    for (const auto& s : says) {
        EXPECT_NE(r.output.find(s), std::string::npos) << "missing '" << s << "' in: " << r.output;
    }
}

std::string with(const fs::path& file, const std::string& pointer, const ojson& value) {
    ojson j = ojson::parse(read_file(file));
    j[ojson::json_pointer(pointer)] = value;
    return j.dump();
}

} // namespace

TEST_F(CliHostileReadback, DeeplyNestedFilesAreRefusedNamingThem) {
    const std::string deep(1000000, '[');
    for (const std::string file : {"scen/coverage.json", "map/report.json", "scen/manifest.json"}) {
        SCOPED_TRACE(file);
        const fs::path dir = copy_with(file, deep);
        expect_input_error(run_railodd(report_of(dir)), {file.substr(file.find('/') + 1), "nested deeper"});
        EXPECT_FALSE(fs::exists(dir / "out"));
    }
}

TEST_F(CliHostileReadback, WronglyTypedFieldsAreInputErrorsWithTheirPath) {
    const std::vector<std::pair<std::string, std::string>> cases = {
        {"map/report.json", "/geometry"},
        {"scen/manifest.json", "/scenarios/0/anchor/s"},
        {"scen/coverage.json", "/templates"},
    };
    for (const auto& [file, pointer] : cases) {
        SCOPED_TRACE(file + pointer);
        const fs::path dir = copy_with(file, with(root() / file, pointer, "x"));
        expect_input_error(run_railodd(report_of(dir)), {file.substr(file.find('/') + 1) + ": " + pointer});
    }
    const fs::path dir = copy_with("scen/play.json", R"({"scenarios": [{"id": "a", "passed": "yes"}]})");
    expect_input_error(run_railodd(report_of(dir)), {"play.json: /scenarios/0/passed"});
}

// -o naming a folder: refused, and the folder above it is left without a
// journal or staging folder, so the next run into it works.
TEST_F(CliHostileReadback, AFailedReportLeavesTheFolderAboveUsable) {
    const fs::path dir = scratch_dir();
    fs::create_directories(dir / "out" / "taken");
    const auto r = run_railodd("report " + quoted(root() / "map") + " -o " + quoted(dir / "out" / "taken"));
    EXPECT_EQ(r.exit_code, 3) << r.output;
    EXPECT_NE(r.output.find("taken"), std::string::npos) << r.output;
    for (const auto& e : fs::directory_iterator(dir / "out")) {
        EXPECT_EQ(e.path().filename(), "taken");
    }
    const auto again = run_railodd("report " + quoted(root() / "map") + " -o " + quoted(dir / "out" / "r.html"));
    EXPECT_EQ(again.exit_code, 0) << again.output;
}

// merge reads every route's odd_profile.json summary: 300,000 nested objects
// once overflowed its stack in the recursive merge.
TEST_F(CliHostileReadback, MergeRefusesADeeplyNestedProfileSummary) {
    const fs::path dir = scratch_dir();
    write_file(dir / "batch_summary.json",
               R"({"railodd": {"format": "batch_summary", "format_version": 1}, "routes_file": "r.yaml",
                   "routes_file_hash": "0", "routes_total": 1, "shard": {"index": 0, "count": 1},
                   "routes": [{"id": "r", "status": "ok", "scenarios": false}]})");
    fs::create_directories(dir / "r");
    std::string summary;
    for (int i = 0; i < 300000; ++i) {
        summary += R"({"a": )";
    }
    summary += "1" + std::string(300000, '}');
    write_file(dir / "r" / "odd_profile.json",
               R"({"railodd": {"format": "odd_profile", "format_version": 2}, "summary": )" + summary + "}");
    expect_input_error(run_railodd("merge " + quoted(dir)), {"odd_profile.json", "nested deeper"});
}

TEST_F(CliHostileReadback, MergeListsManyMissingShardsAndBatchCapsTheCount) {
    const fs::path dir = scratch_dir();
    write_file(dir / "batch_summary.shard-0-of-10000.json",
               R"({"railodd": {"format": "batch_summary", "format_version": 1}, "routes_file": "r.yaml",
                   "routes_file_hash": "0", "routes_total": 0, "shard": {"index": 0, "count": 10000}, "routes": []})");
    const auto r = run_railodd("merge " + quoted(dir));
    EXPECT_EQ(r.exit_code, 2) << r.output;
    EXPECT_EQ(ojson::parse(read_file(dir / "batch_merged.json"))["shards"]["missing"].size(), 9999u);
    write_file(dir / "batch_summary.shard-0-of-10000.json",
               R"({"railodd": {"format": "batch_summary", "format_version": 1}, "routes_file": "r.yaml",
                   "routes_file_hash": "0", "routes_total": 0, "shard": {"index": 0, "count": 10001}, "routes": []})");
    expect_input_error(run_railodd("merge " + quoted(dir)), {"not a shard of a batch run"});
    const auto b = run_railodd("batch " + quoted(dir / "routes.yaml") + " -o " + quoted(dir / "out") + " --shard 0/999999");
    EXPECT_EQ(b.exit_code, 1) << b.output;
    EXPECT_NE(b.output.find("N <= 10000"), std::string::npos) << b.output;
}
