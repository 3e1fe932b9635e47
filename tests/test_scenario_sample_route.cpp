// `railodd scenarios` on the embedded sample route, as a user runs it after
// `railodd convert`: every file valid against the OpenSCENARIO 1.2 schema,
// every road, lane and s it names present in the map, anchors that satisfy
// their templates, full pairwise coverage, determinism and clean failures.
#include "odd_profile_rows.hpp"
#include "test_support.hpp"

#include <nlohmann/json.hpp>
#include <pugixml.hpp>

#include <cmath>
#include <map>
#include <set>

#include <unistd.h>

using namespace railodd::test;
using json = nlohmann::json;

namespace {

CommandResult run_railodd(const std::string& args) { return run_command(std::string{RAILODD_BIN} + " " + args); }

// The sample route converted once for the whole suite.
class ScenarioSampleRoute : public ::testing::Test {
protected:
    // One folder per process: CTest runs each test of the suite in its own
    // process, in parallel with -j.
    static fs::path root() {
        return fs::temp_directory_path() / "railodd-tests" / ("ScenarioSampleRoute-" + std::to_string(::getpid()));
    }
    static void TearDownTestSuite() { fs::remove_all(root()); }
    static fs::path map() { return root() / "map"; }

    static void SetUpTestSuite() {
        fs::remove_all(root());
        fs::create_directories(root());
        const auto s = run_railodd("sample -o " + quoted(root() / "sample"));
        ASSERT_EQ(s.exit_code, 0) << s.output;
        const auto c = run_railodd("convert " + quoted(root() / "sample" / "sample_route.osm") + " -o " +
                                   quoted(map()) + " --no-timings");
        ASSERT_EQ(c.exit_code, 0) << c.output;
    }

    static CommandResult scenarios(const fs::path& out, const std::string& extra = "") {
        return run_railodd("scenarios --map " + quoted(map()) + " -o " + quoted(out) + " -q " + extra);
    }
};

json read_json(const fs::path& p) { return json::parse(read_file(p)); }

std::vector<fs::path> files_in(const fs::path& dir, const std::string& ext) {
    std::vector<fs::path> out;
    for (const auto& e : fs::recursive_directory_iterator(dir)) {
        if (e.is_regular_file() && e.path().extension() == ext) {
            out.push_back(e.path());
        }
    }
    std::sort(out.begin(), out.end());
    return out;
}

struct MapRoad {
    double length = 0.0;
    std::set<int> lanes;
};

std::map<std::string, MapRoad> read_map(const fs::path& xodr) {
    pugi::xml_document doc;
    EXPECT_TRUE(doc.load_file(xodr.c_str()));
    std::map<std::string, MapRoad> roads;
    for (const auto& r : doc.child("OpenDRIVE").children("road")) {
        MapRoad& m = roads[r.attribute("id").value()];
        m.length = r.attribute("length").as_double();
        for (const auto& lane : r.select_nodes(".//lane")) {
            m.lanes.insert(lane.node().attribute("id").as_int());
        }
    }
    return roads;
}

std::string resolved(const pugi::xml_document& doc, const std::string& value) {
    if (value.empty() || value[0] != '$') {
        return value;
    }
    for (const auto& p : doc.child("OpenSCENARIO").child("ParameterDeclarations").children()) {
        if (value.substr(1) == p.attribute("name").value()) {
            return p.attribute("value").value();
        }
    }
    return value;
}

// The street vehicle starts on the crossing road's own lane (the profile
// names the road, its s at the crossing and its lanes), 10 m before the
// crossing, and its path ends where the road meets the track.
void street_vehicle_on_the_road(const fs::path& xosc, const json& anchor, const json& profile) {
    const json* crossing = nullptr;
    for (const auto& e : profile["elements"]) {
        if (e["odd_element"] == anchor["element"] && e["osm_ids"] == anchor["osm_ids"]) {
            crossing = &e;
        }
    }
    ASSERT_NE(crossing, nullptr);
    const json& at = (*crossing)["attributes"];
    ASSERT_TRUE(at.contains("crossing_road_id"));
    const std::string road = at["crossing_road_id"];
    EXPECT_NE(road, anchor["road_id"].get<std::string>());
    const double s_cross = at["crossing_road_s"];
    pugi::xml_document doc;
    ASSERT_TRUE(doc.load_file(xosc.c_str()));
    const auto start = doc.select_node("//Private[@entityRef='StreetVehicle']//LanePosition").node();
    EXPECT_EQ(start.attribute("roadId").value(), road);
    EXPECT_EQ(start.attribute("laneId").as_int(), at["crossing_road_forward_lane"].get<double>());
    EXPECT_NEAR(start.attribute("s").as_double(), s_cross - 10.0, 1e-5);
    EXPECT_NEAR(start.attribute("offset").as_double(), 0.0, 1e-9);
    const auto end = doc.select_node("//Event[@name='StreetVehicleStarts']//Polyline/Vertex[last()]//LanePosition").node();
    EXPECT_EQ(end.attribute("roadId").value(), road);
    EXPECT_NEAR(end.attribute("s").as_double(), s_cross, 1e-5);
}

} // namespace

