#include "play_targets.hpp"

#include "railodd/util/errors.hpp"

#include <algorithm>
#include <iostream>

namespace railodd::cli {

namespace fs = std::filesystem;

TargetPlaces::TargetPlaces(const nlohmann::ordered_json& manifest, const fs::path& dir) {
    for (const auto& sc : manifest["scenarios"]) {
        const std::string name = sc.value("map", "");
        const auto& actors = sc.contains("actors") ? sc["actors"] : nlohmann::ordered_json::array();
        const bool targets = std::any_of(actors.begin(), actors.end(), [](const auto& a) { return a.contains("target"); });
        if (name.empty() || maps_.count(name) || !targets) {
            continue;
        }
        Roads& roads = maps_[name];
        try {
            for (auto& r : xodr_check::read_map_lines(dir / name).roads) {
                roads.emplace(r.id, std::move(r));
            }
        } catch (const InputError& e) {
            // The player reads the map too and says why it cannot.
            std::cerr << "railodd play: targets not placed on the map: " << e.what() << "\n";
        }
    }
}

void TargetPlaces::place(nlohmann::json& scenario) const {
    const auto map = maps_.find(scenario.value("map", ""));
    if (map == maps_.end()) {
        return;
    }
    for (auto& actor : scenario["actors"]) {
        if (!actor.contains("target")) {
            continue;
        }
        auto& t = actor["target"];
        const auto road = map->second.find(t.value("road_id", ""));
        if (road == map->second.end() || !t.contains("lane_id")) {
            continue;
        }
        const auto p = road->second.lane_position(t["lane_id"].get<int>(), t.value("s", 0.0), t.value("offset", 0.0));
        if (p) {
            t["x"] = p->x;
            t["y"] = p->y;
        }
    }
}

} // namespace railodd::cli
