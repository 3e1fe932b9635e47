// Anchors come from the ODD profile rather than from the map: the profile
// already says, with chainage and OSM ids, where each element lies, so a
// scenario's place is traceable to the same data the route's ODD is.
#include "railodd/scenario/anchors.hpp"

#include <algorithm>
#include <cmath>
#include <string_view>
#include <variant>

namespace railodd::scenario {

namespace {

constexpr const char* speed_limit = "Operational Conditions/Speed/Speed limit";
constexpr double min_overrun_m = 20.0; // past the anchor: the stop trigger's 5 m and a step of a fast train, with room
constexpr double eps = 1e-6;

bool under(const std::string& path, const std::string& element) {
    return path == element || (path.size() > element.size() && path.compare(0, element.size(), element) == 0 &&
                               path[element.size()] == '/');
}

bool holds(const odd::AttributeValue& v, const AttributeCondition& c) {
    if (const double* x = std::get_if<double>(&v)) {
        if (!c.values.empty()) {
            return false;
        }
        return (!c.min || *x >= *c.min) && (!c.max || *x <= *c.max);
    }
    const std::string text = std::holds_alternative<bool>(v) ? (std::get<bool>(v) ? "true" : "false")
                                                             : std::get<std::string>(v);
    return !c.min && !c.max && std::find(c.values.begin(), c.values.end(), text) != c.values.end();
}

double anchor_point(const odd::TaggedElement& e, AnchorAt at) {
    switch (at) {
    case AnchorAt::start: return e.chainage_start;
    case AnchorAt::middle: return 0.5 * (e.chainage_start + e.chainage_end);
    case AnchorAt::end: return e.chainage_end;
    }
    return e.chainage_start;
}

// The context element nearest before the anchor within reach; none if there is none.
using LineElements = std::map<std::size_t, std::vector<std::size_t>>;

std::optional<std::size_t> context_before(const odd::OddProfile& p, const std::vector<std::size_t>& on_line,
                                          double chainage, const ContextRequirement& c) {
    std::optional<std::size_t> best;
    for (const std::size_t i : on_line) {
        const auto& e = p.elements[i];
        if (e.chainage_end > chainage + eps || e.chainage_end < chainage - c.within_m || !matches(e, c)) {
            continue;
        }
        if (!best || e.chainage_end > p.elements[*best].chainage_end) {
            best = i;
        }
    }
    return best;
}

double limit_at(const odd::OddProfile& p, const std::vector<std::size_t>& on_line, double chainage) {
    for (const std::size_t i : on_line) {
        const auto& e = p.elements[i];
        if (e.element == speed_limit && e.chainage_start <= chainage + eps &&
            e.chainage_end >= chainage - eps) {
            if (const auto* v = e.find("maxspeed"); v && std::holds_alternative<double>(*v)) {
                return std::get<double>(*v);
            }
        }
    }
    return std::numeric_limits<double>::quiet_NaN();
}

// The run-up a template's timed hazards need: the train's front must start
// further from each conflict point (the anchor, moved along_m) than the
// distance the hazard is timed at.
double hazard_run_up(const Template& t, double ego_half_length_m) {
    double need = 0.0;
    for (const auto& a : t.actors) {
        if (a.move_to && a.hazard_before_m) {
            need = std::max(need, *a.hazard_before_m + ego_half_length_m - a.along_m + 1.0);
        }
    }
    return need;
}

// The stop trigger fires within 5 m of the run's end, so an end a few metres
// into a road (a junction's connecting road) stops the train before it enters
// that road, off its route's last road: such an end moves back onto the road
// before (and on, past roads too short to hold it), unless that would put it
// before `not_before`.
double off_road_start(const LineIndex& lines, std::size_t line, double end, double not_before) {
    constexpr double trigger_m = 6.0; // the trigger's 5 m and a margin
    for (double entry = lines.road_entry(line, end);
         end - entry < trigger_m && entry > lines.start(line) + 1.0 && entry - 0.5 >= not_before;
         entry = lines.road_entry(line, end)) {
        end = entry - 0.5; // and again where the road before is short too
    }
    return end;
}

// The ego's run around an anchor: from run_up_m before it to overrun_m past
// it (or to stop_before_m short of it), or why the track there cannot hold it.
std::optional<std::string> place_run(const odd::OddProfile& profile, const std::vector<std::size_t>& on_line,
                                     const LineIndex& lines, const Template& t, double ego_half_length_m, Anchor& a) {
    const auto place = lines.at(a.line, a.chainage);
    const double run_up = a.chainage - lines.start(a.line);
    auto metres = [](double m) { return std::to_string(static_cast<long>(std::ceil(m - 1e-9))); };
    if (!place) {
        return "no track geometry at chainage " + std::to_string(a.chainage);
    }
    if (run_up < t.ego.min_run_up_m) {
        return "only " + std::to_string(static_cast<long>(run_up)) + " m of track before the anchor, the template needs " +
               metres(t.ego.min_run_up_m) + " m";
    }
    if (const double need = hazard_run_up(t, ego_half_length_m); run_up < need) {
        return "only " + std::to_string(static_cast<long>(run_up)) +
               " m of track before the anchor, the hazard's timing (hazard_before_m) needs " + metres(need) + " m";
    }
    a.place = *place;
    a.start_chainage = std::max(lines.start(a.line), a.chainage - t.ego.run_up_m);
    a.speed_limit_kmh = limit_at(profile, on_line, a.chainage);
    if (t.ego.stop_before_m) {
        // The train's front stops short of the anchor: its reference point
        // (the middle) half a train further back.
        a.end_chainage = off_road_start(lines, a.line, a.chainage - *t.ego.stop_before_m - ego_half_length_m,
                                        a.start_chainage);
        if (a.end_chainage - a.start_chainage < t.ego.min_run_up_m) {
            return "only " + std::to_string(static_cast<long>(run_up)) +
                   " m of track before the anchor, too little for the train to stop " + metres(*t.ego.stop_before_m) +
                   " m short of it after a run of " + metres(t.ego.min_run_up_m) + " m";
        }
        return std::nullopt;
    }
    // The train must pass the anchor (and every actor placed after it) before
    // its run ends: the stop trigger fires a few metres short of the end.
    double past = min_overrun_m;
    for (const auto& actor : t.actors) {
        past = std::max(past, actor.along_m + min_overrun_m);
    }
    if (lines.end(a.line) - a.chainage < past) {
        return "only " + std::to_string(static_cast<long>(lines.end(a.line) - a.chainage)) +
               " m of track after the anchor, the train needs " + metres(past) + " m to run past it";
    }
    a.end_chainage = off_road_start(lines, a.line, std::min(lines.end(a.line), a.chainage + t.ego.overrun_m),
                                    a.chainage + past);
    return std::nullopt;
}

// A road user approaching a crossing starts on the crossing road's own lane;
// where that road is not in the map (a footway outside the road corridor, a
// crossing inside a road junction) it would stand beside the railway instead,
// which is not the scenario: the place is skipped.
std::optional<std::string> road_user_place(const odd::TaggedElement& e, const Template& t) {
    for (const auto& actor : t.actors) {
        const bool approaches = actor.place == Lateral::crossing_approach ||
                                (actor.move_to && *actor.move_to == Lateral::crossing_approach);
        if (!approaches) {
            continue;
        }
        if (!e.find("crossing_road_id")) {
            return "the crossing's road is not in the map: " + actor.name + " has no road to approach on";
        }
        // A vehicle needs a driving lane; a person walks on a sidewalk or, without one, a driving lane.
        const bool vehicle = under(actor.asset_class, "Dynamic Elements/Road vehicle");
        bool lane = false;
        for (const char* k : {"crossing_road_forward_lane", "crossing_road_backward_lane", "crossing_road_forward_walk",
                              "crossing_road_backward_walk"}) {
            const auto* v = e.find(k);
            const bool walk = std::string_view(k).ends_with("walk");
            lane = lane || (v && std::holds_alternative<double>(*v) && std::get<double>(*v) != 0.0 && !(vehicle && walk));
        }
        if (!lane) {
            return "the crossing's road has no lane " + actor.name + " can approach on";
        }
    }
    return std::nullopt;
}

// An actor on the switch's other track needs that track, long enough.
std::optional<std::string> branch_actors(const LineIndex& lines, const Template& t, std::size_t element) {
    for (const auto& actor : t.actors) {
        if (actor.place == Lateral::branch_track && !lines.branch_place(element, std::abs(actor.along_m))) {
            return "no other track at the switch " + std::to_string(static_cast<long>(std::abs(actor.along_m))) +
                   " m long for " + actor.name;
        }
    }
    return std::nullopt;
}

// A run onto a switch's diverging track takes the switch's diverging line.
std::optional<std::string> diverging_run(const LineIndex& lines, const Template& t, std::size_t element, Anchor& a) {
    if (!t.anchor.diverging) {
        return std::nullopt;
    }
    const auto line = lines.diverging(element);
    if (!line) {
        return "no diverging track at the switch (a route profile follows its route, or the profile names no "
               "other track at the switch's node)";
    }
    a.line = *line;
    return std::nullopt;
}

} // namespace

bool matches(const odd::TaggedElement& e, const ElementMatch& match) {
    if (!under(e.element, match.element)) {
        return false;
    }
    for (const auto& c : match.where) {
        const auto* v = e.find(c.attribute);
        if (!v || !holds(*v, c)) {
            return false;
        }
    }
    return true;
}

Anchoring find_anchors(const odd::OddProfile& profile, const LineIndex& lines, const Template& t,
                       double ego_half_length_m) {
    Anchoring out;
    LineElements by_line;
    for (std::size_t i = 0; i < profile.elements.size(); ++i) {
        by_line[lines.line_of(profile.elements[i])].push_back(i);
    }
    for (std::size_t i = 0; i < profile.elements.size(); ++i) {
        const auto& e = profile.elements[i];
        if (!matches(e, t.anchor)) {
            continue;
        }
        const auto& on_line = by_line[lines.line_of(e)];
        Anchor a;
        a.element = i;
        a.line = lines.line_of(e);
        a.chainage = anchor_point(e, t.anchor.at);
        bool complete = true;
        for (const auto& c : t.context) {
            const auto found = context_before(profile, on_line, a.chainage, c);
            complete = complete && found.has_value();
            a.context.push_back(found.value_or(0));
        }
        if (!complete) {
            continue; // not a place for this template; only places that match are reported
        }
        if (auto why = road_user_place(e, t)) {
            out.skipped.push_back({i, std::move(*why)});
        } else if (auto no = diverging_run(lines, t, i, a)) {
            out.skipped.push_back({i, std::move(*no)});
        } else if (auto no = branch_actors(lines, t, i)) {
            out.skipped.push_back({i, std::move(*no)});
        } else if (auto why = place_run(profile, on_line, lines, t, ego_half_length_m, a)) {
            out.skipped.push_back({i, std::move(*why)});
        } else {
            out.anchors.push_back(std::move(a));
        }
    }
    std::stable_sort(out.anchors.begin(), out.anchors.end(), [](const Anchor& x, const Anchor& y) {
        return x.line != y.line ? x.line < y.line : x.chainage < y.chainage;
    });
    return out;
}

} // namespace railodd::scenario
