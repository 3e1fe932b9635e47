// `railodd scenarios --target carla` on the sample route: every element of
// every file is one CARLA's ScenarioRunner lists as supported where it stands
// (its Init or Story column), the files are OpenSCENARIO 1.0 valid against
// the ASAM schema, they hold what ScenarioRunner's parser needs to load them,
// and what they cannot express is declared and listed as degraded_for_target.
#include "test_support.hpp"

#include <nlohmann/json.hpp>
#include <pugixml.hpp>

#include <list>
#include <map>
#include <set>
#include <string_view>
#include <vector>

#include <unistd.h>

using namespace railodd::test;
using json = nlohmann::json;

namespace {

// ---- ScenarioRunner's support list --------------------------------------
// From carla-simulator/scenario_runner Docs/openscenario_support.md, 0.9.16
// release, commit 94ff3b8af752bad2b9d464ad5105868906aa34c0: every row of its
// tables with its Init and Story columns (setup rows are read outside the
// Storyboard; conditions "can be used for StartTrigger and StopTrigger").
struct DocRow {
    bool init;
    bool story;
};
constexpr bool Y = true;
constexpr bool N = false;
const std::map<std::string, DocRow, std::less<>> doc_rows = {
    // "General OpenSCENARIO setup"
    {"FileHeader", {Y, Y}}, {"ControllerCatalog", {Y, Y}}, {"EnvironmentCatalog", {Y, Y}},
    {"ManeuverCatalog", {Y, Y}}, {"MiscObjectCatalog", {Y, Y}}, {"PedestrianCatalog", {Y, Y}},
    {"RouteCatalog", {Y, Y}}, {"TrajectoryCatalog", {Y, Y}}, {"VehicleCatalog", {Y, Y}},
    {"ParameterDeclarations", {Y, Y}}, {"LogicFile", {Y, Y}}, {"SceneGraphFile", {N, N}}, {"TrafficSignals", {N, N}},
    {"EntitySelection", {N, N}}, {"CatalogReference", {Y, Y}}, {"MiscObject", {Y, Y}}, {"ObjectController", {N, N}},
    {"Pedestrian", {Y, Y}}, {"Vehicle", {Y, Y}},
    // GlobalAction
    {"EntityAction", {Y, Y}}, {"EnvironmentAction", {Y, N}}, {"ParameterAction", {Y, Y}}, {"TrafficAction", {N, N}},
    {"TrafficSignalControllerAction", {N, Y}}, {"TrafficSignalStateAction", {N, Y}},
    // UserDefinedAction
    {"CustomCommandAction", {N, Y}},
    // PrivateAction
    {"ActivateControllerAction", {N, Y}}, {"ControllerAction", {Y, Y}}, {"LaneChangeAction", {N, Y}},
    {"LaneOffsetAction", {N, Y}}, {"LateralDistanceAction", {Y, Y}}, {"LongitudinalDistanceAction", {N, Y}},
    {"SpeedAction", {Y, Y}}, {"SynchronizeAction", {N, N}}, {"TeleportAction", {Y, Y}}, {"VisibilityAction", {N, N}},
    {"AcquirePositionAction", {N, Y}}, {"AssignRouteAction", {N, Y}}, {"FollowTrajectoryAction", {N, Y}},
    // ByEntityCondition
    {"AccelerationCondition", {N, Y}}, {"CollisionCondition", {N, Y}}, {"DistanceCondition", {N, Y}},
    {"EndOfRoadCondition", {N, Y}}, {"OffroadCondition", {N, Y}}, {"ReachPositionCondition", {N, Y}},
    {"RelativeDistanceCondition", {N, Y}}, {"RelativeSpeedCondition", {N, Y}}, {"SpeedCondition", {N, Y}},
    {"StandStillCondition", {N, Y}}, {"TimeHeadwayCondition", {N, Y}}, {"TimeToCollisionCondition", {N, Y}},
    {"TraveledDistanceCondition", {N, Y}},
    // ByValueCondition
    {"ParameterCondition", {N, Y}}, {"SimulationTimeCondition", {N, Y}}, {"StoryboardElementStateCondition", {N, Y}},
    {"TimeOfDayCondition", {N, Y}}, {"TrafficSignalCondition", {N, Y}}, {"TrafficSignalControllerCondition", {N, Y}},
    {"UserDefinedValueCondition", {N, N}},
    // Positions
    {"LanePosition", {Y, Y}}, {"RelativeLanePosition", {Y, Y}}, {"RelativeObjectPosition", {Y, Y}},
    {"RelativeRoadPosition", {Y, Y}}, {"RelativeWorldPosition", {Y, Y}}, {"RoadPosition", {Y, Y}},
    {"RoutePosition", {N, N}}, {"WorldPosition", {Y, Y}},
};

// What the document does not name: the frame of the document and the
// Storyboard ("covers ... Stories and the Storyboard", the tables' nesting:
// PrivateAction > LongitudinalAction > SpeedAction) ...
const std::set<std::string, std::less<>> frame = {
    "OpenSCENARIO", "CatalogLocations", "Catalog", "RoadNetwork", "Entities", "ScenarioObject", "Storyboard",
    "Init", "Actions", "Private", "PrivateAction", "GlobalAction", "Story", "Act", "ManeuverGroup", "Actors",
    "EntityRef", "Maneuver", "Event", "Action", "StartTrigger", "StopTrigger", "ConditionGroup", "Condition",
    "ByEntityCondition", "TriggeringEntities", "EntityCondition", "ByValueCondition", "LongitudinalAction",
    "LateralAction", "RoutingAction", "Position"};
// ... and the parts of a listed row ("If an action contains of submodules,
// which are not listed, the support status applies to all submodules"): a
// part must lie inside one of the rows of its group.
struct PartGroup {
    std::set<std::string> rows;
    std::set<std::string, std::less<>> parts;
};
const std::vector<PartGroup> part_groups = {
    {{"ParameterDeclarations"}, {"ParameterDeclaration"}},
    {{"VehicleCatalog", "PedestrianCatalog", "MiscObjectCatalog", "ControllerCatalog"}, {"Directory"}},
    {{"CatalogReference"}, {"ParameterAssignments", "ParameterAssignment"}},
    {{"Vehicle", "Pedestrian", "MiscObject"}, {"BoundingBox", "Center", "Dimensions"}},
    {{"Vehicle"}, {"Performance", "Axles", "FrontAxle", "RearAxle"}},
    {{"Vehicle", "Pedestrian", "MiscObject", "ControllerAction"}, {"Properties", "Property"}},
    {{"EnvironmentAction"}, {"Environment", "TimeOfDay", "Weather", "Sun", "Fog", "Precipitation", "RoadCondition"}},
    {{"SpeedAction"}, {"SpeedActionDynamics", "SpeedActionTarget", "AbsoluteTargetSpeed"}},
    {{"ControllerAction"},
     {"AssignControllerAction", "Controller", "OverrideControllerValueAction", "Throttle", "Brake", "Clutch",
      "ParkingBrake", "SteeringWheel", "Gear"}},
    {{"AssignRouteAction"}, {"Route", "Waypoint"}},
    {{"FollowTrajectoryAction"},
     {"Trajectory", "Shape", "Polyline", "Vertex", "TimeReference", "None", "TrajectoryFollowingMode"}},
    {{"LanePosition", "RoadPosition", "WorldPosition", "RelativeLanePosition", "RelativeRoadPosition",
      "RelativeWorldPosition", "RelativeObjectPosition"},
     {"Orientation"}},
};

enum class Where { setup, init, story };

Where where_of(pugi::xml_node n) {
    for (; n; n = n.parent()) {
        const std::string_view name = n.name();
        if (name == "Init") {
            return Where::init;
        }
        if (name == "Story" || (name == "StopTrigger" && std::string_view{n.parent().name()} == "Storyboard")) {
            return Where::story;
        }
    }
    return Where::setup;
}

bool inside(pugi::xml_node n, const std::set<std::string>& owners) {
    for (n = n.parent(); n; n = n.parent()) {
        if (owners.contains(n.name())) {
            return true;
        }
    }
    return false;
}

// Empty when ScenarioRunner's list has the element where it stands, else why not.
std::string unsupported(pugi::xml_node n) {
    const std::string_view name = n.name();
    const Where w = where_of(n);
    if (const auto r = doc_rows.find(name); r != doc_rows.end()) {
        const bool ok = w == Where::setup ? (r->second.init || r->second.story)
                                          : (w == Where::init ? r->second.init : r->second.story);
        return ok ? "" : std::string(name) + (w == Where::init ? " is not supported in the Init" : " is not supported");
    }
    if (frame.contains(name)) {
        return "";
    }
    for (const auto& g : part_groups) {
        if (g.parts.contains(name)) {
            return inside(n, g.rows) ? "" : std::string(name) + " outside the rows it belongs to";
        }
    }
    return std::string(name) + " is not in ScenarioRunner's list";
}

// ---- the sample route and its carla scenario set ------------------------

CommandResult run_railodd(const std::string& args) { return run_command(std::string{RAILODD_BIN} + " " + args); }

json read_json(const fs::path& p) { return json::parse(read_file(p)); }

class ScenarioCarlaTarget : public ::testing::Test {
protected:
    static fs::path root() {
        return fs::temp_directory_path() / "railodd-tests" / ("ScenarioCarlaTarget-" + std::to_string(::getpid()));
    }
    static fs::path map() { return root() / "map"; }
    static fs::path carla() { return root() / "carla"; }
    static void TearDownTestSuite() { fs::remove_all(root()); }
    // Converted as the demo does (DEM, cant): more of the templates find anchors.
    static void SetUpTestSuite() {
        fs::remove_all(root());
        fs::create_directories(root());
        const auto s = run_railodd("sample -o " + quoted(root() / "sample"));
        ASSERT_EQ(s.exit_code, 0) << s.output;
        const auto c = run_railodd("convert " + quoted(root() / "sample" / "sample_route.osm") + " -o " +
                                   quoted(map()) + " --dem " + quoted(root() / "sample" / "sample_route_dem.tif") +
                                   " --estimate-cant --no-timings");
        ASSERT_EQ(c.exit_code, 0) << c.output;
        // Pairwise: every weather value of every template, snow and wind among them.
        const auto r = scenarios(carla(), "--target carla --strategy pairwise");
        ASSERT_EQ(r.exit_code, 0) << r.output;
    }
    static CommandResult scenarios(const fs::path& out, const std::string& extra = "") {
        return run_railodd("scenarios --map " + quoted(map()) + " -o " + quoted(out) + " -q " + extra);
    }
    static std::vector<fs::path> files(const fs::path& dir) {
        std::vector<fs::path> out;
        for (const auto& e : fs::recursive_directory_iterator(dir)) {
            if (e.is_regular_file() && e.path().extension() == ".xosc") {
                out.push_back(e.path());
            }
        }
        std::sort(out.begin(), out.end());
        return out;
    }
};

void load(pugi::xml_document& doc, const fs::path& f) {
    const auto r = doc.load_file(f.c_str());
    EXPECT_TRUE(r) << f << ": " << r.description();
}

// A declared parameter's value ("$Name" resolved), or the text itself.
std::string resolved(const pugi::xml_node& decls, const std::string& text) {
    if (text.empty() || text[0] != '$') {
        return text;
    }
    for (const auto& p : decls.children("ParameterDeclaration")) {
        if (text.substr(1) == p.attribute("name").value()) {
            return p.attribute("value").value();
        }
    }
    return text;
}

} // namespace

