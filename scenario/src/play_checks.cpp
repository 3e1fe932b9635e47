// A played scenario against its manifest entry: did the player run it
// cleanly, did the train stay on its lane and route, did every actor start
// where and move as the template says, did the hazard happen before the
// train got there; then the criticality figures (docs/scenarios.md,
// "Playing a set").
#include "play_geometry.hpp"

#include <algorithm>
#include <cmath>
#include <optional>
#include <sstream>

namespace railodd::scenario::play {

namespace {

using json = nlohmann::json;

std::string fmt(double v, int digits = 2) {
    std::ostringstream o;
    o.setf(std::ios::fixed);
    o.precision(digits);
    o << v;
    return o.str();
}

bool finite(const Sample& s) {
    return std::isfinite(s.t) && std::isfinite(s.x) && std::isfinite(s.y) && std::isfinite(s.h) &&
           std::isfinite(s.lane_offset) && std::isfinite(s.s) && std::isfinite(s.speed);
}

struct Run {
    const json& sc;
    const Trajectories& tr;
    const Options& o;
    std::vector<Check> checks;

    void check(std::string name, bool passed, std::string detail = {}) {
        checks.push_back({std::move(name), passed, std::move(detail)});
    }
    const std::vector<Sample>* samples(const std::string& name) const {
        const auto it = tr.find(name);
        return it == tr.end() || it->second.empty() ? nullptr : &it->second;
    }
};

// Per step, no entity moves further than its speed allows (half again, plus
// 0.3 m for the player's integration): a jump is a teleport or a snap to
// another road.
std::string first_jump(const std::vector<Sample>& v) {
    for (std::size_t i = 1; i < v.size(); ++i) {
        const double dt = v[i].t - v[i - 1].t;
        const double d = std::hypot(v[i].x - v[i - 1].x, v[i].y - v[i - 1].y);
        if (d > 1.5 * std::max(v[i].speed, v[i - 1].speed) * dt + 0.3) {
            return fmt(d) + " m at t = " + fmt(v[i].t);
        }
    }
    return {};
}

void common_checks(Run& r, const PlayerLog& log, const std::vector<std::string>& entities) {
    r.check("player errors", log.errors.empty(), log.errors.empty() ? "" : log.errors.front());
    std::string missing, nan, jump, off;
    for (const auto& name : entities) {
        const auto* v = r.samples(name);
        if (!v) {
            missing += (missing.empty() ? "" : ", ") + name;
            continue;
        }
        for (const Sample& s : *v) {
            if (!finite(s) && nan.empty()) {
                nan = name + " at t = " + fmt(s.t);
            }
            if ((s.road_id.empty() || s.road_id == "-1") && off.empty()) {
                off = name + " at t = " + fmt(s.t);
            }
        }
        if (const std::string j = first_jump(*v); !j.empty() && jump.empty()) {
            jump = name + " " + j;
        }
    }
    r.check("every entity recorded", missing.empty(), missing.empty() ? "" : "missing: " + missing);
    r.check("no NaN", nan.empty(), nan);
    r.check("no jumps", jump.empty(), jump);
    r.check("on the road network", off.empty(), off.empty() ? "" : "off the network: " + off);
}

// The route's roads in order within the ego's (others only between them:
// connecting roads of the junctions it passes).
bool follows_route(const std::vector<Sample>& ego, const json& route, std::string& detail) {
    std::vector<std::string> seq;
    for (const Sample& s : ego) {
        if (seq.empty() || seq.back() != s.road_id) {
            seq.push_back(s.road_id);
        }
    }
    std::size_t next = 0;
    for (const std::string& road : seq) {
        if (next < route.size() && road == route[next].get<std::string>()) {
            ++next;
        } else if (next == 0 || next == route.size()) {
            detail = "on road " + road + (next == 0 ? " before" : " after") + " its route";
            return false;
        }
    }
    if (next < route.size()) {
        detail = "never on road " + route[next].get<std::string>();
        return false;
    }
    return true;
}

// Passed between two samples on the road, or within a step (plus `slack`)
// of the place where the road ends there or the run stops.
bool passes(const std::vector<Sample>& ego, const std::string& road, double s, double slack) {
    for (std::size_t i = 1; i < ego.size(); ++i) {
        const double step = std::hypot(ego[i].x - ego[i - 1].x, ego[i].y - ego[i - 1].y) + 0.5 + slack;
        if ((ego[i].road_id == road && ego[i - 1].road_id == road && (ego[i - 1].s - s) * (ego[i].s - s) <= 0.0) ||
            (ego[i].road_id == road && std::abs(ego[i].s - s) <= step)) {
            return true;
        }
    }
    return false;
}

void ego_checks(Run& r, const std::vector<Sample>& ego) {
    const json& e = r.sc.at("ego");
    const int lane = e.at("start").at("lane_id").get<int>();
    double worst = 0.0;
    std::string other_lane;
    for (const Sample& s : ego) {
        worst = std::max(worst, std::abs(s.lane_offset));
        if (s.lane_id != lane && other_lane.empty()) {
            other_lane = "lane " + std::to_string(s.lane_id) + " of road " + s.road_id + " at t = " + fmt(s.t);
        }
    }
    r.check("ego on its rail lane", worst <= r.o.lane_tolerance_m && other_lane.empty(),
            other_lane.empty() ? "largest distance from the lane centre " + fmt(worst, 3) + " m" : other_lane);
    std::string detail;
    r.check("ego follows its route", follows_route(ego, e.at("route_roads"), detail), detail);
    // A run that stops short of its anchor (a buffer stop) must reach its
    // end instead; the stop trigger fires within 5 m of it.
    const bool stops_short = e.contains("stops_short_of_anchor") && e.at("stops_short_of_anchor").get<bool>();
    const json& a = stops_short ? e.at("end") : r.sc.at("anchor");
    const std::string road = a.at("road_id").get<std::string>();
    const double s_anchor = a.at("s").get<double>();
    r.check(stops_short ? "ego reaches its stop" : "ego reaches the anchor", passes(ego, road, s_anchor, stops_short ? 6.0 : 0.0),
            "road " + road + " s " + fmt(s_anchor, 1));
}

bool on_route_road(const json& sc, const std::string& road) {
    for (const auto& id : sc.at("ego").at("route_roads")) {
        if (id.get<std::string>() == road) {
            return true;
        }
    }
    return false;
}

void start_checks(Run& r, const json& actor, const std::vector<Sample>& v, const Path& path) {
    const std::string name = actor.at("name");
    const json& st = actor.at("start");
    const Sample& first = v.front();
    const std::string road = st.at("road_id");
    const bool placed = first.road_id == road && std::abs(first.s - st.at("s").get<double>()) <= 0.5;
    r.check(name + " starts in place", placed,
            "road " + first.road_id + " lane " + std::to_string(first.lane_id) + " s " + fmt(first.s, 1));
    if (actor.at("place") == "crossing_approach") {
        // A road user on its own road, not an offset beside the railway.
        r.check(name + " starts on the crossing road", !on_route_road(r.sc, road), "road " + road);
    } else if (const auto foot = path.empty() ? Path::Foot{} : path.project(first.x, first.y);
               on_route_road(r.sc, road) && foot.chainage > 0.0 && foot.chainage < path.length()) {
        // Measured where the recorded run passes the actor: a run that
        // stops short of it (a buffer stop) has no track to measure from.
        const double want = std::abs(st.value("offset", 0.0));
        const double got = foot.distance;
        r.check(name + " starts beside the track as placed", std::abs(got - want) <= 0.5,
                fmt(got) + " m from the track centre, placed at " + fmt(want) + " m");
    }
}

// How near an actor must come to its target's place on the map (target x,
// y, where play placed it) to be there.
constexpr double target_reach_m = 1.5;

// The distance from a sample to its actor's target's place on the map;
// none where the target has no place (road and s only).
std::optional<double> from_place(const Sample& s, const json& target) {
    if (!target.contains("x") || !target.contains("y")) {
        return std::nullopt;
    }
    return std::hypot(s.x - target.at("x").get<double>(), s.y - target.at("y").get<double>());
}

// A road user moving to the crossing stays on its road's lane all the way.
// At its target's place the player may report the road its own road ends
// on (a crossing road cut short at the track: Munich, a car 0.1 m onto the
// next road at its target), as target_check allows.
void road_user_checks(Run& r, const json& actor, const std::vector<Sample>& v) {
    const std::string name = actor.at("name"), road = actor.at("start").at("road_id");
    const json& target = actor.at("target");
    std::string left;
    for (const Sample& s : v) {
        const auto miss = from_place(s, target);
        const bool off = s.road_id != road ? !(miss && *miss <= target_reach_m) : std::abs(s.lane_offset) > 0.5;
        if (off && left.empty()) {
            left = "road " + s.road_id + " offset " + fmt(s.lane_offset) + " at t = " + fmt(s.t);
        }
    }
    r.check(name + " stays on its road's lane", left.empty(), left);
}

// At the target: within 1.5 m of its place on the map where play placed it
// (target x, y), else at its road and s as the player reports them; or, for
// a move onto the track, on the track as the ego recorded it. Where roads
// overlap (a parallel road, a crossing road cut short) the player may report
// the other road's id: the map's place does not depend on it.
void target_check(Run& r, const json& actor, const std::vector<Sample>& v, const Path& path) {
    const json& target = actor.at("target");
    const Sample& last = v.back();
    const std::optional<double> off_place = from_place(last, target);
    const bool placed = off_place.has_value();
    const double miss = placed ? *off_place : std::abs(last.s - target.at("s").get<double>());
    bool there = miss <= target_reach_m && (placed || last.road_id == target.at("road_id").get<std::string>());
    if (!there && actor.value("move_to", "") == "on_track" && !path.empty()) {
        const auto foot = path.project(last.x, last.y);
        there = foot.chainage > 0.0 && foot.chainage < path.length() &&
                foot.distance <= std::abs(target.value("offset", 0.0)) + 0.5;
    }
    r.check(actor.at("name").get<std::string>() + " reaches its target", there,
            "ends on road " + last.road_id + " s " + fmt(last.s, 1) +
                (placed ? ", " + fmt(miss, 1) + " m from its place on the map" : ""));
}

// An actor timed by its template (hazard_before_m) is at its target when
// the ego's front is that far short of it: within a tenth, or 15 m.
void timing_checks(Run& r, const Criticality& c) {
    for (const auto& a : r.sc.at("actors")) {
        if (!a.contains("hazard_before_m")) {
            continue;
        }
        const std::string name = a.at("name");
        const double want = a.at("hazard_before_m");
        const auto f = std::find_if(c.actors.begin(), c.actors.end(), [&](const ActorFigures& x) { return x.name == name; });
        const bool known = f != c.actors.end() && f->distance_at_arrival_m;
        const bool on_time = known && std::abs(*f->distance_at_arrival_m - want) <= std::max(15.0, 0.1 * want);
        r.check(name + " on time", on_time,
                known ? "at its target when the train front is " + fmt(*f->distance_at_arrival_m, 1) + " m short (template: " +
                            fmt(want, 0) + " m)"
                      : "never reached its target");
    }
}

} // namespace

bool Analysis::passed() const {
    return std::all_of(checks.begin(), checks.end(), [](const Check& c) { return c.passed; });
}

Analysis analyse(const json& sc, const Trajectories& tr, const PlayerLog& log, const Options& o) {
    Run r{sc, tr, o, {}};
    std::vector<std::string> entities{"Ego"};
    for (const auto& a : sc.at("actors")) {
        entities.push_back(a.at("name"));
    }
    common_checks(r, log, entities);
    Analysis out;
    const auto* ego = r.samples("Ego");
    if (!ego) {
        out.checks = std::move(r.checks);
        return out;
    }
    ego_checks(r, *ego);
    const Path path(*ego);
    for (const auto& a : sc.at("actors")) {
        const auto* v = r.samples(a.at("name"));
        if (!v) {
            continue;
        }
        start_checks(r, a, *v, path);
        if (a.contains("target")) {
            target_check(r, a, *v, path);
            if (a.at("place") == "crossing_approach" && a.at("kind") != "pedestrian") {
                road_user_checks(r, a, *v);
            }
        }
    }
    out.criticality = criticality(sc, tr, path, o);
    for (const auto& a : sc.at("actors")) {
        if (a.value("move_to", "") != "on_track") {
            continue;
        }
        // The hazard: the actor inside the train's clearance while the train
        // is still short of it.
        const std::string name = a.at("name");
        const auto f = std::find_if(out.criticality.actors.begin(), out.criticality.actors.end(),
                                    [&](const ActorFigures& x) { return x.name == name; });
        const bool happened = f != out.criticality.actors.end() && f->onset_s && *f->distance_at_onset_m > 0.0;
        r.check(name + " in the clearance before the train", happened,
                happened ? "at t = " + fmt(*f->onset_s) + ", train front " + fmt(*f->distance_at_onset_m, 1) + " m short"
                         : "never inside the clearance ahead of the train");
    }
    timing_checks(r, out.criticality);
    out.checks = std::move(r.checks);
    return out;
}

} // namespace railodd::scenario::play
