#include "railodd/xodr/map_builder.hpp"

#include "feature_context.hpp"

#include <algorithm>
#include <limits>
#include <map>
#include <string>

namespace railodd::xodr {

namespace {

// Extent of every mapped node of tracks and roads, plus a margin for the
// curves between them, in the local frame.
void set_bounds(Header& h, const MapInput& in) {
    double n = -std::numeric_limits<double>::infinity(), s = -n, e = n, w = -n;
    for (const auto* g : {&in.geometry.tracks, &in.geometry.roads}) {
        for (const auto& edge : g->edges) {
            for (const auto& node : edge.nodes) {
                n = std::max(n, node.xy.y);
                s = std::min(s, node.xy.y);
                e = std::max(e, node.xy.x);
                w = std::min(w, node.xy.x);
            }
        }
    }
    if (n < s) {
        n = s = e = w = 0.0;
    }
    constexpr double margin = 10.0;
    h.north = n + margin;
    h.south = s - margin;
    h.east = e + margin;
    h.west = w - margin;
}

// CARLA takes a link's element for a road whenever some road has its id (it
// never reads elementType), so junctions are numbered after the last road:
// one id space. Road ids, which the profile and scenarios cite, stay as
// they were handed out.
void number_junctions_after_roads(Map& map) {
    long last = 0;
    for (const Road& r : map.roads) {
        last = std::max(last, std::stol(r.id));
    }
    std::map<std::string, std::string> renamed;
    for (std::size_t i = 0; i < map.junctions.size(); ++i) {
        Junction& j = map.junctions[i];
        j.id = renamed[j.id] = std::to_string(last + 1 + static_cast<long>(i));
    }
    for (Road& r : map.roads) {
        if (r.junction != "-1") {
            r.junction = renamed.at(r.junction);
        }
        for (RoadLink* link : {&r.predecessor, &r.successor}) {
            if (link->type == ElementType::junction) {
                link->id = renamed.at(link->id);
            }
        }
    }
}

} // namespace

MapBuild build_map(const MapInput& in, const MapOptions& options) {
    MapBuild b;
    IdCounter ids;
    // Header: name, date and the local frame as a PROJ string.
    b.map.header.name = options.name;
    b.map.header.date = options.date;
    b.map.header.geo_reference = in.ingest.projection.proj_string();
    set_bounds(b.map.header, in);
    // Tracks first (their ids are the smallest), then the corridor's roads.
    const geometry::FittedMap& g = in.geometry;
    b.rail = add_rail_network({g.tracks, g.fitted_tracks, g.profiles, g.cants, in.ingest.tracks, &g.indexed}, options.rail,
                              ids, b.map);
    b.roads = add_road_network(in.geometry.roads, in.geometry.fitted_roads, in.ingest.roads, options.roads, ids, b.map);
    // Railway features on the written roads.
    FeatureContext ctx{in, b, ids, options.revision};
    add_structures(ctx);
    add_track_features(ctx);
    add_stations(ctx);
    add_level_crossings(ctx);
    number_junctions_after_roads(b.map);
    return b;
}

nlohmann::ordered_json map_report(const MapBuild& b, const MapInput& in) {
    nlohmann::ordered_json r;
    std::size_t rail_roads = 0, rail_connecting = 0, switches = 0;
    for (const auto& road : b.map.roads) {
        rail_roads += road.rail ? 1 : 0;
        rail_connecting += road.rail && road.junction != "-1" ? 1 : 0;
        switches += road.switches.size();
    }
    std::size_t switch_vertices = 0;
    for (const auto& v : in.geometry.tracks.vertices) {
        switch_vertices += v.kind == geometry::VertexKind::switch_ ? 1 : 0;
    }
    r["roads"] = b.map.roads.size();
    r["rail_roads"] = rail_roads;
    r["rail_connecting_roads"] = rail_connecting;
    r["junctions"] = b.map.junctions.size();
    r["rail"] = {{"direct_links", b.rail.direct_links},
                 {"junctions", b.rail.junctions},
                 {"connections", b.rail.connections},
                 {"switches", switches},
                 {"switch_vertices", switch_vertices}};
    r["signals"] = b.signals;
    r["tunnels_and_bridges"] = b.structures;
    r["stations"] = b.stations;
    r["platforms"] = b.platforms;
    r["level_crossings"] = b.level_crossings;
    nlohmann::ordered_json no_road = nlohmann::ordered_json::array();
    for (const auto& m : b.level_crossings_without_road) {
        no_road.push_back({{"road_way", m.road_way}, {"node", m.node}, {"reason", m.reason}});
    }
    r["level_crossings_without_road_side"] = no_road;
    nlohmann::ordered_json unwritten = nlohmann::ordered_json::array();
    for (const auto& u : b.rail.unwritten) {
        const auto& e = in.geometry.tracks.edges[u.edge];
        nlohmann::ordered_json ways = nlohmann::ordered_json::array();
        for (const auto& span : e.ways) {
            ways.push_back(span.way_id);
        }
        unwritten.push_back({{"edge", u.edge}, {"ways", ways}, {"reason", u.reason}});
    }
    r["tracks_not_written"] = unwritten;
    nlohmann::ordered_json unlinked = nlohmann::ordered_json::array();
    for (const auto& u : b.rail.unlinked) {
        unlinked.push_back({{"node", in.geometry.tracks.vertices[u.vertex].node_id}, {"edge", u.edge}, {"reason", u.reason}});
    }
    r["track_ends_not_linked"] = unlinked;
    nlohmann::ordered_json features = nlohmann::ordered_json::array();
    for (const auto& [i, why] : b.features_not_written) {
        const auto& f = in.ingest.features[i];
        features.push_back({{"osm_type", f.osm_type}, {"id", f.id}, {"kind", f.kind}, {"reason", why}});
    }
    r["features_not_written"] = features;
    return r;
}

} // namespace railodd::xodr
