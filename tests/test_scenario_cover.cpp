// `railodd scenarios --strategy cover` (the default) on the sample route as the
// demo converts it (DEM, cant): every element and class of the route and every
// item of the declared ODD the route can host is exercised, every gap says
// why, the set is a fraction of pairwise, seeds change the choice but not the
// coverage, and degraded modes reach the .xosc, the behaviour file and the
// manifest.
#include "test_support.hpp"

#include <nlohmann/json.hpp>
#include <pugixml.hpp>

#include <map>
#include <set>

#include <unistd.h>

using namespace railodd::test;
using json = nlohmann::json;

namespace {

const fs::path data_dir = fs::path{RAILODD_SOURCE_DIR} / "data";

CommandResult run_railodd(const std::string& args) { return run_command(std::string{RAILODD_BIN} + " " + args); }

json read_json(const fs::path& p) { return json::parse(read_file(p)); }

class ScenarioCover : public ::testing::Test {
protected:
    static fs::path root() {
        return fs::temp_directory_path() / "railodd-tests" / ("ScenarioCover-" + std::to_string(::getpid()));
    }
    static fs::path map() { return root() / "map"; }
    static void TearDownTestSuite() { fs::remove_all(root()); }
    static void SetUpTestSuite() {
        fs::remove_all(root());
        fs::create_directories(root());
        const auto s = run_railodd("sample -o " + quoted(root() / "sample"));
        ASSERT_EQ(s.exit_code, 0) << s.output;
        const auto c = run_railodd("convert " + quoted(root() / "sample" / "sample_route.osm") + " -o " + quoted(map()) +
                                   " --dem " + quoted(root() / "sample" / "sample_route_dem.tif") +
                                   " --node-noise 0.3 --estimate-cant --no-timings");
        ASSERT_EQ(c.exit_code, 0) << c.output;
    }
    static CommandResult scenarios(const fs::path& out, const std::string& extra = "") {
        return run_railodd("scenarios --map " + quoted(map()) + " -o " + quoted(out) + " -q " + extra);
    }
};

const std::vector<std::string> reason_starts = {"not on the route", "excluded by the ODD spec", "no anchor on the route",
                                                "not drawn", "no template"};

bool known_reason(const std::string& r) {
    for (const auto& s : reason_starts) {
        if (r.rfind(s, 0) == 0) {
            return true;
        }
    }
    return false;
}

} // namespace

TEST_F(ScenarioCover, EveryRouteClassAndHostableSpecItemIsCovered) {
    const fs::path out = root() / "cover";
    const auto r = scenarios(out, "--odd-spec " + quoted(data_dir / "odd" / "example_odd_spec.yaml"));
    ASSERT_EQ(r.exit_code, 0) << r.output;
    const json c = read_json(out / "coverage.json");
    const double route = c["route"]["ratio"];
    EXPECT_GE(route, 0.95) << c["route"]["covered"] << " of " << c["route"]["items"];
    EXPECT_GT(c["route"]["items"].get<int>(), 80) << "the sample route has switches, signals, bridges, a buffer stop";
    // The spec: every item the route can host is exercised.
    EXPECT_EQ(c["spec"]["covered"], c["spec"]["hostable"]);
    EXPECT_LT(c["spec"]["hostable"].get<int>(), c["spec"]["items"].get<int>()) << "the sample has no ETCS";
    for (const auto& g : c["gaps"]) {
        EXPECT_TRUE(known_reason(g["reason"])) << g.dump();
        if (g["in"] == "spec") {
            EXPECT_EQ(g["reason"], "not on the route") << g.dump();
            EXPECT_EQ(g["on_route"], 0) << g.dump();
        }
    }
    // coverage.txt says why under each gap.
    const std::string txt = read_file(out / "coverage.txt");
    EXPECT_NE(txt.find("GAP "), std::string::npos);
    EXPECT_NE(txt.find("        not on the route"), std::string::npos);
    // At most a third of pairwise over all anchors; every template that has
    // anchors takes part, with every feasible pair of its parameters.
    const json& sel = c["selection"];
    EXPECT_EQ(sel["strategy"], "cover");
    EXPECT_LE(3 * sel["scenarios"].get<int>(), sel["pairwise_scenarios"].get<int>());
    EXPECT_LT(sel["pairwise_scenarios"].get<double>(), sel["full_factorial_scenarios"].get<double>());
    const json m = read_json(out / "manifest.json");
    std::map<std::string, int> per_template;
    for (const auto& s : m["scenarios"]) {
        ++per_template[s["template"]];
    }
    for (const auto& t : c["templates"]) {
        EXPECT_EQ(t["pairs_covered"], t["pairs_feasible"]) << t["template"];
        if (t["anchors"].get<int>() > 0) {
            EXPECT_GT(per_template[t["template"]], 0) << t["template"];
        }
    }
}

