// One concrete scenario: the ego starts on the rail lane before the anchor and
// runs through it along the track; the other actors stand where the template
// puts them relative to the anchor and move when the ego comes near.
#include "instantiate.hpp"

#include "attribute_values.hpp"
#include "environment.hpp"
#include "junction_route.hpp"
#include "target_support.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <optional>

namespace railodd::scenario {

namespace {

constexpr double platform_edge_m = 2.0;  // from the track centre: the edge is ~1.7 m (EBO), people stand just behind it
constexpr double beside_track_m = 3.5;   // beyond the clearance gauge
constexpr double crossing_approach_m = 10.0; // on the road, short of the barriers
constexpr double adjacent_track_m = 4.0;     // track centres of a double line (EBO: 4.0 m)
constexpr double fallback_speed_kmh = 80.0; // where no speed limit is mapped
constexpr double across_step_m = 1.0;       // along the track while stepping across it

const ParameterDomain* varied_param(const TemplateContext& ctx, const Row& row, std::size_t dim, std::size_t& value) {
    if (dim + 1 >= row.size() || row[dim + 1] == kUnset) {
        return nullptr;
    }
    value = row[dim + 1];
    return &ctx.tmpl.parameters[ctx.varied[dim]];
}

// The side a platform is on, from the anchor or a context element.
double side_sign(const TemplateContext& ctx, const Anchor& a) {
    std::vector<std::size_t> elements{a.element};
    elements.insert(elements.end(), a.context.begin(), a.context.end());
    for (const auto i : elements) {
        if (const auto* v = ctx.profile.elements[i].find("side"); v && std::holds_alternative<std::string>(*v)) {
            return std::get<std::string>(*v) == "left" ? 1.0 : -1.0;
        }
    }
    return -1.0;
}

double lateral_offset(Lateral l, double side) {
    switch (l) {
    case Lateral::on_track: return 0.0;
    case Lateral::platform_edge: return side * platform_edge_m;
    case Lateral::beside_track: return side * beside_track_m;
    case Lateral::crossing_approach: return side * crossing_approach_m;
    case Lateral::adjacent_track: return side * adjacent_track_m;
    case Lateral::branch_track: return 0.0;
    }
    return 0.0;
}

std::string value_text(const odd::AttributeValue& v) {
    if (const double* x = std::get_if<double>(&v)) {
        return format_number(std::round(*x * 10.0) / 10.0);
    }
    if (const bool* b = std::get_if<bool>(&v)) {
        return *b ? "true" : "false";
    }
    return std::get<std::string>(v);
}

// Every taxonomy attribute of a profile element as a covered value.
void cover_element(const TemplateContext& ctx, const odd::TaggedElement& e, std::vector<CoveredValue>& out) {
    out.push_back({e.element, "", "", "", "map"});
    const odd::Element* el = ctx.taxonomy.find(e.element);
    for (const auto& attr : e.attributes) {
        const odd::Attribute* a = el ? ctx.taxonomy.attribute(*el, attr.name) : nullptr;
        if (a) {
            const auto text = std::holds_alternative<double>(attr.value) ? format_number(std::get<double>(attr.value))
                                                                         : value_text(attr.value);
            out.push_back({e.element, attr.name, text, value_class(*a, text), "map"});
        }
    }
}

void cover_asset(const TemplateContext& ctx, const Asset& asset, std::vector<CoveredValue>& out) {
    out.push_back({asset.element, "", asset.id, "", "asset"});
    const odd::Element* el = ctx.taxonomy.find(asset.element);
    for (const auto& [name, value] : asset.attributes) {
        const odd::Attribute* a = ctx.taxonomy.attribute(*el, name);
        out.push_back({asset.element, name, value, a ? value_class(*a, value) : value, "asset"});
    }
}

// The map's part of a scenario: the anchor, its context, every stretch of
// track the anchor point lies on (speed limit, gradient, track count, ...)
// and, for a stretch anchor, the points within it (a platform's station, a
// bridge's signal).
std::vector<CoveredValue> cover_map(const TemplateContext& ctx, const Anchor& a,
                                    const std::vector<std::size_t>& on_line) {
    std::vector<CoveredValue> out;
    const auto& anchor = ctx.profile.elements[a.element];
    cover_element(ctx, anchor, out);
    for (const auto i : a.context) {
        cover_element(ctx, ctx.profile.elements[i], out);
    }
    for (const std::size_t i : on_line) {
        const auto& e = ctx.profile.elements[i];
        if (i == a.element || std::find(a.context.begin(), a.context.end(), i) != a.context.end()) {
            continue;
        }
        const bool on_it = !e.point && e.chainage_start <= a.chainage && e.chainage_end >= a.chainage;
        const bool inside = e.point && !anchor.point && e.chainage_start >= anchor.chainage_start &&
                            e.chainage_start <= anchor.chainage_end;
        if (on_it || inside) {
            cover_element(ctx, e, out);
        }
    }
    return out;
}

double number_attribute(const TemplateContext& ctx, const Anchor& a, const char* name) {
    const auto* v = ctx.profile.elements[a.element].find(name);
    return v && std::holds_alternative<double>(*v) ? std::get<double>(*v) : 0.0;
}

// A road user at a level crossing starts on the crossing road's own lane,
// crossing_approach_m before the crossing point, and moves along that lane
// (sampled every 2 m, so the path follows the road) to the point where the
// road meets the track. A pedestrian takes the road's sidewalk where it has
// one. The lane travelling in +s is taken where there is room before the
// crossing, else the one travelling in -s; where neither has the room (a
// road cut back short for a junction), the one with more, from a centimetre
// inside the road's end. Nothing where the profile names no crossing road
// (a crossing inside a road junction).
std::optional<std::vector<LanePlacement>> crossing_road_path(const TemplateContext& ctx, const Anchor& a,
                                                             bool pedestrian) {
    const auto* id = ctx.profile.elements[a.element].find("crossing_road_id");
    if (!id || !std::holds_alternative<std::string>(*id)) {
        return std::nullopt;
    }
    const double s_cross = number_attribute(ctx, a, "crossing_road_s");
    const double length = number_attribute(ctx, a, "crossing_road_length");
    const int fwd = static_cast<int>(number_attribute(ctx, a, pedestrian ? "crossing_road_forward_walk" : "crossing_road_forward_lane"));
    const int bwd = static_cast<int>(number_attribute(ctx, a, pedestrian ? "crossing_road_backward_walk" : "crossing_road_backward_lane"));
    if (pedestrian && fwd == 0 && bwd == 0) {
        return crossing_road_path(ctx, a, false);
    }
    constexpr double inside = 0.01;
    const double room_fwd = fwd != 0 ? s_cross - inside : -1.0;
    const double room_bwd = bwd != 0 && length > 0.0 ? length - inside - s_cross : -1.0;
    const bool forward = room_fwd >= crossing_approach_m || (room_bwd < crossing_approach_m && room_fwd >= room_bwd);
    const double room = std::min(crossing_approach_m, forward ? room_fwd : room_bwd);
    if (room < 1.0) {
        return std::nullopt;
    }
    const double s0 = forward ? s_cross - room : s_cross + room;
    std::vector<LanePlacement> path;
    const int steps = std::max(1, static_cast<int>(std::ceil(room / 2.0)));
    for (int i = 0; i <= steps; ++i) {
        LanePlacement p;
        p.road_id = std::get<std::string>(*id);
        p.lane_id = forward ? fwd : bwd;
        p.s = s0 + (s_cross - s0) * i / steps;
        p.reversed = !forward;
        path.push_back(p);
    }
    return path;
}

// Where an off-road actor (a person, an animal) stepping across the track
// ends: a metre on in the ego's direction of travel (a player may measure a
// polyline's progress along s: esmini 3.6 ends a path with no progress in s
// at once, unmoved), or a metre back where the road ends within it (Munich:
// a 13.3 m road; esmini truncates an s beyond a road's end and says so).
LanePlacement across_target(const TemplateContext& ctx, const Anchor& a, double chainage, const LanePlacement& on_track) {
    for (const double step : {across_step_m, -across_step_m}) {
        const auto p = ctx.lines.at(a.line, chainage + step);
        if (p && p->road_id == on_track.road_id && p->lane_id == on_track.lane_id) {
            return *p;
        }
    }
    LanePlacement target = on_track;
    target.s += on_track.reversed ? -across_step_m : across_step_m;
    return target;
}

Actor place_actor(const TemplateContext& ctx, const ActorTemplate& t, const Asset& asset, const Anchor& a, double side) {
    Actor actor = actor_from(asset, t.name, entry_name(asset, ctx.options.target));
    actor.place = to_string(t.place);
    const double chainage = std::clamp(a.chainage + t.along_m, a.start_chainage, a.end_chainage);
    const auto at = ctx.lines.at(a.line, chainage);
    actor.start = at.value_or(a.place);
    actor.start.offset = lateral_offset(t.place, side);
    const LanePlacement on_track = actor.start;
    const auto road = t.place == Lateral::crossing_approach
                          ? crossing_road_path(ctx, a, actor.kind == Actor::Kind::pedestrian)
                          : std::nullopt;
    if (road) {
        actor.start = road->front();
    }
    if (t.place == Lateral::branch_track) { // find_anchors skipped switches without the branch
        actor.start = ctx.lines.branch_place(a.element, std::abs(t.along_m)).value_or(actor.start);
    }
    if (t.move_to) {
        actor.move_to = to_string(*t.move_to);
        if (road && *t.move_to == Lateral::on_track) {
            actor.path = *road;
        } else {
            // Across the track: off-road actors (people, animals) step onto
            // or off it.
            LanePlacement target = across_target(ctx, a, chainage, on_track);
            target.offset = lateral_offset(*t.move_to, side);
            actor.path = {actor.start, target};
        }
        actor.target = actor.path.back();
        actor.target_speed_mps = t.move_speed_kmh / 3.6;
        actor.hazard_before_m = t.hazard_before_m;
    }
    if (!t.behaviour.empty()) {
        actor.properties.emplace_back("behaviour", t.behaviour);
    }
    return actor;
}

double path_length(const std::vector<LanePlacement>& path) {
    double len = 0.0;
    for (std::size_t i = 1; i < path.size(); ++i) {
        len += std::hypot(path[i].s - path[i - 1].s, path[i].offset - path[i - 1].offset);
    }
    return len;
}

// When an actor's move starts: the ego's travelled distance, and how long
// the ego must first stand. With hazard_before_m the move is timed from the
// ego's speed and the actor's path so that the actor reaches its target when
// the ego's front is that far short of the conflict point (the anchor, moved
// along_m); where the run-up is too short for that, the move starts at once
// and the ego sets off late by the time it lacks.
struct MoveStart {
    double ego_distance_m = 0.0;
    double ego_delay_s = 0.0;
};

MoveStart move_start(const ActorTemplate& t, const Actor& actor, const Anchor& a, const Actor& ego) {
    if (!t.hazard_before_m) {
        return {std::max(0.0, a.chainage - a.start_chainage - t.trigger_before_m), 0.0};
    }
    const double run_up = a.chainage + t.along_m - a.start_chainage;
    const double move_s = path_length(actor.path) / std::max(actor.target_speed_mps, 0.1);
    const double at = run_up - *t.hazard_before_m - ego.dimensions.length / 2.0 - ego.speed_mps * move_s;
    if (at >= 0.0) {
        return {at, 0.0};
    }
    return {0.0, -at / std::max(ego.speed_mps, 0.1)};
}

// The ego's run sampled every 10 m of chainage and at its end. 10 m keeps a
// straight chord within 0.1 m of a 150 m curve and spans several of a
// player's steps even at 300 km/h; chainages outside the line are left out.
std::vector<TrackSample> track_samples(const LineIndex& lines, std::size_t line, double c0, double c1) {
    constexpr double step_m = 10.0;
    std::vector<TrackSample> out;
    const auto n = static_cast<std::size_t>(std::max(0.0, std::ceil((c1 - c0) / step_m)));
    for (std::size_t i = 0; i <= n; ++i) {
        const double c = std::min(c0 + static_cast<double>(i) * step_m, c1);
        if (auto p = lines.at(line, c)) {
            out.push_back({c - c0, *p});
        }
    }
    return out;
}

} // namespace

void prepare(TemplateContext& ctx) {
    ctx.ego_assets = ctx.catalog.under(ctx.tmpl.ego.asset_class);
    ctx.default_assets["Ego"] = ctx.ego_assets.front();
    for (const auto& a : ctx.tmpl.actors) {
        ctx.default_assets[a.name] = ctx.catalog.under(a.asset_class).front();
    }
    // The elements of each anchor element's own line (a diverging run's
    // line has none of its own).
    auto own_line = [&](const Anchor& a) { return ctx.lines.line_of(ctx.profile.elements[a.element]); };
    std::map<std::size_t, std::vector<std::size_t>> by_line;
    for (const auto& a : ctx.anchors) {
        by_line[own_line(a)];
    }
    for (std::size_t i = 0; i < ctx.profile.elements.size(); ++i) {
        if (const auto it = by_line.find(ctx.lines.line_of(ctx.profile.elements[i])); it != by_line.end()) {
            it->second.push_back(i);
        }
    }
    ctx.anchor_cover.clear();
    for (const auto& a : ctx.anchors) {
        ctx.anchor_cover.push_back(cover_map(ctx, a, by_line[own_line(a)]));
    }
}

const Asset& asset_for(const TemplateContext& ctx, const Row& row, const std::string& actor) {
    for (std::size_t d = 0; d < ctx.varied.size(); ++d) {
        std::size_t v = 0;
        const ParameterDomain* p = varied_param(ctx, row, d, v);
        if (p && p->kind == ParameterKind::actor_asset && p->actor == actor) {
            return *ctx.catalog.find(p->values[v]);
        }
    }
    return *ctx.default_assets.at(actor);
}

const Asset* ego_for(const TemplateContext& ctx, const Row& row, double kmh) {
    for (std::size_t d = 0; d < ctx.varied.size(); ++d) {
        std::size_t v = 0;
        const ParameterDomain* p = varied_param(ctx, row, d, v);
        if (p && p->kind == ParameterKind::actor_asset && p->actor == "Ego") {
            return ctx.catalog.find(p->values[v]);
        }
    }
    const Asset* fallback = ctx.default_assets.at("Ego");
    if (!std::isfinite(kmh) || kmh <= fallback->max_speed_mps * 3.6 + 1e-9) {
        return fallback;
    }
    for (const Asset* a : ctx.ego_assets) {
        if (kmh <= a->max_speed_mps * 3.6 + 1e-9) {
            return a;
        }
    }
    return nullptr;
}

EgoSpeed ego_speed_for(const TemplateContext& ctx, const Row& row) {
    const Anchor& a = ctx.anchors[row[0]];
    for (std::size_t d = 0; d < ctx.varied.size(); ++d) {
        std::size_t v = 0;
        const ParameterDomain* p = varied_param(ctx, row, d, v);
        if (!p || p->kind != ParameterKind::ego_speed) {
            continue;
        }
        if (p->limit_fractions.empty()) {
            return {*parse_number(p->values[v]), "parameter"};
        }
        if (std::isfinite(a.speed_limit_kmh)) {
            return {p->limit_fractions[v] * a.speed_limit_kmh, "speed limit"};
        }
        // No limit mapped here: a fraction of a moderate line speed, capped by
        // the train, rather than of the train's top speed (trams, sidings).
        return {p->limit_fractions[v] * std::min(fallback_speed_kmh, asset_for(ctx, row, "Ego").max_speed_mps * 3.6),
                "default line speed"};
    }
    if (std::isfinite(a.speed_limit_kmh)) { // no speed parameter: run at the line speed
        return {a.speed_limit_kmh, "speed limit"};
    }
    return {fallback_speed_kmh, "default"};
}

ScenarioRecord instantiate(const TemplateContext& ctx, const Row& row, const std::string& id) {
    ScenarioRecord rec;
    rec.template_id = ctx.tmpl.id;
    rec.anchor = ctx.anchors[row[0]];
    const Anchor& a = rec.anchor;
    ConcreteScenario& sc = rec.scenario;
    sc.id = id;
    sc.date = ctx.options.date;
    sc.map_file = ctx.options.map_file;
    sc.catalog_dir = ctx.options.catalog_dir;

    const EgoSpeed speed = ego_speed_for(ctx, row);
    rec.speed_basis = speed.basis;
    const Asset* fast_enough = ego_for(ctx, row, speed.kmh);
    const Asset& ego_asset = fast_enough ? *fast_enough : asset_for(ctx, row, "Ego");
    sc.ego = actor_from(ego_asset, "Ego", entry_name(ego_asset, ctx.options.target));
    sc.ego.start = ctx.lines.at(a.line, a.start_chainage).value_or(a.place);
    sc.ego.route = ctx.lines.waypoints(a.line, a.start_chainage, a.end_chainage);
    take_connecting_roads(sc.ego.route, ctx.options.connecting_roads);
    if (!target_support::usable(ctx.options.target, "AssignRouteAction", target_support::Where::init) &&
        !target_support::usable(ctx.options.target, "AssignRouteAction", target_support::Where::story)) {
        sc.ego_track = track_samples(ctx.lines, a.line, a.start_chainage, a.end_chainage);
    }
    sc.ego.speed_mps = speed.kmh / 3.6;
    sc.ego_end = ctx.lines.at(a.line, a.end_chainage);
    sc.ego_run_m = a.end_chainage - a.start_chainage;
    sc.stop_time_s = std::ceil((a.end_chainage - a.start_chainage) / std::max(sc.ego.speed_mps, 1.0)) + 30.0;
    rec.assets.emplace_back("Ego", ego_asset.id);
    cover_asset(ctx, ego_asset, rec.odd_elements);
    rec.odd_elements.push_back({"Dynamic Elements/Rail vehicle/Ego train", "speed", format_number(speed.kmh),
                                value_class(*ctx.taxonomy.attribute(*ctx.taxonomy.find("Dynamic Elements/Rail vehicle/Ego train"), "speed"),
                                            format_number(speed.kmh)),
                                "parameter"});

    const double side = side_sign(ctx, a);
    double trigger = std::numeric_limits<double>::infinity();
    for (const auto& t : ctx.tmpl.actors) {
        const Asset& asset = asset_for(ctx, row, t.name);
        sc.others.push_back(place_actor(ctx, t, asset, a, side));
        rec.assets.emplace_back(t.name, asset.id);
        cover_asset(ctx, asset, rec.odd_elements);
        if (t.move_to) {
            const MoveStart m = move_start(t, sc.others.back(), a, sc.ego);
            trigger = std::min(trigger, m.ego_distance_m);
            sc.ego_start_delay_s = std::max(sc.ego_start_delay_s, m.ego_delay_s);
        }
    }
    sc.trigger_distance_m = std::isfinite(trigger) ? trigger : 0.0;
    sc.stop_time_s += std::ceil(sc.ego_start_delay_s);
    const auto& map = ctx.anchor_cover[row[0]];
    rec.odd_elements.insert(rec.odd_elements.end(), map.begin(), map.end());
    fill_parameters(ctx, row, speed, rec);
    return rec;
}

} // namespace railodd::scenario