TEST_F(ScenarioCarlaTarget, EveryElementWrittenIsInScenarioRunnersSupportList) {
    const auto all = files(carla());
    ASSERT_GT(all.size(), 30u);
    std::set<std::string> seen;
    for (const auto& f : all) {
        pugi::xml_document doc;
        load(doc, f);
        for (const auto& x : doc.select_nodes("//*")) {
            const pugi::xml_node n = x.node();
            seen.insert(n.name());
            const std::string why = unsupported(n);
            EXPECT_TRUE(why.empty()) << f.filename() << ": " << why;
        }
    }
    // The set uses what the test means to check: the route as a trajectory,
    // the ego's controller, moving actors' timing, the run's end.
    for (const char* e : {"FollowTrajectoryAction", "Vertex", "ControllerAction", "TraveledDistanceCondition",
                          "StoryboardElementStateCondition", "DistanceCondition", "EnvironmentAction"}) {
        EXPECT_TRUE(seen.contains(e)) << e;
    }
    for (const char* e : {"AssignRouteAction", "AcquirePositionAction", "Wind", "TrajectoryRef",
                          "ParameterValueDistribution"}) {
        EXPECT_FALSE(seen.contains(e)) << e;
    }
    EXPECT_FALSE(fs::exists(carla() / "distributions")) << "OpenSCENARIO 1.0 has no ParameterValueDistribution";
}

