// The OpenSCENARIO writer: scenario, catalog and distribution documents, read
// back with pugixml and (with ../shared/data) validated against the ASAM XSDs
// with xmllint.
#include "test_support.hpp"

#include "railodd/scenario/xosc_writer.hpp"
#include "railodd/util/errors.hpp"

#include <pugixml.hpp>

using namespace railodd::test;
using namespace railodd::scenario;

namespace {

LanePlacement at(std::string road, int lane, double s, double offset = 0.0, bool reversed = false) {
    return {std::move(road), lane, s, offset, reversed};
}

Actor train() {
    Actor a;
    a.name = "Ego";
    a.kind = Actor::Kind::vehicle;
    a.category = "train";
    a.asset_id = "regional_emu";
    a.catalog_entry = "regional_emu";
    a.model3d = "vehicle.railodd.emu";
    a.mass_kg = 120000;
    a.dimensions = {68.5, 2.9, 4.2};
    a.max_speed_mps = 44.4;
    a.max_acceleration = 1.0;
    a.max_deceleration = 1.2;
    a.start = at("3", -1, 20.0);
    a.speed_mps = 25.0;
    a.route = {at("3", -1, 20.0), at("5", -1, 100.0)};
    a.properties = {{"odd.track_class", "mainline"}};
    return a;
}

Actor car() {
    Actor a;
    a.name = "Obstacle";
    a.category = "car";
    a.asset_id = "sedan";
    a.catalog_entry = "sedan";
    a.model3d = "vehicle.tesla.model3";
    a.mass_kg = 1600;
    a.dimensions = {4.7, 1.9, 1.5};
    a.max_speed_mps = 50;
    a.max_acceleration = 3;
    a.max_deceleration = 8;
    a.start = at("7", 1, 10.25, -1e-9, true); // a tiny negative offset must print as 0
    return a;
}

Actor walker() {
    Actor a;
    a.name = "Walker";
    a.kind = Actor::Kind::pedestrian;
    a.category = "pedestrian";
    a.asset_id = "adult";
    a.catalog_entry = "adult";
    a.model3d = "walker.pedestrian.0001";
    a.mass_kg = 80;
    a.dimensions = {0.5, 0.6, 1.8};
    a.start = at("3", -2, 150.0, 1.5);
    a.target = at("3", -1, 150.0);
    a.target_speed_mps = 1.4;
    return a;
}

ConcreteScenario scenario() {
    ConcreteScenario sc;
    sc.id = "obstacle_on_track_0001";
    sc.description = "A pedestrian steps onto the track ahead of the train in rain and fog";
    sc.map_file = "../map/map.xodr";
    sc.catalog_dir = "catalogs";
    sc.parameters = {{"EgoSpeed", "double", "25"},
                     {"FogVisualRange", "double", "80"},
                     {"ObstacleAsset", "string", "sedan"}};
    sc.ego = train();
    sc.others = {car(), walker()};
    sc.environment.precipitation = "rain";
    sc.environment.precipitation_intensity_mm_h = 4.0;
    sc.environment.fog_visual_range_m = 80.0;
    sc.environment.fractional_cloud_cover = 0.75;
    sc.environment.friction_scale = 0.7;
    sc.trigger_distance_m = 120.0;
    sc.stop_time_s = 90.0;
    sc.ego_end = at("5", -1, 180.0);
    return sc;
}

pugi::xml_document parse(const std::string& text) {
    pugi::xml_document doc;
    const auto r = doc.load_string(text.c_str());
    EXPECT_TRUE(r) << r.description();
    return doc;
}

pugi::xml_node select(const pugi::xml_document& doc, const std::string& xpath) {
    return doc.select_node(xpath.c_str()).node();
}

std::string attribute(const pugi::xml_document& doc, const std::string& xpath, const char* name) {
    const pugi::xml_node n = select(doc, xpath);
    EXPECT_TRUE(n) << "no node " << xpath;
    return n.attribute(name).value();
}

const std::string ego_init = "/OpenSCENARIO/Storyboard/Init/Actions/Private[@entityRef='Ego']";

} // namespace

