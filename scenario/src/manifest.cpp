// manifest.json: the traceability record of a scenario set. Every scenario
// names where it stands (road, s, chainage, OSM ids), what it was made of
// (template, parameter values, assets, perturbations) and which ODD elements
// it exercises, each with its source.
#include "railodd/scenario/outputs.hpp"

#include <cmath>

namespace railodd::scenario {

namespace {

using ojson = nlohmann::ordered_json;

ojson lane_json(const LanePlacement& p) {
    ojson j = {{"road_id", p.road_id}, {"lane_id", p.lane_id}, {"s", p.s}};
    if (p.offset != 0.0) {
        j["offset"] = p.offset;
    }
    if (p.reversed) {
        j["reversed"] = true;
    }
    return j;
}

ojson anchor_json(const ScenarioRecord& rec, const odd::OddProfile& profile) {
    const Anchor& a = rec.anchor;
    const auto& e = profile.elements[a.element];
    ojson context = ojson::array();
    for (const auto i : a.context) {
        const auto& c = profile.elements[i];
        context.push_back({{"element", c.element}, {"road_id", c.road_id}, {"s_start", c.s_start}, {"s_end", c.s_end},
                           {"chainage_start", c.chainage_start}, {"chainage_end", c.chainage_end},
                           {"osm_ids", c.osm_ids}});
    }
    ojson j = {{"element", e.element}, {"road_id", a.place.road_id}, {"lane_id", a.place.lane_id}, {"s", a.place.s},
               {"track", e.track}, {"chainage", a.chainage}, {"osm_ids", e.osm_ids}};
    j["speed_limit_kmh"] = std::isfinite(a.speed_limit_kmh) ? ojson(a.speed_limit_kmh) : ojson(nullptr);
    j["context"] = std::move(context);
    return j;
}

const char* kind_name(Actor::Kind k) {
    switch (k) {
    case Actor::Kind::vehicle: return "vehicle";
    case Actor::Kind::pedestrian: return "pedestrian";
    case Actor::Kind::misc_object: return "misc_object";
    }
    return "vehicle";
}

// Where each actor starts and goes, as the template put it: what `railodd
// play` checks the recorded trajectories against.
ojson actors_json(const ConcreteScenario& sc) {
    ojson out = ojson::array();
    for (const Actor& a : sc.others) {
        ojson j = {{"name", a.name}, {"asset", a.asset_id}, {"kind", kind_name(a.kind)}, {"place", a.place},
                   {"start", lane_json(a.start)}};
        if (a.target) {
            j["move_to"] = a.move_to;
            j["target"] = lane_json(*a.target);
            j["speed_mps"] = a.target_speed_mps;
            if (a.hazard_before_m) {
                j["hazard_before_m"] = *a.hazard_before_m;
            }
        }
        j["length_m"] = a.dimensions.length;
        j["width_m"] = a.dimensions.width;
        out.push_back(std::move(j));
    }
    return out;
}

ojson route_roads(const Actor& ego) {
    ojson roads = ojson::array();
    auto add = [&](const std::string& id) {
        if (roads.empty() || roads.back() != id) {
            roads.push_back(id);
        }
    };
    add(ego.start.road_id);
    for (const auto& w : ego.route) {
        add(w.road_id);
    }
    return roads;
}

ojson scenario_json(const ScenarioRecord& rec, const odd::OddProfile& profile) {
    const ConcreteScenario& sc = rec.scenario;
    ojson params = ojson::object();
    for (std::size_t i = 0; i < rec.values.size(); ++i) {
        params[rec.values[i].first] = {{"value", rec.raw[i].second}, {"text", rec.values[i].second}};
    }
    ojson assets = ojson::object();
    for (const auto& [actor, id] : rec.assets) {
        assets[actor] = id;
    }
    ojson perturbations = ojson::array();
    ojson covered = ojson::array();
    for (const auto& v : rec.odd_elements) {
        if (v.source == "perturbation" && !v.attribute.empty()) {
            perturbations.push_back({{"element", v.element}, {"attribute", v.attribute}, {"value", v.value},
                                     {"class", v.value_class}});
        }
        covered.push_back({{"element", v.element}, {"attribute", v.attribute}, {"value", v.value},
                           {"class", v.value_class}, {"source", v.source}});
    }
    ojson osc_params = ojson::object();
    for (const auto& p : sc.parameters) {
        osc_params[p.name] = p.value;
    }
    const Anchor& a = rec.anchor;
    return {{"id", sc.id},
            {"file", sc.id + ".xosc"},
            {"behavior", sc.id + ".behavior.yaml"},
            {"template", rec.template_id},
            {"text", sc.description},
            {"parameters", std::move(params)},
            {"osc_parameters", std::move(osc_params)},
            {"anchor", anchor_json(rec, profile)},
            {"ego", {{"asset", sc.ego.asset_id}, {"start", lane_json(sc.ego.start)},
                     {"run_up_m", a.chainage - a.start_chainage}, {"overrun_m", a.end_chainage - a.chainage},
                     {"speed_kmh", sc.ego.speed_mps * 3.6}, {"speed_basis", rec.speed_basis},
                     {"trigger_distance_m", sc.trigger_distance_m}, {"start_delay_s", sc.ego_start_delay_s},
                     {"route_roads", route_roads(sc.ego)},
                     {"length_m", sc.ego.dimensions.length}, {"width_m", sc.ego.dimensions.width},
                     {"max_deceleration", sc.ego.max_deceleration},
                     {"end", sc.ego_end ? lane_json(*sc.ego_end) : ojson(nullptr)},
                     {"stops_short_of_anchor", a.end_chainage < a.chainage}}},
            {"actors", actors_json(sc)},
            {"assets", std::move(assets)},
            {"perturbations", std::move(perturbations)},
            {"odd_elements", std::move(covered)},
            {"map", sc.map_file}};
}

ojson degraded_json(const std::vector<Degradation>& list) {
    ojson out = ojson::array();
    for (const auto& d : list) {
        out.push_back({{"name", d.name}, {"value", d.value}, {"reason", d.reason}});
    }
    return out;
}

} // namespace

ojson manifest_json(const Generation& g, const odd::OddProfile& profile, const OutputInfo& info,
                    const Degradations& degraded) {
    ojson j;
    j["railodd"] = {{"format", "scenario_manifest"}, {"format_version", 1}};
    j["inputs"] = {{"map_dir", info.map_dir},     {"map", info.map_file},
                   {"taxonomy", info.taxonomy_file}, {"catalog", info.catalog_file},
                   {"templates", info.templates_file}, {"odd_spec", info.spec_file},
                   {"route", profile.route}};
    j["generation"] = {{"strategy", to_string(info.strategy)}, {"count", info.count}, {"seed", info.seed},
                       {"openscenario", "1." + std::to_string(info.osc_minor)}, {"target", to_string(info.target)}};
    ojson templates = ojson::array();
    for (const auto& r : g.runs) {
        templates.push_back({{"id", r.template_id}, {"anchors", r.anchors}, {"anchors_skipped", r.skipped.size()},
                             {"scenarios", r.rows},
                             {"distribution", has_distributions(info)
                                                  ? ojson("distributions/" + r.template_id + ".xosc")
                                                  : ojson(nullptr)}});
        if (r.every_valid_row) {
            // --count asked for more than exist: the reader sees why there are fewer.
            templates.back()["all_valid_rows"] = true;
        }
    }
    j["templates"] = std::move(templates);
    ojson scenarios = ojson::array();
    for (const auto& s : g.scenarios) {
        scenarios.push_back(scenario_json(s, profile));
        if (info.target != Target::esmini) {
            const auto it = degraded.find(s.scenario.id);
            scenarios.back()["degraded_for_target"] =
                degraded_json(it == degraded.end() ? std::vector<Degradation>{} : it->second);
        }
    }
    j["scenarios"] = std::move(scenarios);
    return j;
}

} // namespace railodd::scenario