TEST_F(ScenarioCover, OtherSeedsChooseOtherAnchorsWithTheSameCoverage) {
    std::map<std::string, std::string> first;
    std::set<std::string> anchor_sets;
    for (const int seed : {1, 2, 7}) {
        const fs::path out = root() / ("seed" + std::to_string(seed));
        ASSERT_EQ(scenarios(out, "--seed " + std::to_string(seed)).exit_code, 0);
        const json c = read_json(out / "coverage.json");
        EXPECT_GE(c["route"]["ratio"].get<double>(), 0.95) << "seed " << seed;
        std::string anchors;
        const json m = read_json(out / "manifest.json");
        for (const auto& s : m["scenarios"]) {
            anchors += s["template"].get<std::string>() + "@" + s["anchor"]["track"].dump() + ":" +
                       s["anchor"]["chainage"].dump() + ";";
        }
        anchor_sets.insert(anchors);
    }
    EXPECT_GT(anchor_sets.size(), 1u) << "the seed orders ties of the set cover";
    // Same seed, same bytes.
    ASSERT_EQ(scenarios(root() / "again", "--seed 2").exit_code, 0);
    for (const auto& e : fs::recursive_directory_iterator(root() / "seed2")) {
        if (e.is_regular_file()) {
            const auto rel = fs::relative(e.path(), root() / "seed2");
            EXPECT_EQ(read_file(e.path()), read_file(root() / "again" / rel)) << rel;
        }
    }
}

// A degraded mode without an OpenSCENARIO action (GNSS, train radio, the
// lens) is a string parameter and a behaviour-file condition; one with a
// mapping (fog) sets the environment; both are in the manifest's ODD values.
TEST_F(ScenarioCover, DegradedModesReachTheScenarioTheBehaviourFileAndTheManifest) {
    const fs::path out = root() / "modes";
    ASSERT_EQ(scenarios(out, "--strategy pairwise").exit_code, 0);
    const json m = read_json(out / "manifest.json");
    std::set<std::string> seen;
    for (const auto& s : m["scenarios"]) {
        if (!s["parameters"].contains("degraded")) {
            continue;
        }
        const std::string mode = s["parameters"]["degraded"]["value"];
        seen.insert(mode);
        pugi::xml_document doc;
        ASSERT_TRUE(doc.load_file((out / s["file"].get<std::string>()).c_str()));
        auto param = [&](const char* name) {
            return std::string(
                doc.select_node(("//ParameterDeclaration[@name='" + std::string(name) + "']").c_str()).node().attribute("value").value());
        };
        EXPECT_EQ(param("DegradedMode"), mode) << s["id"];
        const std::string behaviour = read_file(out / s["behavior"].get<std::string>());
        EXPECT_NE(behaviour.find("degraded_mode: " + mode), std::string::npos) << s["id"];
        std::set<std::string> mode_values;
        for (const auto& v : s["odd_elements"]) {
            if (v["source"] == "degraded_mode" && !v["attribute"].get<std::string>().empty()) {
                mode_values.insert(v["element"].get<std::string>() + "|" + v["attribute"].get<std::string>() + "=" +
                                   v["value"].get<std::string>());
            }
        }
        if (mode == "gnss_loss") {
            EXPECT_EQ(param("GNSSAvailability"), "unavailable") << s["id"];
            EXPECT_NE(behaviour.find("Connectivity/Positioning/GNSS availability: unavailable"), std::string::npos);
            EXPECT_TRUE(mode_values.contains("Connectivity/Positioning/GNSS|availability=unavailable")) << s["id"];
        } else if (mode == "radio_loss") {
            EXPECT_EQ(param("TrainRadioCoverage"), "none") << s["id"];
            EXPECT_TRUE(mode_values.contains("Connectivity/Communication/Train radio|coverage=none")) << s["id"];
        } else if (mode == "dense_fog") {
            EXPECT_EQ(param("FogVisualRange"), "80") << s["id"];
            EXPECT_TRUE(doc.select_node("//Fog[@visualRange='$FogVisualRange']")) << s["id"];
            EXPECT_TRUE(mode_values.contains("Environmental Conditions/Particulates/Fog|visibility=80")) << s["id"];
        } else if (mode == "dirty_lens") {
            EXPECT_EQ(param("LensCondition"), "dirty") << s["id"];
        } else if (mode == "none") {
            EXPECT_TRUE(mode_values.empty()) << s["id"];
        }
    }
    for (const char* mode : {"none", "gnss_loss", "radio_loss", "dense_fog", "dirty_lens", "low_adhesion"}) {
        EXPECT_TRUE(seen.contains(mode)) << mode;
    }
}