TEST(ScenarioXoscWriter, WritesHeaderParametersMapAndCatalogs) {
    const auto doc = parse(xosc_text(scenario()));
    EXPECT_EQ(attribute(doc, "/OpenSCENARIO/FileHeader", "revMajor"), "1");
    EXPECT_EQ(attribute(doc, "/OpenSCENARIO/FileHeader", "revMinor"), "2");
    EXPECT_EQ(attribute(doc, "/OpenSCENARIO/FileHeader", "date"), "2026-01-01T00:00:00");
    EXPECT_EQ(attribute(doc, "//ParameterDeclaration[@name='EgoSpeed']", "value"), "25");
    EXPECT_EQ(attribute(doc, "//ParameterDeclaration[@name='EgoSpeed']", "parameterType"), "double");
    EXPECT_EQ(attribute(doc, "/OpenSCENARIO/RoadNetwork/LogicFile", "filepath"), "../map/map.xodr");
    EXPECT_EQ(attribute(doc, "//CatalogLocations/VehicleCatalog/Directory", "path"), "catalogs");
    EXPECT_EQ(attribute(doc, "//CatalogLocations/PedestrianCatalog/Directory", "path"), "catalogs");
    // ObstacleAsset is declared, EgoAsset and WalkerAsset are not.
    EXPECT_EQ(attribute(doc, "//ScenarioObject[@name='Obstacle']/CatalogReference", "entryName"), "$ObstacleAsset");
    EXPECT_EQ(attribute(doc, "//ScenarioObject[@name='Ego']/CatalogReference", "entryName"), "regional_emu");
    EXPECT_EQ(attribute(doc, "//ScenarioObject[@name='Walker']/CatalogReference", "catalogName"),
              "PedestrianCatalog");
}

TEST(ScenarioXoscWriter, PlacesTheEgoOnItsLaneWithParameterSpeedAndRoute) {
    const auto doc = parse(xosc_text(scenario()));
    const std::string lane = ego_init + "/PrivateAction/TeleportAction/Position/LanePosition";
    EXPECT_EQ(attribute(doc, lane, "roadId"), "3");
    EXPECT_EQ(attribute(doc, lane, "laneId"), "-1");
    EXPECT_EQ(attribute(doc, lane, "s"), "20");
    EXPECT_EQ(attribute(doc, lane + "/Orientation", "h"), "0");
    EXPECT_EQ(attribute(doc, ego_init + "//SpeedAction/SpeedActionTarget/AbsoluteTargetSpeed", "value"),
              "$EgoSpeed");
    const auto waypoints = doc.select_nodes((ego_init + "//AssignRouteAction/Route/Waypoint").c_str());
    ASSERT_EQ(waypoints.size(), 2u);
    EXPECT_STREQ(waypoints[1].node().attribute("routeStrategy").value(), "shortest");
    EXPECT_STREQ(waypoints[1].node().child("Position").child("LanePosition").attribute("roadId").value(), "5");
    EXPECT_EQ(attribute(doc, ego_init + "//Route", "closed"), "false");

    // The standing car faces against s; its offset of -1e-9 prints as 0.
    const std::string car = "//Private[@entityRef='Obstacle']//TeleportAction/Position/LanePosition";
    EXPECT_EQ(attribute(doc, car, "s"), "10.25");
    EXPECT_EQ(attribute(doc, car, "offset"), "0");
    EXPECT_EQ(attribute(doc, car + "/Orientation", "type"), "relative");
    EXPECT_EQ(attribute(doc, car + "/Orientation", "h"), "3.141593");
    EXPECT_FALSE(select(doc, "//Private[@entityRef='Obstacle']//SpeedAction")) << "a standing car gets no speed";
}

TEST(ScenarioXoscWriter, WritesTheEnvironmentWithParameters) {
    const auto doc = parse(xosc_text(scenario()));
    const std::string env = "//GlobalAction/EnvironmentAction/Environment";
    EXPECT_EQ(attribute(doc, env + "/TimeOfDay", "dateTime"), "2026-06-21T12:00:00");
    EXPECT_EQ(attribute(doc, env + "/Weather", "fractionalCloudCover"), "sixOktas");
    EXPECT_EQ(attribute(doc, env + "/Weather", "temperature"), "288.15");
    EXPECT_EQ(attribute(doc, env + "/Weather/Sun", "intensity"), "100000");
    EXPECT_EQ(attribute(doc, env + "/Weather/Fog", "visualRange"), "$FogVisualRange");
    EXPECT_EQ(attribute(doc, env + "/Weather/Precipitation", "precipitationType"), "rain");
    EXPECT_EQ(attribute(doc, env + "/Weather/Precipitation", "precipitationIntensity"), "4");
    EXPECT_EQ(attribute(doc, env + "/RoadCondition", "frictionScaleFactor"), "0.7");
}