TEST_F(ScenarioCarlaTarget, EveryFileIsValidOpenScenario10) {
    const fs::path xsd = shared_data().empty() ? fs::path{} : shared_data() / "schemas" / "OpenSCENARIOv1.0.xsd";
    if (!fs::is_regular_file(xsd)) {
        GTEST_SKIP() << "../shared/data/schemas/OpenSCENARIOv1.0.xsd is absent: skipping the schema test";
    }
    if (run_command("command -v xmllint").exit_code != 0) {
        GTEST_SKIP() << "xmllint is not installed (libxml2-utils): skipping the schema test";
    }
    std::string cmd = "xmllint --noout --schema " + quoted(xsd);
    for (const auto& f : files(carla())) {
        cmd.append(" ").append(quoted(f));
    }
    const auto v = run_command(cmd);
    EXPECT_EQ(v.exit_code, 0) << v.output.substr(0, 3000);
}

using Catalogs = std::map<std::string, std::map<std::string, pugi::xml_node>>;

// catalog name -> entry name -> entry, as _load_catalogs keys them.
Catalogs read_catalogs(const std::vector<fs::path>& files, std::list<pugi::xml_document>& keep) {
    Catalogs out;
    for (const auto& f : files) {
        load(keep.emplace_back(), f);
        const auto c = keep.back().child("OpenSCENARIO").child("Catalog");
        EXPECT_EQ(f.stem(), c.attribute("name").value()) << "ScenarioRunner opens <path>/<Type>Catalog.xosc";
        for (const auto& e : c.children()) {
            out[c.attribute("name").value()][e.attribute("name").value()] = e;
        }
    }
    return out;
}

