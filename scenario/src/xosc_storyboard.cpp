// The storyboard of the scenario document: Init (environment, placements,
// speeds, the ego's route), one Story with an Event per moving actor, and the
// StopTrigger. Where the target cannot take the ego's route in the Init
// (target_support.hpp), the route becomes an Event of the ego's, as a
// FollowTrajectoryAction through the sampled run where the target's
// AssignRouteAction does not run either.
//
// Conditions use conditionEdge="none" (level-triggered): an edge could be
// missed when it is already true at the first evaluation (a trigger distance
// of 0, SimulationTime > 0), and the events run at most once anyway.
#include "xosc_support.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>
#include <vector>

namespace railodd::scenario::xosc {

namespace {

// How close (m) the ego's reference point must come to ego_end to stop the run:
// about two simulation steps of a fast train, so a step cannot jump over it.
constexpr double ego_end_tolerance_m = 5.0;

void teleport(pugi::xml_node priv, const LanePlacement& p) {
    position(priv.append_child("PrivateAction").append_child("TeleportAction"), p);
}

// The route's waypoints, at least two as the schema requires: a single
// waypoint is reached from the start.
std::vector<LanePlacement> waypoints(const Actor& a) {
    std::vector<LanePlacement> w;
    if (a.route.size() == 1) {
        w.push_back(a.start);
    }
    w.insert(w.end(), a.route.begin(), a.route.end());
    return w;
}

void assign_route(pugi::xml_node priv, const Actor& a) {
    const auto points = waypoints(a);
    if (points.empty()) {
        return;
    }
    pugi::xml_node route = priv.append_child("PrivateAction")
                               .append_child("RoutingAction")
                               .append_child("AssignRouteAction")
                               .append_child("Route");
    attr(route, "name", a.name + "Route");
    attr(route, "closed", "false");
    for (const auto& p : points) {
        pugi::xml_node w = route.append_child("Waypoint");
        attr(w, "routeStrategy", "shortest");
        position(w, p);
    }
}

// The target's controller module for the ego train (Profile::ego_controller),
// with every override off as ScenarioRunner requires.
void assign_controller(pugi::xml_node priv, const char* module) {
    pugi::xml_node action = priv.append_child("PrivateAction").append_child("ControllerAction");
    pugi::xml_node controller = action.append_child("AssignControllerAction").append_child("Controller");
    attr(controller, "name", "EgoController");
    pugi::xml_node p = controller.append_child("Properties").append_child("Property");
    attr(p, "name", "module");
    attr(p, "value", module);
    pugi::xml_node overrides = action.append_child("OverrideControllerValueAction");
    for (const char* name : {"Throttle", "Brake", "Clutch", "ParkingBrake", "SteeringWheel"}) {
        pugi::xml_node o = overrides.append_child(name);
        attr(o, "value", 0.0);
        attr(o, "active", "false");
    }
    pugi::xml_node gear = overrides.append_child("Gear");
    attr(gear, "number", 0.0);
    attr(gear, "active", "false");
}

void init_actor(pugi::xml_node actions, const Actor& a, bool is_ego, const Context& cx) {
    pugi::xml_node priv = actions.append_child("Private");
    attr(priv, "entityRef", a.name);
    teleport(priv, a.start);
    // The ego always gets a speed (the parameter EgoSpeed drives it); the
    // others only when they move from the start.
    if (is_ego) {
        // A late start stands first (ego_departs sets it off).
        speed_action(priv.append_child("PrivateAction"),
                     cx.scenario().ego_start_delay_s > 0.0
                         ? "0"
                         : cx.value("AbsoluteTargetSpeed", parameter_names::ego_speed, a.speed_mps));
        if (*cx.profile().ego_controller) {
            assign_controller(priv, cx.profile().ego_controller);
        }
    } else if (a.speed_mps > 0.0) {
        speed_action(priv.append_child("PrivateAction"), num(a.speed_mps));
    }
    if (!is_ego || cx.usable("AssignRouteAction", target_support::Where::init)) {
        assign_route(priv, a);
    }
}

pugi::xml_node condition(pugi::xml_node group, const std::string& name) {
    pugi::xml_node c = group.append_child("Condition");
    attr(c, "name", name);
    attr(c, "delay", 0.0);
    attr(c, "conditionEdge", "none");
    return c;
}

void simulation_time_condition(pugi::xml_node group, const std::string& name, const char* rule, double t) {
    pugi::xml_node c = condition(group, name)
                           .append_child("ByValueCondition")
                           .append_child("SimulationTimeCondition");
    attr(c, "value", t);
    attr(c, "rule", rule);
}

// <ByEntityCondition> of the ego under a new Condition; returns its EntityCondition.
pugi::xml_node ego_condition(pugi::xml_node group, const std::string& name, const Context& cx) {
    pugi::xml_node by = condition(group, name).append_child("ByEntityCondition");
    pugi::xml_node triggering = by.append_child("TriggeringEntities");
    attr(triggering, "triggeringEntitiesRule", "any");
    attr(triggering.append_child("EntityRef"), "entityRef", cx.scenario().ego.name);
    return by.append_child("EntityCondition");
}

// A FollowTrajectoryAction under `action` through the points at `speed`,
// the first point reached at t0 s, taken at the actor's own speed
// (TimeReference None): players steer it along the path, where an
// AcquirePositionAction leaves the way to their router (esmini drove road
// users along the railway) and competes with the SpeedAction for the
// longitudinal domain. OpenSCENARIO 1.0 needs each vertex's time and has
// the Trajectory without a TrajectoryRef.
void follow_trajectory(pugi::xml_node action, const std::string& name, const std::vector<TrackSample>& points,
                       double speed, double t0, const Context& cx) {
    pugi::xml_node follow =
        action.append_child("PrivateAction").append_child("RoutingAction").append_child("FollowTrajectoryAction");
    pugi::xml_node trajectory =
        (cx.rev_minor() < 1 ? follow : follow.append_child("TrajectoryRef")).append_child("Trajectory");
    attr(trajectory, "name", name);
    attr(trajectory, "closed", "false");
    pugi::xml_node polyline = trajectory.append_child("Shape").append_child("Polyline");
    for (const auto& p : points) {
        pugi::xml_node vertex = polyline.append_child("Vertex");
        if (cx.rev_minor() < 1) {
            attr(vertex, "time", t0 + p.distance_m / std::max(speed, 0.1));
        }
        position(vertex, p.place, false);
    }
    follow.append_child("TimeReference").append_child("None");
    attr(follow.append_child("TrajectoryFollowingMode"), "followingMode", "position");
}

// The actor's motion path with the distance along it: metres in s and
// across the lane, as the generator times the move (instantiate.cpp).
std::vector<TrackSample> motion_path(const Actor& a) {
    std::vector<LanePlacement> path = a.path;
    if (path.empty()) {
        path = {a.start, *a.target};
    }
    std::vector<TrackSample> out;
    for (const auto& p : path) {
        const double step = out.empty() ? 0.0
                                        : std::hypot(p.s - out.back().place.s, p.offset - out.back().place.offset);
        out.push_back({out.empty() ? 0.0 : out.back().distance_m + step, p});
    }
    return out;
}

void follow_path(pugi::xml_node event, const Actor& a, const Context& cx) {
    pugi::xml_node action = event.append_child("Action");
    attr(action, "name", a.name + "ToTarget");
    follow_trajectory(action, a.name + "Path", motion_path(a), a.target_speed_mps, 0.0, cx);
}

const char* priority(const Context& cx) { return cx.rev_minor() < 2 ? "overwrite" : "override"; } // renamed in 1.2

void actor_maneuver_group(pugi::xml_node act, const Actor& a, const Context& cx) {
    pugi::xml_node group = act.append_child("ManeuverGroup");
    attr(group, "maximumExecutionCount", 1);
    attr(group, "name", a.name + "Group");
    pugi::xml_node actors = group.append_child("Actors");
    attr(actors, "selectTriggeringEntities", "false");
    attr(actors.append_child("EntityRef"), "entityRef", a.name);

    pugi::xml_node maneuver = group.append_child("Maneuver");
    attr(maneuver, "name", a.name + "Maneuver");
    pugi::xml_node event = maneuver.append_child("Event");
    attr(event, "name", a.name + "Starts");
    attr(event, "priority", priority(cx));
    attr(event, "maximumExecutionCount", 1);

    pugi::xml_node speed = event.append_child("Action");
    attr(speed, "name", a.name + "Speed");
    speed_action(speed.append_child("PrivateAction"),
                 cx.value("AbsoluteTargetSpeed", a.name + "Speed", a.target_speed_mps));
    follow_path(event, a, cx);
    pugi::xml_node start = event.append_child("StartTrigger").append_child("ConditionGroup");
    pugi::xml_node travelled = ego_condition(start, "EgoTravelled", cx).append_child("TraveledDistanceCondition");
    attr(travelled, "value", cx.scenario().trigger_distance_m);

    // At the end of its path the actor stops (a car on the crossing, a
    // person on the track): without it a player's default controller drives
    // on along the lane.
    pugi::xml_node stop = maneuver.append_child("Event");
    attr(stop, "name", a.name + "Stops");
    attr(stop, "priority", priority(cx));
    attr(stop, "maximumExecutionCount", 1);
    pugi::xml_node halt = stop.append_child("Action");
    attr(halt, "name", a.name + "Halt");
    speed_action(halt.append_child("PrivateAction"), "0");
    pugi::xml_node done = condition(stop.append_child("StartTrigger").append_child("ConditionGroup"), a.name + "AtTarget")
                              .append_child("ByValueCondition")
                              .append_child("StoryboardElementStateCondition");
    attr(done, "storyboardElementType", "action");
    attr(done, "storyboardElementRef", a.name + "ToTarget");
    attr(done, "state", "endTransition");
}

pugi::xml_node ego_event(pugi::xml_node maneuver, const char* name, const Context& cx) {
    pugi::xml_node event = maneuver.append_child("Event");
    attr(event, "name", cx.scenario().ego.name + name);
    attr(event, "priority", priority(cx));
    attr(event, "maximumExecutionCount", 1);
    return event;
}

// The ego's route where the Init cannot take it: an AssignRouteAction where
// the target runs one in a Story, else a trajectory through the sampled run.
void ego_route(pugi::xml_node maneuver, const Context& cx) {
    const ConcreteScenario& sc = cx.scenario();
    pugi::xml_node event = ego_event(maneuver, "Route", cx);
    pugi::xml_node action = event.append_child("Action");
    attr(action, "name", sc.ego.name + "Route");
    if (cx.usable("AssignRouteAction", target_support::Where::story)) {
        assign_route(action, sc.ego);
    } else if (cx.usable("FollowTrajectoryAction", target_support::Where::story) && sc.ego_track.size() >= 2) {
        follow_trajectory(action, sc.ego.name + "Track", sc.ego_track, sc.ego.speed_mps, sc.ego_start_delay_s, cx);
    } else {
        throw std::logic_error("OpenSCENARIO writer: no way to give scenario " + sc.id + "'s ego its route under " +
                               to_string(cx.target()) + " (is the ego's track sampled for this target?)");
    }
    simulation_time_condition(event.append_child("StartTrigger").append_child("ConditionGroup"), "EgoSetsOff",
                              "greaterThan", 0.0);
}

// The ego's events: its route where the Init cannot take it, and its
// departure after ego_start_delay_s where the actors need the time
// (instantiate.cpp, move_start). Returns whether there was any.
bool ego_maneuver_group(pugi::xml_node act, const Context& cx) {
    const ConcreteScenario& sc = cx.scenario();
    const bool route = !cx.usable("AssignRouteAction", target_support::Where::init);
    if (!route && sc.ego_start_delay_s <= 0.0) {
        return false;
    }
    pugi::xml_node group = act.append_child("ManeuverGroup");
    attr(group, "maximumExecutionCount", 1);
    attr(group, "name", sc.ego.name + "Group");
    pugi::xml_node actors = group.append_child("Actors");
    attr(actors, "selectTriggeringEntities", "false");
    attr(actors.append_child("EntityRef"), "entityRef", sc.ego.name);
    pugi::xml_node maneuver = group.append_child("Maneuver");
    attr(maneuver, "name", sc.ego.name + "Maneuver");
    if (route) {
        ego_route(maneuver, cx);
    }
    if (sc.ego_start_delay_s > 0.0) {
        pugi::xml_node event = ego_event(maneuver, "Departs", cx);
        pugi::xml_node go = event.append_child("Action");
        attr(go, "name", sc.ego.name + "Speed");
        speed_action(go.append_child("PrivateAction"),
                     cx.value("AbsoluteTargetSpeed", parameter_names::ego_speed, sc.ego.speed_mps));
        simulation_time_condition(event.append_child("StartTrigger").append_child("ConditionGroup"), "EgoDelay",
                                  "greaterThan", sc.ego_start_delay_s);
    }
    return true;
}

// Condition groups are OR-ed: the run stops at stop_time_s or at ego_end,
// once the ego has run nearly its whole way there: a run round a tram's
// turning loop passes within the tolerance of its end before it reaches its
// anchor (Munich: 4.6 m, at a tenth of its run), and a distance alone
// ended it there.
void end_conditions(pugi::xml_node trigger, const Context& cx) {
    constexpr double run_slack_m = 10.0;
    const ConcreteScenario& sc = cx.scenario();
    simulation_time_condition(trigger.append_child("ConditionGroup"), "TimeOut", "greaterThan", sc.stop_time_s);
    if (sc.ego_end) {
        pugi::xml_node group = trigger.append_child("ConditionGroup");
        pugi::xml_node distance = ego_condition(group, "EgoAtEnd", cx).append_child("DistanceCondition");
        if (cx.rev_minor() < 1) {
            attr(distance, "alongRoute", "false"); // required in 1.0, deprecated since
        }
        attr(distance, "value", ego_end_tolerance_m);
        attr(distance, "freespace", "false");
        attr(distance, "rule", "lessThan");
        position(distance, *sc.ego_end);
        pugi::xml_node run = ego_condition(group, "EgoRanItsWay", cx).append_child("TraveledDistanceCondition");
        attr(run, "value", std::max(0.0, sc.ego_run_m - ego_end_tolerance_m - run_slack_m));
    }
}

} // namespace

void write_init(pugi::xml_node storyboard, const Context& cx) {
    pugi::xml_node actions = storyboard.append_child("Init").append_child("Actions");
    write_environment(actions.append_child("GlobalAction").append_child("EnvironmentAction"), cx);
    init_actor(actions, cx.scenario().ego, true, cx);
    for (const auto& a : cx.scenario().others) {
        init_actor(actions, a, false, cx);
    }
}

void write_story(pugi::xml_node storyboard, const Context& cx) {
    const ConcreteScenario& sc = cx.scenario();
    pugi::xml_node story = storyboard.append_child("Story");
    attr(story, "name", sc.id.empty() ? std::string{"Story"} : sc.id);
    pugi::xml_node act = story.append_child("Act");
    attr(act, "name", "Act");
    bool any = ego_maneuver_group(act, cx);
    for (const auto& a : sc.others) {
        if (a.target) {
            actor_maneuver_group(act, a, cx);
            any = true;
        }
    }
    if (!any) {
        // An Act needs a ManeuverGroup (and 1.1 a Story): the ego's, empty.
        pugi::xml_node group = act.append_child("ManeuverGroup");
        attr(group, "maximumExecutionCount", 1);
        attr(group, "name", sc.ego.name + "Group");
        pugi::xml_node actors = group.append_child("Actors");
        attr(actors, "selectTriggeringEntities", "false");
        attr(actors.append_child("EntityRef"), "entityRef", sc.ego.name);
    }
    simulation_time_condition(act.append_child("StartTrigger").append_child("ConditionGroup"), "ActStart",
                              "greaterThan", 0.0);
    if (!cx.profile().storyboard_stop_ends_run) {
        // The target ends the run when the Act ends: the Act stops where the
        // Storyboard would.
        end_conditions(act.append_child("StopTrigger"), cx);
    }
}

void write_stop_trigger(pugi::xml_node storyboard, const Context& cx) {
    end_conditions(storyboard.append_child("StopTrigger"), cx);
}

} // namespace railodd::scenario::xosc