TEST(ScenarioXoscWriter, TriggersTheWalkerByEgoDistanceAndStopsByTimeOrEnd) {
    const auto doc = parse(xosc_text(scenario()));
    const auto groups = doc.select_nodes("//Story/Act/ManeuverGroup");
    ASSERT_EQ(groups.size(), 1u) << "only the walker has a target";
    const std::string event = "//ManeuverGroup[@name='WalkerGroup']/Maneuver/Event";
    EXPECT_EQ(attribute(doc, "//ManeuverGroup[@name='WalkerGroup']/Actors/EntityRef", "entityRef"), "Walker");
    EXPECT_EQ(attribute(doc, event + "//AbsoluteTargetSpeed", "value"), "1.4");
    const std::string path = event + "[@name='WalkerStarts']//FollowTrajectoryAction";
    EXPECT_EQ(attribute(doc, path + "//Polyline/Vertex[last()]/Position/LanePosition", "laneId"), "-1");
    EXPECT_TRUE(select(doc, path + "/TimeReference/None")) << "at the walker's own speed";
    // At the end of its path the walker stops.
    const std::string stops = event + "[@name='WalkerStops']";
    EXPECT_EQ(attribute(doc, stops + "//StoryboardElementStateCondition", "storyboardElementRef"), "WalkerToTarget");
    EXPECT_EQ(attribute(doc, stops + "//StoryboardElementStateCondition", "state"), "endTransition");
    EXPECT_EQ(attribute(doc, stops + "//AbsoluteTargetSpeed", "value"), "0");
    const std::string cond = event + "[@name='WalkerStarts']/StartTrigger/ConditionGroup/Condition/ByEntityCondition";
    EXPECT_EQ(attribute(doc, cond + "/TriggeringEntities/EntityRef", "entityRef"), "Ego");
    EXPECT_EQ(attribute(doc, cond + "/EntityCondition/TraveledDistanceCondition", "value"), "120");
    EXPECT_EQ(attribute(doc, "//Act/StartTrigger//SimulationTimeCondition", "rule"), "greaterThan");

    const auto stop = doc.select_nodes("/OpenSCENARIO/Storyboard/StopTrigger/ConditionGroup");
    ASSERT_EQ(stop.size(), 2u) << "time OR ego at its end";
    EXPECT_EQ(attribute(doc, "/OpenSCENARIO/Storyboard/StopTrigger//SimulationTimeCondition", "value"), "90");
    EXPECT_EQ(attribute(doc, "/OpenSCENARIO/Storyboard/StopTrigger//DistanceCondition/Position/LanePosition", "s"),
              "180");
}

// The end stops the run only once the ego has run nearly its whole way
// there (the ego's run less the end's 5 m tolerance and 10 m): a run round
// a tram's turning loop passed within 5 m of its end a tenth of the way in
// (Munich), and the distance alone ended it before its anchor.
TEST(ScenarioXoscWriter, TheEndStopsTheRunOnlyAfterTheEgoRanItsWay) {
    auto sc = scenario();
    sc.ego_run_m = 160.0;
    const auto doc = parse(xosc_text(sc));
    const std::string group = "/OpenSCENARIO/Storyboard/StopTrigger/ConditionGroup[Condition/@name='EgoAtEnd']";
    const auto conditions = doc.select_nodes((group + "/Condition").c_str());
    ASSERT_EQ(conditions.size(), 2u) << "near the end AND far enough along";
    EXPECT_EQ(attribute(doc, group + "/Condition[@name='EgoRanItsWay']//TraveledDistanceCondition", "value"), "145");
    EXPECT_EQ(attribute(doc, group + "/Condition[@name='EgoRanItsWay']//TriggeringEntities/EntityRef", "entityRef"),
              "Ego");
}

TEST(ScenarioXoscWriter, WithoutMovingActorsTheActKeepsAnEmptyEgoGroup) {
    auto sc = scenario();
    sc.others.clear();
    sc.ego_end.reset();
    const auto doc = parse(xosc_text(sc));
    EXPECT_EQ(attribute(doc, "//Act/ManeuverGroup/Actors/EntityRef", "entityRef"), "Ego");
    EXPECT_EQ(doc.select_nodes("/OpenSCENARIO/Storyboard/StopTrigger/ConditionGroup").size(), 1u);
}