TEST_F(ScenarioSampleRoute, EveryFileIsValidOpenScenario12) {
    RAILODD_REQUIRE_SHARED_DATA();
    const fs::path xsd = shared_data() / "schemas" / "OpenSCENARIOv1.2.xsd";
    const fs::path out = root() / "xsd";
    const auto r = scenarios(out);
    ASSERT_EQ(r.exit_code, 0) << r.output;
    const auto files = files_in(out, ".xosc");
    ASSERT_GT(files.size(), 20u);
    std::string cmd = "xmllint --noout --schema " + quoted(xsd);
    for (const auto& f : files) {
        cmd.append(" ").append(quoted(f)); // not " " + ...: GCC 12 warns (-Wrestrict) on that temporary
    }
    const auto v = run_command(cmd);
    EXPECT_EQ(v.exit_code, 0) << v.output.substr(0, 2000);
}

TEST_F(ScenarioSampleRoute, PlacesAndEntitiesExistInMapAndCatalogs) {
    const fs::path out = root() / "refs";
    const auto r = scenarios(out);
    ASSERT_EQ(r.exit_code, 0) << r.output;
    const auto roads = read_map(map() / "map.xodr");
    std::set<std::string> entries;
    for (const auto& c : files_in(out / "catalogs", ".xosc")) {
        pugi::xml_document doc;
        ASSERT_TRUE(doc.load_file(c.c_str()));
        for (const auto& e : doc.child("OpenSCENARIO").child("Catalog").children()) {
            entries.insert(e.attribute("name").value());
        }
    }
    std::size_t positions = 0;
    for (const auto& f : files_in(out, ".xosc")) {
        if (f.parent_path() != out) {
            continue; // catalogs and distributions
        }
        pugi::xml_document doc;
        ASSERT_TRUE(doc.load_file(f.c_str())) << f;
        const fs::path logic = f.parent_path() / doc.select_node("//LogicFile").node().attribute("filepath").value();
        EXPECT_TRUE(fs::equivalent(logic, map() / "map.xodr")) << f;
        for (const auto& n : doc.select_nodes("//LanePosition")) {
            const auto p = n.node();
            const auto road = roads.find(p.attribute("roadId").value());
            ASSERT_NE(road, roads.end()) << f << ": road " << p.attribute("roadId").value();
            const double s = p.attribute("s").as_double();
            EXPECT_GE(s, 0.0) << f;
            EXPECT_LE(s, road->second.length + 1e-6) << f << ": road " << road->first;
            EXPECT_TRUE(road->second.lanes.contains(p.attribute("laneId").as_int())) << f;
            ++positions;
        }
        std::set<std::string> names;
        for (const auto& o : doc.select_nodes("//ScenarioObject")) {
            names.insert(o.node().attribute("name").value());
            const auto entry = resolved(doc, o.node().child("CatalogReference").attribute("entryName").value());
            EXPECT_TRUE(entries.contains(entry)) << f << ": catalog entry " << entry;
        }
        for (const auto& ref : doc.select_nodes("//*[@entityRef]")) {
            EXPECT_TRUE(names.contains(ref.node().attribute("entityRef").value())) << f;
        }
        const auto ego = doc.select_node("//ScenarioObject[@name='Ego']");
        EXPECT_TRUE(ego) << f;
    }
    EXPECT_GT(positions, 100u);
}

