#pragma once
// What a target player reads of OpenSCENARIO, element by element, and the
// few facts about it that are not an element's support: the one place the
// writer asks before it writes an action, a condition or a position
// (docs/scenarios.md "Targets"). Internal to the scenario library.
#include "railodd/scenario/target.hpp"

#include <pugixml.hpp>

#include <string_view>

namespace railodd::scenario::target_support {

// Where an element stands: outside the Storyboard (header, parameters,
// catalog locations, entities, catalog documents), in the Init, or in a
// Story or the Storyboard's StopTrigger. ScenarioRunner's table has separate
// Init and Story columns for its actions.
enum class Where { setup, init, story };

// Whether the target reads `element` there. The esmini target reads
// everything the writer writes: it has no table.
bool supported(Target t, std::string_view element, Where where);

// Supported and known to run. ScenarioRunner 0.9.16 lists AssignRouteAction
// and AcquirePositionAction for a Story, but builds both with
// ChangeActorWaypoints(times=None), whose constructor takes len(None) and
// raises TypeError (srunner/scenariomanager/scenarioatomics/atomic_behaviors.py).
bool usable(Target t, std::string_view element, Where where);

// Whether the target resolves "$Name" references in the element's attributes.
// ScenarioRunner resolves them through ParameterRef where it parses speeds,
// distances, times, positions and catalog entry names, but reads the
// Environment's attributes raw (float("$SunElevation") fails).
bool resolves_parameters(Target t, std::string_view element);

// Facts about the target that no element table says.
struct Profile {
    // A Precipitation of type snow: CARLA's weather has no snowfall.
    bool snow = true;
    // The Sun's intensity is read as 1 - cloud cover (ScenarioRunner:
    // cloudiness = 100 - 100 x intensity), not as illuminance.
    bool sun_intensity_is_cloudiness = false;
    // The Storyboard's StopTrigger ends the run. ScenarioRunner reads it only
    // for conditions named criteria_*; an Act's StopTrigger ends the Act.
    bool storyboard_stop_ends_run = true;
    // The ego is told apart by a catalog Property type = ego_vehicle.
    bool ego_type_property = false;
    // Every scenario names all three catalogs, written or not (the set writes
    // a catalog only for the kinds it uses). ScenarioRunner warns for each
    // location whose file is missing: it gets only the kinds the scenario uses.
    bool all_catalog_locations = true;
    // Controller module given to the ego train in the Init ("" none).
    // simple_vehicle_control sets the velocity along the given positions
    // without CARLA's vehicle engine, as rails guide a train; the default
    // npc_vehicle_control steers a car with a PID controller.
    const char* ego_controller = "";
};
const Profile& profile(Target t);

// Throws std::logic_error naming the first element of the document (with
// its path) that the target does not read where it stands: the writer's own
// guard that it wrote only what the target supports. No-op for esmini.
void check_document(const pugi::xml_node& root, Target t);

} // namespace railodd::scenario::target_support