// openscenario_configuration.py: every catalog location holds its file, every
// entity's entry is in its catalog, and one vehicle, the Ego, has the
// Property type = ego_vehicle (its entry parameter set by the reference).
TEST_F(ScenarioCarlaTarget, EveryEntityIsInItsCatalogAndOneIsTheEgo) {
    std::list<pugi::xml_document> keep; // the catalog nodes point into them
    Catalogs catalogs = read_catalogs(files(carla() / "catalogs"), keep);
    for (const auto& f : files(carla())) {
        if (f.parent_path() != carla()) {
            continue;
        }
        pugi::xml_document doc;
        load(doc, f);
        const auto root = doc.child("OpenSCENARIO");
        for (const auto& loc : root.child("CatalogLocations").children()) {
            EXPECT_TRUE(fs::is_regular_file(carla() / loc.child("Directory").attribute("path").value() /
                                            (std::string(loc.name()) + ".xosc")))
                << f.filename() << ": " << loc.name();
        }
        int egos = 0;
        for (const auto& obj : root.child("Entities").children("ScenarioObject")) {
            const auto ref = obj.child("CatalogReference");
            const std::string entry = resolved(root.child("ParameterDeclarations"), ref.attribute("entryName").value());
            ASSERT_TRUE(catalogs[ref.attribute("catalogName").value()].contains(entry)) << entry;
            const auto e = catalogs[ref.attribute("catalogName").value()][entry];
            if (std::string_view{e.name()} != "Vehicle") {
                continue;
            }
            std::string type = e.select_node("Properties/Property[@name='type']").node().attribute("value").value();
            const auto assigned = ref.select_node("ParameterAssignments/ParameterAssignment").node();
            type = type == "$ActorType" ? (assigned ? assigned.attribute("value").value() : "scenario") : type;
            egos += type == "ego_vehicle";
            EXPECT_EQ(type == "ego_vehicle", std::string_view{obj.attribute("name").value()} == "Ego");
        }
        EXPECT_EQ(egos, 1) << f.filename();
    }
}

