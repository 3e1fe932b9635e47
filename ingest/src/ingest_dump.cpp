#include "railodd/ingest/dump.hpp"

#include <map>

namespace railodd::ingest {

using nlohmann::ordered_json;

namespace {

const char* origin_type(Origin o) { return o == Origin::osm ? "way" : "ogr_feature"; }

ordered_json counts_by_kind(const std::vector<Feature>& features) {
    std::map<std::string, std::size_t> n;
    for (const auto& f : features) {
        ++n[f.kind];
    }
    ordered_json j = ordered_json::object();
    for (const auto& [k, v] : n) {
        j[k] = v;
    }
    return j;
}

ordered_json coords(const std::vector<NodeRef>& nodes) {
    ordered_json a = ordered_json::array();
    for (const auto& n : nodes) {
        a.push_back({n.lonlat.lon, n.lonlat.lat});
    }
    return a;
}

ordered_json way_feature(const Way& way, const char* layer) {
    ordered_json geom;
    if (way.parts.size() == 1) {
        geom = {{"type", "LineString"}, {"coordinates", coords(way.parts.front())}};
    } else {
        ordered_json lines = ordered_json::array();
        for (const auto& part : way.parts) {
            lines.push_back(coords(part));
        }
        geom = {{"type", "MultiLineString"}, {"coordinates", lines}};
    }
    ordered_json props = {{"layer", layer}, {"osm_type", origin_type(way.origin)}, {"osm_id", way.id},
                          {"clipped", way.clipped()}, {"tags", way.tags}};
    return {{"type", "Feature"}, {"geometry", geom}, {"properties", props}};
}

ordered_json feature_feature(const Feature& f) {
    ordered_json geom;
    if (f.outline.empty()) {
        geom = {{"type", "Point"}, {"coordinates", {f.position.lonlat.lon, f.position.lonlat.lat}}};
    } else if (f.area) {
        geom = {{"type", "Polygon"}, {"coordinates", ordered_json::array({coords(f.outline)})}};
    } else {
        geom = {{"type", "LineString"}, {"coordinates", coords(f.outline)}};
    }
    ordered_json props = {{"layer", "feature"}, {"kind", f.kind},     {"osm_type", f.osm_type},
                          {"osm_id", f.id},     {"on_track", f.on_track}, {"tags", f.tags}};
    return {{"type", "Feature"}, {"geometry", geom}, {"properties", props}};
}

} // namespace

ordered_json report_sections(const IngestResult& r) {
    const IngestCounts& c = r.counts;
    std::size_t clipped = 0;
    for (const auto& t : r.tracks) {
        clipped += t.clipped() ? 1 : 0;
    }
    ordered_json j;
    j["input"] = {{"file", r.source},
                  {"selection", r.selection},
                  {"track_ways", c.input_track_ways},
                  {"road_ways", c.input_road_ways},
                  {"features", c.input_features},
                  {"nodes", c.input_nodes},
                  {"track_nodes", c.input_track_nodes},
                  {"missing_track_nodes", c.missing_track_nodes}};
    j["output"] = {{"track_ways", c.output_track_ways},
                   {"clipped_track_ways", clipped},
                   {"road_ways", c.output_road_ways},
                   {"features", c.output_features},
                   {"features_by_kind", counts_by_kind(r.features)}};
    j["projection"] = {{"proj", r.projection.proj_string()},
                       {"origin", {{"lon", r.projection.origin().lon}, {"lat", r.projection.origin().lat}}}};
    ordered_json dropped = ordered_json::array();
    for (const auto& d : r.dropped) {
        dropped.push_back({{"kind", d.kind}, {"osm_type", d.osm_type}, {"osm_id", d.id}, {"reason", d.reason}});
    }
    j["dropped"] = std::move(dropped);
    ordered_json repairs = ordered_json::array();
    for (const auto& rp : r.repairs) {
        repairs.push_back({{"kind", rp.kind}, {"osm_type", rp.osm_type}, {"osm_id", rp.id}, {"action", rp.action}});
    }
    j["repairs"] = std::move(repairs);
    return j;
}

std::string to_geojson(const IngestResult& r) {
    ordered_json features = ordered_json::array();
    for (const auto& t : r.tracks) {
        features.push_back(way_feature(t, "track"));
    }
    for (const auto& w : r.roads) {
        features.push_back(way_feature(w, "road"));
    }
    for (const auto& f : r.features) {
        features.push_back(feature_feature(f));
    }
    ordered_json fc = {{"type", "FeatureCollection"}, {"features", std::move(features)}};
    return fc.dump(1) + "\n";
}

} // namespace railodd::ingest