TEST_F(ScenarioSampleRoute, AnchorsSatisfyTheirTemplates) {
    const fs::path out = root() / "anchors";
    ASSERT_EQ(scenarios(out).exit_code, 0);
    const json m = read_json(out / "manifest.json");
    const json profile = with_element_objects(read_json(map() / "odd_profile.json"));
    std::map<std::string, std::size_t> per_template;
    for (const auto& s : m["scenarios"]) {
        const std::string t = s["template"];
        ++per_template[t];
        const auto& a = s["anchor"];
        const double run_up = s["ego"]["run_up_m"];
        EXPECT_GT(run_up, 99.0) << s["id"];
        EXPECT_LE(s["ego"]["speed_kmh"].get<double>(), a["speed_limit_kmh"].get<double>() + 1e-9) << s["id"];
        if (t == "curve_crossing_street_vehicle") {
            EXPECT_EQ(a["element"], "Scenery/Crossings/Level crossing");
            ASSERT_EQ(a["context"].size(), 1u);
            const auto& c = a["context"][0];
            EXPECT_EQ(c["element"], "Scenery/Track geometry/Horizontal/Curve");
            const double gap = a["chainage"].get<double>() - c["chainage_end"].get<double>();
            EXPECT_GE(gap, 0.0);
            EXPECT_LE(gap, 500.0);
            EXPECT_NE(s["text"].get<std::string>().find("radius "), std::string::npos);
            street_vehicle_on_the_road(out / s["file"].get<std::string>(), a, profile);
            EXPECT_EQ(s["assets"]["Ego"].is_string(), true);
        } else if (t == "tunnel_exit_animal") {
            EXPECT_EQ(a["element"], "Scenery/Structures/Tunnel");
        } else if (t == "platform_edge_passenger") {
            EXPECT_EQ(a["element"], "Scenery/Stations and stops/Platform");
        }
        // The anchor is a profile element: same track, chainage and OSM ids
        // (the road can be the next one where the element lies at a road's end).
        bool found = false;
        for (const auto& e : profile["elements"]) {
            const bool at_start = std::abs(e["chainage_start"].get<double>() - a["chainage"].get<double>()) < 1e-6;
            const bool at_end = std::abs(e["chainage_end"].get<double>() - a["chainage"].get<double>()) < 1e-6;
            const bool within = e["chainage_start"].get<double>() <= a["chainage"].get<double>() + 1e-6 &&
                                e["chainage_end"].get<double>() >= a["chainage"].get<double>() - 1e-6;
            found = found || (e["odd_element"] == a["element"] && e["osm_ids"] == a["osm_ids"] &&
                              e["track"] == a["track"] && (at_start || at_end || within));
        }
        EXPECT_TRUE(found) << s["id"];
        std::set<std::string> sources;
        for (const auto& v : s["odd_elements"]) {
            sources.insert(v["source"].get<std::string>());
        }
        EXPECT_TRUE(sources.contains("map") && sources.contains("parameter")) << s["id"];
        for (const auto& src : sources) {
            EXPECT_TRUE((std::set<std::string>{"asset", "map", "parameter", "perturbation", "degraded_mode"}).contains(src))
                << s["id"] << " " << src;
        }
    }
    for (const char* t : {"curve_crossing_street_vehicle", "level_crossing_person", "platform_edge_passenger",
                          "tunnel_exit_animal", "curve_track_worker"}) {
        EXPECT_GT(per_template[t], 0u) << t;
    }
}

TEST_F(ScenarioSampleRoute, PairwiseCoversEveryFeasiblePair) {
    const fs::path out = root() / "pairs";
    ASSERT_EQ(scenarios(out, "--strategy pairwise").exit_code, 0);
    const json c = read_json(out / "coverage.json");
    ASSERT_FALSE(c["templates"].empty());
    for (const auto& t : c["templates"]) {
        if (t["anchors"].get<int>() > 0) {
            EXPECT_GT(t["pairs_feasible"].get<int>(), 0) << t["template"];
        }
        EXPECT_EQ(t["pairs_covered"], t["pairs_feasible"]) << t["template"];
    }
    // Against the full product on two anchors per template, both ways: the
    // full product on every anchor writes 44,478 files (86 s, 260 s under
    // the sanitizers) to tell the same.
    const std::string two = " --max-anchors 2";
    const json few = (scenarios(root() / "pairs2", "--strategy pairwise" + two), read_json(root() / "pairs2" / "coverage.json"));
    const json full = (scenarios(root() / "full", "--strategy full" + two), read_json(root() / "full" / "coverage.json"));
    EXPECT_LT(few["scenarios"].get<int>(), full["scenarios"].get<int>());
    EXPECT_GT(c["route"]["covered"].get<int>(), 0);
    for (const auto& g : c["gaps"]) {
        EXPECT_FALSE(g["reason"].get<std::string>().empty()) << g.dump();
    }
}