// What openscenario_configuration.py and openscenario_parser.py need besides:
// revision 1.0, a name, the map where the file says, one Story, literal
// values where the parser reads attributes raw, one position per actor in
// the Init, times on vertices, the run's end in the Act.
TEST_F(ScenarioCarlaTarget, FilesHoldWhatScenarioRunnersParserReads) {
    const json m = read_json(carla() / "manifest.json");
    EXPECT_EQ(m["generation"]["openscenario"], "1.0");
    EXPECT_EQ(m["generation"]["target"], "carla");
    for (const auto& s : m["scenarios"]) {
        const fs::path file = carla() / s["file"].get<std::string>();
        pugi::xml_document doc;
        load(doc, file);
        const auto root = doc.child("OpenSCENARIO");
        const auto header = root.child("FileHeader");
        EXPECT_STREQ(header.attribute("revMajor").value(), "1");
        EXPECT_STREQ(header.attribute("revMinor").value(), "0") << file;
        const std::string description = header.attribute("description").value();
        EXPECT_FALSE(description.empty() || description.rfind("CARLA:", 0) == 0) << "the scenario's name";
        const std::string logic = root.child("RoadNetwork").child("LogicFile").attribute("filepath").value();
        EXPECT_NE(logic.find(".xodr"), std::string::npos);
        EXPECT_TRUE(fs::is_regular_file(carla() / logic)) << logic;
        EXPECT_EQ(doc.select_nodes("//Story").size(), 1u);
        for (const auto& n : doc.select_nodes("//EnvironmentAction//@*")) {
            EXPECT_NE(n.attribute().value()[0], '$') << file << ": read raw by ScenarioRunner";
        }
        for (const auto& v : doc.select_nodes("//Vertex")) {
            EXPECT_FALSE(v.node().attribute("time").empty()) << file;
        }
        for (const auto& p : root.child("Storyboard").child("Init").child("Actions").children("Private")) {
            EXPECT_EQ(p.select_nodes(".//Position").size(), 1u) << "the parser takes the last Position as the start";
        }
        EXPECT_TRUE(doc.select_node("//Act/StopTrigger/ConditionGroup")) << "ScenarioRunner ends the run there";
        const auto track = doc.select_nodes("//ManeuverGroup[Actors/EntityRef/@entityRef='Ego']//Vertex");
        EXPECT_GE(track.size(), 10u) << file << ": the ego's run, sampled along the track";
    }
}

// Every parameter no element carries is declared and listed with its reason;
// templates with a signal aspect, a degraded mode, snow or wind lose it.
TEST_F(ScenarioCarlaTarget, WhatCannotBeExpressedIsDeclaredAndListedAsDegraded) {
    const json m = read_json(carla() / "manifest.json");
    std::set<std::string> names;
    for (const auto& s : m["scenarios"]) {
        ASSERT_TRUE(s.contains("degraded_for_target")) << s["id"];
        const std::string text = read_file(carla() / s["file"].get<std::string>());
        pugi::xml_document doc;
        load(doc, carla() / s["file"].get<std::string>());
        const auto decls = doc.child("OpenSCENARIO").child("ParameterDeclarations");
        std::set<std::string> degraded;
        for (const auto& d : s["degraded_for_target"]) {
            const std::string name = d["name"];
            degraded.insert(name);
            names.insert(name);
            EXPECT_FALSE(d["reason"].get<std::string>().empty());
            const auto decl = decls.find_child_by_attribute("ParameterDeclaration", "name", name.c_str());
            ASSERT_TRUE(decl) << s["id"] << ": " << name << " kept as a parameter";
            EXPECT_EQ(decl.attribute("value").value(), d["value"].get<std::string>());
            EXPECT_EQ(text.find("\"$" + name + "\""), std::string::npos) << name << " is used, not dropped";
        }
        const json& params = s["parameters"];
        if (params.contains("aspect")) {
            EXPECT_TRUE(degraded.contains("Aspect")) << s["id"];
        }
        const std::string behaviour = read_file(carla() / s["behavior"].get<std::string>());
        if (params.contains("degraded") && behaviour.find("degraded_mode_family: none") == std::string::npos) {
            EXPECT_TRUE(degraded.contains("DegradedMode")) << s["id"];
        }
        if (behaviour.find("GNSS availability: ") != std::string::npos) {
            EXPECT_TRUE(degraded.contains("GNSSAvailability")) << s["id"];
        }
        if (s["osc_parameters"].value("PrecipitationType", "") == "snow") {
            EXPECT_TRUE(degraded.contains("PrecipitationType")) << s["id"];
            EXPECT_STREQ(doc.select_node("//Precipitation").node().attribute("precipitationType").value(), "dry");
        }
        for (const auto& v : s["odd_elements"]) {
            if (v["element"] == "Environmental Conditions/Weather/Wind" && v["attribute"] == "speed" &&
                v["value"] != "0") {
                EXPECT_TRUE(degraded.contains("WindSpeed")) << s["id"];
            }
        }
    }
    for (const char* n : {"Aspect", "DegradedMode", "GNSSAvailability", "PrecipitationType", "WindSpeed"}) {
        EXPECT_TRUE(names.contains(n)) << n << " degraded somewhere in the pairwise set";
    }
}