TEST(ScenarioXoscWriter, CatalogDescribesTheTrainAndOrdersEntriesByKind) {
    const auto sc = scenario();
    // The walker first: the schema still wants vehicles before pedestrians.
    const auto doc = parse(catalog_text("VehicleCatalog", {sc.others[1], sc.ego, sc.others[0], sc.ego}));
    EXPECT_EQ(attribute(doc, "/OpenSCENARIO/Catalog", "name"), "VehicleCatalog");
    const std::string emu = "/OpenSCENARIO/Catalog/Vehicle[@name='regional_emu']";
    EXPECT_EQ(attribute(doc, emu, "vehicleCategory"), "train");
    EXPECT_EQ(attribute(doc, emu, "mass"), "120000");
    EXPECT_EQ(attribute(doc, emu + "/BoundingBox/Center", "z"), "2.1");
    EXPECT_EQ(attribute(doc, emu + "/BoundingBox/Dimensions", "length"), "68.5");
    EXPECT_EQ(attribute(doc, emu + "/Performance", "maxSpeed"), "44.4");
    EXPECT_EQ(attribute(doc, emu + "/Axles/FrontAxle", "trackWidth"), "1.435");
    EXPECT_EQ(attribute(doc, emu + "/Axles/RearAxle", "positionX"), "-23.975");
    EXPECT_EQ(attribute(doc, emu + "/Properties/Property[@name='odd.track_class']", "value"), "mainline");
    EXPECT_EQ(attribute(doc, emu + "/Properties/Property[@name='carla_blueprint']", "value"), "vehicle.railodd.emu");
    EXPECT_EQ(doc.select_nodes("/OpenSCENARIO/Catalog/Vehicle").size(), 2u) << "the ego's entry once";
    const auto children = doc.select_nodes("/OpenSCENARIO/Catalog/*");
    ASSERT_EQ(children.size(), 3u);
    EXPECT_STREQ(children[2].node().name(), "Pedestrian");
    EXPECT_STREQ(children[2].node().attribute("pedestrianCategory").value(), "pedestrian");
}

TEST(ScenarioXoscWriter, DistributionListsTheValueSets) {
    const auto doc = parse(distribution_text("../obstacle_on_track_0001.xosc",
                                             {{{"EgoSpeed", "25"}, {"FogVisualRange", "80"}},
                                              {{"EgoSpeed", "33.3"}, {"FogVisualRange", "200"}}},
                                             "obstacle_on_track", "2026-01-01T00:00:00", {}));
    EXPECT_EQ(attribute(doc, "//ParameterValueDistribution/ScenarioFile", "filepath"),
              "../obstacle_on_track_0001.xosc");
    const auto sets = doc.select_nodes("//Deterministic/DeterministicMultiParameterDistribution/"
                                       "ValueSetDistribution/ParameterValueSet");
    ASSERT_EQ(sets.size(), 2u);
    const pugi::xml_node second = sets[1].node().child("ParameterAssignment");
    EXPECT_STREQ(second.attribute("parameterRef").value(), "EgoSpeed");
    EXPECT_STREQ(second.attribute("value").value(), "33.3");

    // A set without assignments cannot be written (the schema wants one): skipped.
    const auto none = parse(distribution_text("a.xosc", {{}, {{"EgoSpeed", "20"}}}, "d", "2026-01-01T00:00:00", {}));
    EXPECT_EQ(none.select_nodes("//ParameterValueSet").size(), 1u);
    const auto empty = parse(distribution_text("a.xosc", {{}}, "d", "2026-01-01T00:00:00", {}));
    EXPECT_TRUE(select(empty, "//Deterministic"));
    EXPECT_FALSE(select(empty, "//Deterministic/*"));
}

TEST(ScenarioXoscWriter, RevisionsDifferWhereTheSchemasDo) {
    const auto v11 = parse(xosc_text(scenario(), {1}));
    EXPECT_EQ(attribute(v11, "//Weather", "cloudState"), "overcast");
    EXPECT_EQ(attribute(v11, "//Event", "priority"), "overwrite");
    const auto v13 = parse(xosc_text(scenario(), {3}));
    EXPECT_EQ(attribute(v13, "//Weather/Sun", "illuminance"), "100000");
    EXPECT_EQ(attribute(v13, "//Event", "priority"), "override");
    EXPECT_THROW(xosc_text(scenario(), {4}), railodd::UsageError);
}

