#include "railodd/geometry/topology_report.hpp"

#include <map>

namespace railodd::geometry {

using nlohmann::ordered_json;

namespace {

ordered_json road_rail_json(const std::vector<RoadRailCrossing>& crossings) {
    std::size_t separated = 0, with_node = 0, shared = 0;
    ordered_json unmarked = ordered_json::array();
    for (const auto& c : crossings) {
        if (c.grade_separated) {
            ++separated;
            continue;
        }
        shared += c.shared_node != 0 ? 1 : 0;
        if (c.level_crossing_node != 0) {
            ++with_node;
        } else {
            // An at-grade crossing nobody tagged: worth a mapper's look.
            unmarked.push_back({{"road_way", c.road_way_id}, {"track_edge", c.edge}, {"shared_node", c.shared_node}});
        }
    }
    return {{"total", crossings.size()},
            {"grade_separated", separated},
            {"at_grade", crossings.size() - separated},
            {"at_grade_sharing_a_node", shared},
            {"at_grade_with_level_crossing_node", with_node},
            {"at_grade_without_level_crossing_node", unmarked}};
}

ordered_json track_json(const std::vector<TrackCrossing>& crossings) {
    std::size_t separated = 0, diamonds = 0;
    for (const auto& c : crossings) {
        separated += c.grade_separated ? 1 : 0;
        diamonds += (!c.grade_separated && c.shared_node != 0) ? 1 : 0;
    }
    return {{"total", crossings.size()}, {"grade_separated", separated}, {"diamond_crossings", diamonds}};
}

} // namespace

ordered_json topology_report(const Crossings& crossings, const Attachment& attachment,
                             const std::vector<ingest::Feature>& features) {
    std::map<std::string, std::size_t> by_kind;
    for (const auto& a : attachment.attached) {
        ++by_kind[features[a.feature].kind];
    }
    ordered_json attached = ordered_json::object();
    for (const auto& [k, n] : by_kind) {
        attached[k] = n;
    }
    ordered_json unattached = ordered_json::array();
    for (const auto& u : attachment.unattached) {
        const auto& f = features[u.feature];
        unattached.push_back({{"kind", f.kind}, {"osm_type", f.osm_type}, {"osm_id", f.id}, {"reason", u.reason}});
    }
    return {{"road_rail_crossings", road_rail_json(crossings.road_rail)},
            {"track_crossings", track_json(crossings.tracks)},
            {"features_attached", attached},
            {"features_unattached", unattached}};
}

} // namespace railodd::geometry
