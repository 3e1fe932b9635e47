// ID.behavior.yaml, format railodd-behavior 1 (docs/scenarios.md "Behaviour
// files"): what a custom controller needs for the motions OpenSCENARIO players
// handle poorly (pedestrians stepping onto the track, a car stopping on a
// crossing) and the railway context of the anchor. It complements the .xosc:
// entity names and positions are the same, nothing is duplicated in meaning.
#include "railodd/scenario/outputs.hpp"

#include <yaml-cpp/yaml.h>

#include <cstdio>

namespace railodd::scenario {

namespace {

// Numbers as fixed text so that the file is byte-identical across runs.
std::string num(double v) {
    char buf[40];
    std::snprintf(buf, sizeof buf, "%.3f", v);
    std::string s = buf;
    s.erase(s.find_last_not_of('0') + 1);
    if (s.back() == '.') {
        s.pop_back();
    }
    return s == "-0" ? "0" : s;
}

void place(YAML::Emitter& y, const LanePlacement& p) {
    y << YAML::Flow << YAML::BeginMap << YAML::Key << "road_id" << YAML::Value << YAML::DoubleQuoted << p.road_id
      << YAML::Key << "lane_id" << YAML::Value << p.lane_id << YAML::Key << "s" << YAML::Value << num(p.s)
      << YAML::Key << "offset" << YAML::Value << num(p.offset) << YAML::EndMap;
}

void properties(YAML::Emitter& y, const Actor& a) {
    y << YAML::Key << "attributes" << YAML::Value << YAML::BeginMap;
    for (const auto& [k, v] : a.properties) {
        y << YAML::Key << k << YAML::Value << v;
    }
    y << YAML::EndMap;
}

void actor(YAML::Emitter& y, const Actor& a, double trigger) {
    static const char* kinds[] = {"vehicle", "pedestrian", "misc_object"};
    y << YAML::BeginMap << YAML::Key << "entity" << YAML::Value << a.name << YAML::Key << "asset" << YAML::Value
      << a.asset_id << YAML::Key << "kind" << YAML::Value << kinds[static_cast<int>(a.kind)];
    properties(y, a);
    y << YAML::Key << "start" << YAML::Value;
    place(y, a.start);
    if (a.target) {
        y << YAML::Key << "motion" << YAML::Value << YAML::BeginMap;
        y << YAML::Key << "trigger" << YAML::Value << YAML::Flow << YAML::BeginMap << YAML::Key << "entity"
          << YAML::Value << "Ego" << YAML::Key << "traveled_distance_m" << YAML::Value << num(trigger) << YAML::EndMap;
        y << YAML::Key << "to" << YAML::Value;
        place(y, *a.target);
        y << YAML::Key << "speed_mps" << YAML::Value << num(a.target_speed_mps) << YAML::EndMap;
    } else {
        y << YAML::Key << "motion" << YAML::Value << YAML::Null;
    }
    y << YAML::EndMap;
}

} // namespace

std::string behavior_yaml(const ScenarioRecord& rec, const odd::OddProfile& profile) {
    const ConcreteScenario& sc = rec.scenario;
    YAML::Emitter y;
    y << YAML::BeginMap;
    y << YAML::Key << "format" << YAML::Value << "railodd-behavior" << YAML::Key << "format_version" << YAML::Value << 1;
    y << YAML::Key << "scenario" << YAML::Value << sc.id << YAML::Key << "scenario_file" << YAML::Value
      << sc.id + ".xosc" << YAML::Key << "map" << YAML::Value << sc.map_file;
    y << YAML::Key << "ego" << YAML::Value << YAML::BeginMap << YAML::Key << "entity" << YAML::Value << "Ego"
      << YAML::Key << "asset" << YAML::Value << sc.ego.asset_id << YAML::Key << "speed_mps" << YAML::Value
      << num(sc.ego.speed_mps) << YAML::Key << "max_deceleration_mps2" << YAML::Value << num(sc.ego.max_deceleration);
    properties(y, sc.ego);
    y << YAML::Key << "route" << YAML::Value << YAML::BeginSeq;
    for (const auto& w : sc.ego.route) {
        place(y, w);
    }
    y << YAML::EndSeq << YAML::EndMap;
    y << YAML::Key << "actors" << YAML::Value << YAML::BeginSeq;
    for (const auto& a : sc.others) {
        actor(y, a, sc.trigger_distance_m);
    }
    y << YAML::EndSeq;
    if (!sc.conditions.empty()) {
        y << YAML::Key << "conditions" << YAML::Value << YAML::BeginMap;
        for (const auto& [k, v] : sc.conditions) {
            y << YAML::Key << k << YAML::Value << v;
        }
        y << YAML::EndMap;
    }
    const auto& e = profile.elements[rec.anchor.element];
    y << YAML::Key << "railway" << YAML::Value << YAML::BeginMap << YAML::Key << "anchor" << YAML::Value
      << YAML::BeginMap << YAML::Key << "element" << YAML::Value << e.element << YAML::Key << "at" << YAML::Value;
    place(y, rec.anchor.place);
    y << YAML::Key << "osm_ids" << YAML::Value << YAML::Flow << e.osm_ids << YAML::Key << "attributes" << YAML::Value
      << YAML::BeginMap;
    for (const auto& a : e.attributes) {
        std::string v;
        if (const double* x = std::get_if<double>(&a.value)) {
            v = num(*x);
        } else if (const bool* b = std::get_if<bool>(&a.value)) {
            v = *b ? "true" : "false";
        } else {
            v = std::get<std::string>(a.value);
        }
        y << YAML::Key << a.name << YAML::Value << v;
    }
    y << YAML::EndMap << YAML::EndMap << YAML::EndMap << YAML::EndMap;
    return std::string("# railodd behaviour file (docs/scenarios.md, \"Behaviour files\")\n") + y.c_str() + "\n";
}

} // namespace railodd::scenario