TEST(ScenarioXoscWriter, WritingTwiceIsByteIdenticalAndLeavesNoTemporaryFile) {
    const auto dir = scratch_dir();
    write_xosc(scenario(), dir / "a.xosc");
    write_xosc(scenario(), dir / "b.xosc");
    write_file(dir / "c.xosc", "stale");
    write_xosc(scenario(), dir / "c.xosc"); // replaces an existing file
    const std::string a = read_file(dir / "a.xosc");
    EXPECT_FALSE(a.empty());
    EXPECT_EQ(a, read_file(dir / "b.xosc"));
    EXPECT_EQ(a, read_file(dir / "c.xosc"));
    EXPECT_EQ(a, xosc_text(scenario()));
    EXPECT_EQ(std::distance(fs::directory_iterator(dir), fs::directory_iterator{}), 3);
}

TEST(ScenarioXoscWriter, WritingIntoAMissingDirectoryThrowsAndLeavesNoFile) {
    const auto dir = scratch_dir();
    const fs::path file = dir / "missing" / "a.xosc";
    try {
        write_xosc(scenario(), file);
        FAIL() << "no OutputError";
    } catch (const railodd::OutputError& e) {
        EXPECT_EQ(e.where(), file.string());
    }
    EXPECT_THROW(write_catalog("VehicleCatalog", {train()}, file), railodd::OutputError);
    EXPECT_THROW(write_parameter_distribution("a.xosc", {}, "d", "2026-01-01T00:00:00", file),
                 railodd::OutputError);
    EXPECT_FALSE(fs::exists(dir / "missing"));
    EXPECT_TRUE(fs::is_empty(dir));
}

// ---- against the ASAM schemas in ../shared/data/schemas (label: shared) ----

namespace {

fs::path xsd(int rev_minor) {
    const fs::path dir = shared_data().empty() ? fs::path{} : shared_data() / "schemas";
    return dir / (rev_minor == 1 ? "OpenSCENARIOv1.1.1.xsd" : "OpenSCENARIOv1." + std::to_string(rev_minor) + ".xsd");
}

void expect_valid(const fs::path& schema, const fs::path& file) {
    const auto r = run_command("xmllint --noout --schema " + quoted(schema) + " " + quoted(file));
    EXPECT_EQ(r.exit_code, 0) << file << " against " << schema << ":\n" << r.output;
}

void validate_all(int rev_minor) {
    RAILODD_REQUIRE_SHARED_DATA();
    if (!fs::is_regular_file(xsd(rev_minor))) {
        GTEST_SKIP() << xsd(rev_minor) << " is absent: skipping schema test";
    }
    if (run_command("command -v xmllint").exit_code != 0) {
        GTEST_SKIP() << "xmllint is not installed (libxml2-utils): skipping schema test";
    }
    const auto dir = scratch_dir();
    const WriteOptions opt{rev_minor};
    const auto sc = scenario();
    write_xosc(sc, dir / "scenario.xosc", opt);
    auto bare = sc; // no parameters, no others, no route, no end
    bare.parameters.clear();
    bare.others.clear();
    bare.ego.route.clear();
    bare.ego_end.reset();
    write_xosc(bare, dir / "bare.xosc", opt);
    write_catalog("VehicleCatalog", {sc.ego, sc.others[0], sc.others[1]}, dir / "catalog.xosc", opt);
    auto box = car();
    box.kind = Actor::Kind::misc_object;
    box.category = "obstacle";
    box.catalog_entry = "crate";
    write_catalog("MiscObjectCatalog", {box}, dir / "misc.xosc", opt);
    write_parameter_distribution("scenario.xosc", {{{"EgoSpeed", "25"}}, {{"EgoSpeed", "30"}}}, "speeds",
                                 sc.date, dir / "distribution.xosc", opt);
    for (const char* f : {"scenario.xosc", "bare.xosc", "catalog.xosc", "misc.xosc", "distribution.xosc"}) {
        expect_valid(xsd(rev_minor), dir / f);
    }
}

} // namespace

TEST(ScenarioXoscSchema, ValidAgainstOpenScenario12) { validate_all(2); }
TEST(ScenarioXoscSchema, ValidAgainstOpenScenario13) { validate_all(3); }
TEST(ScenarioXoscSchema, ValidAgainstOpenScenario11) { validate_all(1); }
