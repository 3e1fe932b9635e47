// The target players: their names, revisions and catalog entry names
// (target.hpp), and what each reads of OpenSCENARIO (target_support.hpp).
#include "target_support.hpp"

#include "railodd/util/errors.hpp"

#include <algorithm>
#include <array>
#include <map>
#include <stdexcept>
#include <string>

namespace railodd::scenario {

// ---- target.hpp: names, revisions, catalog entry names -------------------

Target target_from(std::string_view name) {
    if (name == "esmini") {
        return Target::esmini;
    }
    if (name == "carla") {
        return Target::carla;
    }
    throw std::invalid_argument("'" + std::string(name) + "' is not a target: esmini or carla");
}

const char* to_string(Target t) { return t == Target::carla ? "carla" : "esmini"; }

int default_revision(Target t) { return t == Target::carla ? 0 : 2; }

void check_revision_for(Target t, int rev_minor) {
    if (t == Target::carla && rev_minor != 0) {
        // openscenario_configuration.py _check_version: "Only OpenSCENARIO 1.0 is supported".
        throw UsageError("OpenSCENARIO 1." + std::to_string(rev_minor),
                         "the carla target writes OpenSCENARIO 1.0, the only revision ScenarioRunner reads");
    }
    if (t == Target::esmini && (rev_minor < 1 || rev_minor > 3)) {
        throw UsageError("OpenSCENARIO 1." + std::to_string(rev_minor),
                         "unsupported revision: the esmini target writes 1.1, 1.2 and 1.3");
    }
}

const std::string& entry_name(const Asset& asset, Target t) {
    return t == Target::carla && !asset.carla_blueprint.empty() ? asset.carla_blueprint : asset.osc_entry;
}

void check_catalog_for(const Catalog& catalog, Target t) {
    if (t != Target::carla) {
        return; // esmini's entries are the osc_entry names the catalog loader checked
    }
    std::map<std::string, const Asset*> seen;
    for (const auto& a : catalog.assets) {
        const auto [it, fresh] = seen.emplace(entry_name(a, t), &a);
        if (!fresh) {
            throw InputError(catalog.source + ":" + std::to_string(a.line),
                             "assets '" + it->second->id + "' and '" + a.id + "' share carla_blueprint '" +
                                 it->first +
                                 "': ScenarioRunner spawns the blueprint a catalog entry is named after, so "
                                 "under --target carla each asset needs a blueprint of its own");
        }
    }
}

// ScenarioRunner's OpenSCENARIO support, as carla-simulator/scenario_runner
// documents it in Docs/openscenario_support.md (0.9.16 release, commit
// 94ff3b8af752bad2b9d464ad5105868906aa34c0) and as its parser
// (srunner/tools/openscenario_parser.py, srunner/scenarios/open_scenario.py,
// srunner/scenarioconfigs/openscenario_configuration.py) reads it.
//
// Every row of the document's tables is here with its Init and Story
// columns. The document says an action's support "applies to all
// submodules", so the elements inside a supported row (a SpeedAction's
// target, a Trajectory's Polyline, a catalog entry's BoundingBox) are rows
// of their own marked as parts; only the parts the writer may write are
// listed, so that check_document also catches an element nobody reviewed.
namespace target_support {

namespace {

struct Row {
    const char* element;
    bool setup;
    bool init;
    bool story;
    bool resolves = true; // "$Name" references in its attributes resolved
};

constexpr bool Y = true;
constexpr bool N = false;

// clang-format off
constexpr std::array scenario_runner{
    // "General OpenSCENARIO setup"
    Row{"OpenSCENARIO", Y, N, N},            // document root (part)
    Row{"FileHeader", Y, N, N},
    Row{"ParameterDeclarations", Y, Y, Y},
    Row{"ParameterDeclaration", Y, Y, Y},    // part of ParameterDeclarations
    Row{"CatalogLocations", Y, N, N},
    Row{"VehicleCatalog", Y, N, N},
    Row{"ControllerCatalog", Y, N, N},
    Row{"PedestrianCatalog", Y, N, N},
    Row{"MiscObjectCatalog", Y, N, N},
    Row{"EnvironmentCatalog", Y, N, N},
    Row{"ManeuverCatalog", Y, N, N},
    Row{"TrajectoryCatalog", Y, N, N},
    Row{"RouteCatalog", Y, N, N},
    Row{"Directory", Y, N, N},               // part of the catalog locations
    Row{"RoadNetwork", Y, N, N},             // part: holds LogicFile
    Row{"LogicFile", Y, N, N},
    Row{"SceneGraphFile", N, N, N},
    Row{"TrafficSignals", N, N, N},
    Row{"Entities", Y, N, N},                // part: holds the ScenarioObjects
    Row{"EntitySelection", N, N, N},
    Row{"ScenarioObject", Y, N, N},          // part: holds the rows below
    Row{"CatalogReference", Y, N, N},
    Row{"ParameterAssignments", Y, N, N},    // part of CatalogReference
    Row{"ParameterAssignment", Y, N, N},     // part of CatalogReference
    Row{"MiscObject", Y, N, N, N},           // name, model and category read raw
    Row{"ObjectController", N, N, N},
    Row{"Pedestrian", Y, N, N, N},
    Row{"Vehicle", Y, N, N, N},
    // Parts of a catalog document and of its entries ("BoundingBox entries are ignored")
    Row{"Catalog", Y, N, N},
    Row{"BoundingBox", Y, N, N},
    Row{"Center", Y, N, N},
    Row{"Dimensions", Y, N, N},
    Row{"Performance", Y, N, N},
    Row{"Axles", Y, N, N},
    Row{"FrontAxle", Y, N, N},
    Row{"RearAxle", Y, N, N},
    Row{"Properties", Y, Y, Y},              // entries, controllers
    Row{"Property", Y, Y, Y},
    // The Storyboard ("Stories and the Storyboard"); Where of an element is
    // that of its own position, so Init and Story are parts of each column.
    Row{"Storyboard", Y, N, N},
    Row{"Init", N, Y, N},
    Row{"Actions", N, Y, N},
    Row{"Private", N, Y, N},
    Row{"PrivateAction", N, Y, Y},
    Row{"GlobalAction", N, Y, Y},
    Row{"Story", N, N, Y},
    Row{"Act", N, N, Y},
    Row{"ManeuverGroup", N, N, Y},
    Row{"Actors", N, N, Y},
    Row{"EntityRef", N, N, Y},
    Row{"Maneuver", N, N, Y},
    Row{"Event", N, N, Y},
    Row{"Action", N, N, Y},
    Row{"StartTrigger", N, N, Y},
    Row{"StopTrigger", N, N, Y},
    Row{"ConditionGroup", N, N, Y},
    Row{"Condition", N, N, Y},
    Row{"ByEntityCondition", N, N, Y},
    Row{"TriggeringEntities", N, N, Y},
    Row{"EntityCondition", N, N, Y},
    Row{"ByValueCondition", N, N, Y},
    // GlobalAction
    Row{"EntityAction", N, Y, Y},
    Row{"EnvironmentAction", N, Y, N},
    Row{"ParameterAction", N, Y, Y},
    Row{"InfrastructureAction", N, N, Y},    // part of the two rows below
    Row{"TrafficSignalAction", N, N, Y},
    Row{"TrafficAction", N, N, N},
    Row{"TrafficSignalControllerAction", N, N, Y},
    Row{"TrafficSignalStateAction", N, N, Y},
    Row{"Environment", N, Y, N},             // parts of EnvironmentAction, read raw
    Row{"TimeOfDay", N, Y, N, N},
    Row{"Weather", N, Y, N, N},
    Row{"Sun", N, Y, N, N},
    Row{"Fog", N, Y, N, N},
    Row{"Precipitation", N, Y, N, N},
    Row{"RoadCondition", N, Y, N, N},
    // UserDefinedAction
    Row{"UserDefinedAction", N, N, Y},
    Row{"CustomCommandAction", N, N, Y},
    // PrivateAction
    Row{"ActivateControllerAction", N, N, Y},
    Row{"ControllerAction", N, Y, Y},
    Row{"AssignControllerAction", N, Y, Y},  // parts of ControllerAction
    Row{"Controller", N, Y, Y},
    Row{"OverrideControllerValueAction", N, Y, Y},
    Row{"Throttle", N, Y, Y},
    Row{"Brake", N, Y, Y},
    Row{"Clutch", N, Y, Y},
    Row{"ParkingBrake", N, Y, Y},
    Row{"SteeringWheel", N, Y, Y},
    Row{"Gear", N, Y, Y},
    Row{"LateralAction", N, Y, Y},           // part: holds the three rows below
    Row{"LaneChangeAction", N, N, Y},
    Row{"LaneOffsetAction", N, N, Y},
    Row{"LateralDistanceAction", N, Y, Y},
    Row{"LongitudinalAction", N, Y, Y},      // part: holds the two rows below
    Row{"LongitudinalDistanceAction", N, N, Y},
    Row{"SpeedAction", N, Y, Y},
    Row{"SpeedActionDynamics", N, Y, Y},     // parts of SpeedAction
    Row{"SpeedActionTarget", N, Y, Y},
    Row{"AbsoluteTargetSpeed", N, Y, Y},
    Row{"SynchronizeAction", N, N, N},
    Row{"TeleportAction", N, Y, Y},
    Row{"VisibilityAction", N, N, N},
    Row{"RoutingAction", N, N, Y},           // part: holds the three rows below
    Row{"AcquirePositionAction", N, N, Y},
    Row{"AssignRouteAction", N, N, Y},
    Row{"Route", N, N, Y},                   // parts of AssignRouteAction
    Row{"Waypoint", N, N, Y},
    Row{"FollowTrajectoryAction", N, N, Y},
    Row{"Trajectory", N, N, Y},              // parts of FollowTrajectoryAction
    Row{"Shape", N, N, Y},
    Row{"Polyline", N, N, Y},
    Row{"Vertex", N, N, Y, N},               // time read with float()
    Row{"TimeReference", N, N, Y},
    Row{"None", N, N, Y},
    Row{"TrajectoryFollowingMode", N, N, Y},
    // ByEntityCondition
    Row{"AccelerationCondition", N, N, Y},
    Row{"CollisionCondition", N, N, Y},
    Row{"DistanceCondition", N, N, Y},
    Row{"EndOfRoadCondition", N, N, Y},
    Row{"OffroadCondition", N, N, Y},
    Row{"ReachPositionCondition", N, N, Y},
    Row{"RelativeDistanceCondition", N, N, Y},
    Row{"RelativeSpeedCondition", N, N, Y},
    Row{"SpeedCondition", N, N, Y},
    Row{"StandStillCondition", N, N, Y},
    Row{"TimeHeadwayCondition", N, N, Y},
    Row{"TimeToCollisionCondition", N, N, Y},
    Row{"TraveledDistanceCondition", N, N, Y},
    // ByValueCondition
    Row{"ParameterCondition", N, N, Y},
    Row{"SimulationTimeCondition", N, N, Y},
    Row{"StoryboardElementStateCondition", N, N, Y},
    Row{"TimeOfDayCondition", N, N, Y},
    Row{"TrafficSignalCondition", N, N, Y},
    Row{"TrafficSignalControllerCondition", N, N, Y},
    Row{"UserDefinedValueCondition", N, N, N},
    // Positions, wherever an action or condition holds them
    Row{"Position", Y, Y, Y},                // part
    Row{"Orientation", Y, Y, Y},             // part of the positions
    Row{"LanePosition", Y, Y, Y},
    Row{"RelativeLanePosition", Y, Y, Y},
    Row{"RelativeObjectPosition", Y, Y, Y},
    Row{"RelativeRoadPosition", Y, Y, Y},
    Row{"RelativeWorldPosition", Y, Y, Y},
    Row{"RoadPosition", Y, Y, Y},
    Row{"RoutePosition", N, N, N},
    Row{"WorldPosition", Y, Y, Y},
};
// clang-format on

// Documented, but fails in the 0.9.16 code (see usable() in the header).
constexpr std::array scenario_runner_fails{"AssignRouteAction", "AcquirePositionAction"};

const Row* find(std::string_view element) {
    const auto it = std::find_if(scenario_runner.begin(), scenario_runner.end(),
                                 [&](const Row& r) { return element == r.element; });
    return it == scenario_runner.end() ? nullptr : &*it;
}

const char* where_name(Where w) {
    return w == Where::init ? "the Init" : w == Where::story ? "a Story or StopTrigger" : "the setup";
}

Where where_of(const pugi::xml_node& node) {
    for (pugi::xml_node n = node; n; n = n.parent()) {
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

std::string path_of(const pugi::xml_node& node) {
    std::string path;
    for (pugi::xml_node n = node; n && n.type() == pugi::node_element; n = n.parent()) {
        path = "/" + std::string(n.name()) + path;
    }
    return path;
}

} // namespace

bool supported(Target t, std::string_view element, Where where) {
    if (t == Target::esmini) {
        return true;
    }
    const Row* r = find(element);
    return r && (where == Where::setup ? r->setup : where == Where::init ? r->init : r->story);
}

bool usable(Target t, std::string_view element, Where where) {
    if (!supported(t, element, where)) {
        return false;
    }
    return t == Target::esmini || std::none_of(scenario_runner_fails.begin(), scenario_runner_fails.end(),
                                               [&](const char* e) { return element == e; });
}

bool resolves_parameters(Target t, std::string_view element) {
    if (t == Target::esmini) {
        return true;
    }
    const Row* r = find(element);
    return r && r->resolves;
}

const Profile& profile(Target t) {
    static const Profile esmini{};
    static const Profile carla{.snow = false,
                               .sun_intensity_is_cloudiness = true,
                               .storyboard_stop_ends_run = false,
                               .ego_type_property = true,
                               .all_catalog_locations = false,
                               .ego_controller = "simple_vehicle_control"};
    return t == Target::carla ? carla : esmini;
}

void check_document(const pugi::xml_node& root, Target t) {
    if (t == Target::esmini) {
        return;
    }
    for (pugi::xml_node n = root; n;) {
        if (n.type() == pugi::node_element && !supported(t, n.name(), where_of(n))) {
            throw std::logic_error("OpenSCENARIO writer: " + path_of(n) + " is not read by " + to_string(t) +
                                   " in " + where_name(where_of(n)));
        }
        // Depth first, without recursion.
        if (n.first_child()) {
            n = n.first_child();
            continue;
        }
        while (n && n != root && !n.next_sibling()) {
            n = n.parent();
        }
        n = (n && n != root) ? n.next_sibling() : pugi::xml_node{};
    }
}

} // namespace target_support

} // namespace railodd::scenario
