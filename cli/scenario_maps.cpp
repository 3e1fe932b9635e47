#include "scenario_maps.hpp"

#include "railodd/xodr_check/map_crop.hpp"
#include "railodd/xodr_check/map_lines.hpp"

#include <map>
#include <set>
#include <string>
#include <vector>

namespace railodd::cli {

namespace {

// Every road a scenario's actors stand on or move over.
std::set<std::string> scenario_roads(const scenario::ConcreteScenario& sc) {
    std::set<std::string> roads;
    const auto add = [&](const scenario::Actor& a) {
        roads.insert(a.start.road_id);
        for (const auto& p : a.route) {
            roads.insert(p.road_id);
        }
        for (const auto& p : a.path) {
            roads.insert(p.road_id);
        }
        if (a.target) {
            roads.insert(a.target->road_id);
        }
    };
    add(sc.ego);
    for (const auto& a : sc.others) {
        add(a);
    }
    if (sc.ego_end) {
        roads.insert(sc.ego_end->road_id);
    }
    roads.erase("");
    return roads;
}

} // namespace

std::vector<scenario::ConnectingRoad> connecting_roads(const std::filesystem::path& map) {
    std::vector<scenario::ConnectingRoad> out;
    for (const auto& r : xodr_check::read_map_lines(map).roads) {
        if (r.junction != "-1" && !r.predecessor.empty() && !r.successor.empty()) {
            out.push_back({r.id, r.junction, r.predecessor, r.successor, r.length});
        }
    }
    return out;
}

double corridor_for(double requested, const std::filesystem::path& map) {
    if (requested >= 0.0) {
        return requested;
    }
    std::error_code ec;
    const std::uintmax_t size = std::filesystem::file_size(map, ec);
    return !ec && size > corridor_default_above_bytes ? corridor_default_m : 0.0;
}

void cut_scenario_maps(OutputStage& stage, const std::filesystem::path& map, double corridor_m,
                       scenario::Generation& generation) {
    const xodr_check::MapCrop crop(map);
    std::map<std::set<std::string>, std::string> cut;
    for (auto& rec : generation.scenarios) {
        const std::set<std::string> roads = scenario_roads(rec.scenario);
        auto it = cut.find(roads);
        if (it == cut.end()) {
            xodr_check::CropSpec spec;
            spec.roads.assign(roads.begin(), roads.end());
            spec.corridor_m = corridor_m;
            const std::string name = "maps/corridor_" + std::to_string(cut.size() + 1) + ".xodr";
            stage.write_text(name, crop.cut(spec).xml);
            it = cut.emplace(roads, name).first;
        }
        rec.scenario.map_file = it->second;
    }
}

} // namespace railodd::cli