// Each reason is given where it applies: a template set of the level
// crossing alone leaves the buffer stop to "no template", --max-anchors under
// pairwise leaves classes "not drawn".
TEST_F(ScenarioCover, GapsSayWhy) {
    const fs::path dir = scratch_dir();
    // The shipped file cut after its first template (the paper's level crossing).
    std::string t = read_file(data_dir / "scenario" / "templates.yaml");
    const auto second = t.find("\n  - id: ", t.find("\n  - id: curve_crossing_street_vehicle") + 1);
    ASSERT_NE(second, std::string::npos);
    t.erase(second + 1);
    write_file(dir / "templates.yaml", t);
    ASSERT_EQ(scenarios(dir / "a", "--templates " + quoted(dir / "templates.yaml")).exit_code, 0);
    std::map<std::string, std::string> why;
    const json a = read_json(dir / "a" / "coverage.json");
    for (const auto& g : a["gaps"]) {
        why[g["element"].get<std::string>() + "|" + g["attribute"].get<std::string>() + "=" + g["class"].get<std::string>()] =
            g["reason"];
    }
    ASSERT_TRUE(why.contains("Scenery/Track layout/Buffer stop|="));
    EXPECT_EQ(why["Scenery/Track layout/Buffer stop|="].rfind("no template anchors on this element", 0), 0u);

    ASSERT_EQ(scenarios(dir / "b", "--strategy pairwise --max-anchors 1").exit_code, 0);
    const json b = read_json(dir / "b" / "coverage.json");
    std::size_t not_drawn = 0;
    for (const auto& g : b["gaps"]) {
        not_drawn += g["reason"].get<std::string>().rfind("not drawn", 0) == 0 ? 1 : 0;
        EXPECT_TRUE(known_reason(g["reason"])) << g.dump();
    }
    EXPECT_GT(not_drawn, 0u);

}

// At a facing switch the through template runs on along the main track and
// the diverging one onto the branch: their routes part at the switch, and the
// diverging run's obstacle stands on a road only the diverging run takes. At
// a trailing switch the stock stands on the joining track, off the route.
TEST_F(ScenarioCover, DivergingRunTakesTheSwitchsBranch) {
    const fs::path out = root() / "switch";
    ASSERT_EQ(scenarios(out, "--strategy pairwise").exit_code, 0);
    const json m = read_json(out / "manifest.json");
    std::map<std::string, std::vector<std::string>> through, diverging; // switch node -> route roads
    std::map<std::string, std::string> obstacle;
    for (const auto& s : m["scenarios"]) {
        const std::string node = s["anchor"]["osm_ids"][0];
        const auto roads = s["ego"]["route_roads"].get<std::vector<std::string>>();
        if (s["template"] == "facing_switch_obstacle") {
            through[node] = roads;
        } else if (s["template"] == "trailing_switch_stabled_stock") {
            // The stock stands on the joining track: a road the train does not run on.
            const std::string stock = s["actors"][0]["start"]["road_id"];
            EXPECT_EQ(std::find(roads.begin(), roads.end(), stock), roads.end()) << s["id"];
            EXPECT_EQ(s["actors"][0]["place"], "branch_track");
        } else if (s["template"] == "facing_switch_diverging") {
            diverging[node] = roads;
            obstacle[node] = s["actors"][0]["start"]["road_id"];
            EXPECT_LE(s["ego"]["speed_kmh"].get<double>(), 60.0 + 1e-6) << s["id"];
        }
    }
    ASSERT_FALSE(diverging.empty());
    for (const auto& [node, roads] : diverging) {
        ASSERT_TRUE(through.contains(node)) << node;
        EXPECT_NE(roads, through[node]) << node;
        EXPECT_EQ(roads.front(), through[node].front()) << node << ": the same run-up";
        EXPECT_NE(std::find(roads.begin(), roads.end(), obstacle[node]), roads.end()) << node;
        EXPECT_EQ(std::find(through[node].begin(), through[node].end(), obstacle[node]), through[node].end()) << node;
    }
}