TEST_F(ScenarioCarlaTarget, SameInputSameFiles) {
    const fs::path again = root() / "carla_again";
    const auto r = scenarios(again, "--target carla --strategy pairwise");
    ASSERT_EQ(r.exit_code, 0) << r.output;
    const auto a = files(carla());
    const auto b = files(again);
    ASSERT_EQ(a.size(), b.size());
    for (std::size_t i = 0; i < a.size(); ++i) {
        EXPECT_EQ(read_file(a[i]), read_file(b[i])) << a[i].filename();
    }
    EXPECT_EQ(read_file(carla() / "manifest.json"), read_file(again / "manifest.json"));
}

TEST_F(ScenarioCarlaTarget, DefaultTargetStaysEsmini) {
    const fs::path out = root() / "esmini";
    const auto r = scenarios(out);
    ASSERT_EQ(r.exit_code, 0) << r.output;
    const json m = read_json(out / "manifest.json");
    EXPECT_EQ(m["generation"]["target"], "esmini");
    EXPECT_EQ(m["generation"]["openscenario"], "1.2");
    EXPECT_FALSE(m["scenarios"][0].contains("degraded_for_target"));
    pugi::xml_document doc;
    load(doc, out / m["scenarios"][0]["file"].get<std::string>());
    EXPECT_STREQ(doc.child("OpenSCENARIO").child("FileHeader").attribute("revMinor").value(), "2");
    EXPECT_TRUE(doc.select_node("//Init//AssignRouteAction"));
}

TEST_F(ScenarioCarlaTarget, BadOptionsAndCatalogsAreRefused) {
    const fs::path out = root() / "refused";
    auto r = scenarios(out, "--target carla --osc-version 1.2");
    EXPECT_EQ(r.exit_code, 1) << r.output;
    EXPECT_NE(r.output.find("OpenSCENARIO 1.0"), std::string::npos) << r.output;
    r = scenarios(out, "--target unreal");
    EXPECT_EQ(r.exit_code, 1) << r.output;
    EXPECT_NE(r.output.find("esmini or carla"), std::string::npos) << r.output;
    r = scenarios(out, "--osc-version 1.0");
    EXPECT_EQ(r.exit_code, 1) << r.output;
    // Two assets with one blueprint would merge into one catalog entry.
    std::string assets = read_file(fs::path{RAILODD_SOURCE_DIR} / "data" / "scenario" / "assets.yaml");
    const std::string etron = "carla_blueprint: vehicle.audi.etron";
    ASSERT_NE(assets.find(etron), std::string::npos);
    assets.replace(assets.find(etron), etron.size(), "carla_blueprint: vehicle.tesla.model3");
    const fs::path catalog = write_file(root() / "assets_shared_blueprint.yaml", assets);
    r = scenarios(out, "--target carla --catalog " + quoted(catalog));
    EXPECT_EQ(r.exit_code, 2) << r.output;
    EXPECT_NE(r.output.find("share carla_blueprint 'vehicle.tesla.model3'"), std::string::npos) << r.output;
    EXPECT_EQ(scenarios(out, "--catalog " + quoted(catalog)).exit_code, 0) << "esmini names entries by osc_entry";
}