TEST_F(ScenarioSampleRoute, DeterministicForASeed) {
    auto bytes = [](const fs::path& dir) {
        std::map<std::string, std::string> out;
        for (const auto& e : fs::recursive_directory_iterator(dir)) {
            if (e.is_regular_file()) {
                out[fs::relative(e.path(), dir).string()] = read_file(e.path());
            }
        }
        return out;
    };
    ASSERT_EQ(scenarios(root() / "r1", "--strategy random --count 7 --seed 42").exit_code, 0);
    ASSERT_EQ(scenarios(root() / "r2", "--strategy random --count 7 --seed 42").exit_code, 0);
    ASSERT_EQ(scenarios(root() / "r3", "--strategy random --count 7 --seed 43").exit_code, 0);
    const auto a = bytes(root() / "r1"), b = bytes(root() / "r2"), c = bytes(root() / "r3");
    EXPECT_EQ(a, b);
    EXPECT_NE(a.at("manifest.json"), c.at("manifest.json"));
    EXPECT_EQ(read_json(root() / "r1" / "coverage.json")["templates"][0]["rows"], 7);
}

TEST_F(ScenarioSampleRoute, RerunRemovesScenariosItNoLongerWrites) {
    const fs::path out = root() / "rerun";
    ASSERT_EQ(scenarios(out).exit_code, 0);
    const auto before = files_in(out, ".xosc").size();
    ASSERT_EQ(scenarios(out, "--strategy random --count 1").exit_code, 0);
    const json m = read_json(out / "manifest.json");
    std::size_t top = 0;
    for (const auto& f : files_in(out, ".xosc")) {
        top += f.parent_path() == out ? 1 : 0;
    }
    EXPECT_EQ(top, m["scenarios"].size());
    EXPECT_LT(top, before);
}

TEST_F(ScenarioSampleRoute, BadInputFailsWithoutOutput) {
    const fs::path out = root() / "bad";
    const auto missing = run_railodd("scenarios --map " + quoted(root() / "nope") + " -o " + quoted(out));
    EXPECT_EQ(missing.exit_code, 2) << missing.output;
    const fs::path tmpl = write_file(root() / "bad.yaml", "templates:\n  - id: x\n    text: \"at {speed}\"\n"
                                                          "    anchor: {element: Scenery/Crossings/Level crossing}\n");
    const auto r = scenarios(out, "--templates " + quoted(tmpl));
    EXPECT_EQ(r.exit_code, 2) << r.output;
    EXPECT_NE(r.output.find("bad.yaml:3"), std::string::npos) << r.output;
    EXPECT_NE(r.output.find("placeholder {speed}"), std::string::npos) << r.output;
    EXPECT_TRUE(!fs::exists(out) || files_in(out, ".xosc").empty());
    const auto u = scenarios(out, "--strategy random");
    EXPECT_EQ(u.exit_code, 1) << u.output;
}

// A route run against the roads' direction (Brookside to Sampleton): the ego
// faces against s and its waypoints fall in s.
TEST_F(ScenarioSampleRoute, RouteAgainstTheRoadsRunsBackwardsInS) {
    const fs::path route = root() / "route_back";
    const auto c = run_railodd("convert " + quoted(root() / "sample" / "sample_route.osm") + " -o " + quoted(route) +
                               " --no-timings --from Brookside --to Sampleton");
    ASSERT_EQ(c.exit_code, 0) << c.output;
    const fs::path out = root() / "route_back_scenarios";
    const auto r = run_railodd("scenarios --map " + quoted(route) + " -o " + quoted(out) + " -q");
    ASSERT_EQ(r.exit_code, 0) << r.output;
    const json m = read_json(out / "manifest.json");
    ASSERT_FALSE(m["scenarios"].empty());
    for (const auto& s : m["scenarios"]) {
        EXPECT_EQ(s["ego"]["start"].value("reversed", false), true) << s["id"];
        pugi::xml_document doc;
        ASSERT_TRUE(doc.load_file((out / s["file"].get<std::string>()).c_str()));
        const auto waypoints = doc.select_nodes("//Waypoint//LanePosition");
        ASSERT_GE(waypoints.size(), 2u);
        const auto first = waypoints.first().node(), last = (waypoints.end() - 1)->node();
        if (std::string{first.attribute("roadId").value()} == last.attribute("roadId").value()) {
            EXPECT_GT(first.attribute("s").as_double(), last.attribute("s").as_double()) << s["id"];
        }
        EXPECT_EQ(std::string{first.child("Orientation").attribute("h").value()}, "3.141593") << s["id"];
    }
}
