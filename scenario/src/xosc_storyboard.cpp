// The storyboard of the scenario document: Init (environment, placements,
// speeds, the ego's route), one Story with an Event per moving actor, and the
// StopTrigger.
//
// Conditions use conditionEdge="none" (level-triggered): an edge could be
// missed when it is already true at the first evaluation (a trigger distance
// of 0, SimulationTime > 0), and the events run at most once anyway.
#include "xosc_support.hpp"

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

void init_actor(pugi::xml_node actions, const Actor& a, bool is_ego, const Context& cx) {
    pugi::xml_node priv = actions.append_child("Private");
    attr(priv, "entityRef", a.name);
    teleport(priv, a.start);
    // The ego always gets a speed (the parameter EgoSpeed drives it); the
    // others only when they move from the start.
    if (is_ego) {
        // A late start stands first (ego_departs sets it off).
        speed_action(priv.append_child("PrivateAction"), cx.scenario().ego_start_delay_s > 0.0
                                                             ? "0"
                                                             : cx.value(parameter_names::ego_speed, a.speed_mps));
    } else if (a.speed_mps > 0.0) {
        speed_action(priv.append_child("PrivateAction"), num(a.speed_mps));
    }
    assign_route(priv, a);
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

// The motion as a polyline trajectory through the path's lane positions,
// taken at the actor's own speed (TimeReference None): players steer it
// along the path, where an AcquirePositionAction leaves the way to their
// router (esmini drove road users along the railway) and competes with the
// SpeedAction for the longitudinal domain.
void follow_path(pugi::xml_node event, const Actor& a) {
    pugi::xml_node action = event.append_child("Action");
    attr(action, "name", a.name + "ToTarget");
    pugi::xml_node follow =
        action.append_child("PrivateAction").append_child("RoutingAction").append_child("FollowTrajectoryAction");
    pugi::xml_node trajectory = follow.append_child("TrajectoryRef").append_child("Trajectory");
    attr(trajectory, "name", a.name + "Path");
    attr(trajectory, "closed", "false");
    pugi::xml_node polyline = trajectory.append_child("Shape").append_child("Polyline");
    std::vector<LanePlacement> path = a.path;
    if (path.empty()) {
        path = {a.start, *a.target};
    }
    for (const auto& p : path) {
        position(polyline.append_child("Vertex"), p, false);
    }
    follow.append_child("TimeReference").append_child("None");
    attr(follow.append_child("TrajectoryFollowingMode"), "followingMode", "position");
}

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
    attr(event, "priority", cx.rev_minor() < 2 ? "overwrite" : "override"); // renamed in 1.2
    attr(event, "maximumExecutionCount", 1);

    pugi::xml_node speed = event.append_child("Action");
    attr(speed, "name", a.name + "Speed");
    speed_action(speed.append_child("PrivateAction"), cx.value(a.name + "Speed", a.target_speed_mps));
    follow_path(event, a);
    pugi::xml_node start = event.append_child("StartTrigger").append_child("ConditionGroup");
    pugi::xml_node travelled = ego_condition(start, "EgoTravelled", cx).append_child("TraveledDistanceCondition");
    attr(travelled, "value", cx.scenario().trigger_distance_m);

    // At the end of its path the actor stops (a car on the crossing, a
    // person on the track): without it a player's default controller drives
    // on along the lane.
    pugi::xml_node stop = maneuver.append_child("Event");
    attr(stop, "name", a.name + "Stops");
    attr(stop, "priority", cx.rev_minor() < 2 ? "overwrite" : "override");
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

// The ego's departure after ego_start_delay_s, where the actors need the
// time (instantiate.cpp, move_start).
void ego_departs(pugi::xml_node act, const Context& cx) {
    const Actor& ego = cx.scenario().ego;
    pugi::xml_node group = act.append_child("ManeuverGroup");
    attr(group, "maximumExecutionCount", 1);
    attr(group, "name", ego.name + "Group");
    pugi::xml_node actors = group.append_child("Actors");
    attr(actors, "selectTriggeringEntities", "false");
    attr(actors.append_child("EntityRef"), "entityRef", ego.name);
    pugi::xml_node maneuver = group.append_child("Maneuver");
    attr(maneuver, "name", ego.name + "Maneuver");
    pugi::xml_node event = maneuver.append_child("Event");
    attr(event, "name", ego.name + "Departs");
    attr(event, "priority", cx.rev_minor() < 2 ? "overwrite" : "override");
    attr(event, "maximumExecutionCount", 1);
    pugi::xml_node go = event.append_child("Action");
    attr(go, "name", ego.name + "Speed");
    speed_action(go.append_child("PrivateAction"), cx.value(parameter_names::ego_speed, ego.speed_mps));
    simulation_time_condition(event.append_child("StartTrigger").append_child("ConditionGroup"), "EgoDelay",
                              "greaterThan", cx.scenario().ego_start_delay_s);
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
    bool any = sc.ego_start_delay_s > 0.0;
    if (any) {
        ego_departs(act, cx);
    }
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
}

// Condition groups are OR-ed: the run stops at stop_time_s or at ego_end.
void write_stop_trigger(pugi::xml_node storyboard, const Context& cx) {
    const ConcreteScenario& sc = cx.scenario();
    pugi::xml_node trigger = storyboard.append_child("StopTrigger");
    simulation_time_condition(trigger.append_child("ConditionGroup"), "TimeOut", "greaterThan", sc.stop_time_s);
    if (sc.ego_end) {
        pugi::xml_node distance =
            ego_condition(trigger.append_child("ConditionGroup"), "EgoAtEnd", cx).append_child("DistanceCondition");
        attr(distance, "value", ego_end_tolerance_m);
        attr(distance, "freespace", "false");
        attr(distance, "rule", "lessThan");
        position(distance, *sc.ego_end);
    }
}

} // namespace railodd::scenario::xosc
