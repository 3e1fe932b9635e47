// Template files whose values make no sense, and a cover strategy asked for
// fewer scenarios than its array holds, through `railodd scenarios` on the
// sample route: each nonsense value is refused naming the file and the field
// (exit 2) before anything is written, and --count caps every strategy.
#include "test_support.hpp"

#include <nlohmann/json.hpp>

#include <map>
#include <string>
#include <tuple>
#include <vector>

using namespace railodd::test;

namespace {

CommandResult run_railodd(const std::string& args) { return run_command(std::string{RAILODD_BIN} + " " + args); }

const fs::path data_dir = fs::path{RAILODD_SOURCE_DIR} / "data";

class ScenarioHostileTemplates : public ::testing::Test {
protected:
    static fs::path root() {
        return fs::temp_directory_path() / "railodd-tests" / ("ScenarioHostileTemplates-" + std::to_string(::getpid()));
    }
    static fs::path map() { return root() / "map"; }
    static void SetUpTestSuite() {
        fs::remove_all(root());
        fs::create_directories(root());
        ASSERT_EQ(run_railodd("sample -o " + quoted(root() / "sample")).exit_code, 0);
        const auto c = run_railodd("convert " + quoted(root() / "sample" / "sample_route.osm") + " -o " + quoted(map()) +
                                   " --no-timings --no-report");
        ASSERT_EQ(c.exit_code, 0) << c.output;
    }
    static void TearDownTestSuite() { fs::remove_all(root()); }

    // The shipped templates with `from` (in the first template) replaced by `to`.
    static fs::path templates_with(const fs::path& dir, const std::string& from, const std::string& to) {
        std::string t = read_file(data_dir / "scenario" / "templates.yaml");
        const auto at = t.find(from);
        EXPECT_NE(at, std::string::npos) << from;
        return write_file(dir / "templates.yaml", t.replace(at, from.size(), to));
    }
    static CommandResult scenarios(const fs::path& templates, const fs::path& out, const std::string& more) {
        return run_railodd("scenarios --map " + quoted(map()) + " --templates " + quoted(templates) + " -o " +
                           quoted(out) + " --quiet " + more);
    }
};

const std::string speed_line = "      speed: {kind: ego_speed, values: [40, 80, 120]}\n";

std::string choice(const std::string& name, int n) {
    std::string values;
    for (int i = 0; i < n; ++i) {
        values += (i ? ", v" : "v") + std::to_string(i);
    }
    return "      " + name + ": {kind: choice, values: [" + values + "]}\n";
}

} // namespace

TEST_F(ScenarioHostileTemplates, NonsenseValuesAreRefusedNamingFileAndField) {
    const std::vector<std::tuple<std::string, std::string, std::string>> cases = {
        {"hazard_before_m: 300", "hazard_before_m: -500", "'hazard_before_m' must be from 0"},
        {"move_speed_kmh: 10\n        hazard_before_m: 300", "move_speed_kmh: 1e-300\n        hazard_before_m: 300",
         "'move_speed_kmh' must be from 0.1"},
        {speed_line, speed_line + "      EgoSpeed: {kind: choice, values: [a, b]}\n", "'EgoSpeed' is one railodd declares"},
        {speed_line, speed_line + "      street_vehicle_asset: {kind: choice, values: [a]}\n",
         "'StreetVehicleAsset' is one railodd declares"},
        {speed_line, speed_line + "      mode: {kind: degraded_mode, values: [dense_fog, dense_fog]}\n",
         "'dense_fog' is listed twice"},
    };
    const fs::path dir = scratch_dir();
    for (const auto& [from, to, says] : cases) {
        SCOPED_TRACE(to);
        const fs::path templates = templates_with(dir, from, to), out = dir / "out";
        const auto r = scenarios(templates, out, "--strategy random --count 1");
        EXPECT_EQ(r.exit_code, 2) << r.output;
        EXPECT_NE(r.output.find(templates.string()), std::string::npos) << r.output;
        EXPECT_NE(r.output.find(says), std::string::npos) << r.output;
        EXPECT_FALSE(fs::exists(out));
    }
}

// Two choices of 30 values make a cover array of 900 rows: --count 10 keeps 10.
TEST_F(ScenarioHostileTemplates, CoverHonoursCount) {
    const fs::path dir = scratch_dir();
    const fs::path templates =
        templates_with(dir, speed_line, speed_line + choice("aspect_a", 30) + choice("aspect_b", 30));
    const fs::path out = dir / "out";
    const auto r = scenarios(templates, out, "--strategy cover --count 10");
    ASSERT_EQ(r.exit_code, 0) << r.output;
    const auto m = nlohmann::json::parse(read_file(out / "manifest.json"));
    std::map<std::string, int> per_template;
    for (const auto& s : m["scenarios"]) {
        ++per_template[s["template"].get<std::string>()];
    }
    EXPECT_GT(per_template["curve_crossing_street_vehicle"], 0);
    for (const auto& [t, n] : per_template) {
        EXPECT_LE(n, 10) << t;
    }
}
