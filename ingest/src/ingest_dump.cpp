#include "railodd/ingest/dump.hpp"

#include "railodd/util/json_text.hpp"

#include <cmath>
#include <map>
#include <ostream>
#include <sstream>

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

void append_coords(std::string& out, const std::vector<NodeRef>& nodes) {
    out += '[';
    for (std::size_t i = 0; i < nodes.size(); ++i) {
        out += i ? ",[" : "[";
        append_json_number(out, nodes[i].lonlat.lon);
        out += ',';
        append_json_number(out, nodes[i].lonlat.lat);
        out += ']';
    }
    out += ']';
}

void append_tags(std::string& out, const Tags& tags) {
    out += '{';
    const char* sep = "";
    for (const auto& [k, v] : tags) {
        out += sep;
        append_json_string(out, k);
        out += ':';
        append_json_string(out, v);
        sep = ",";
    }
    out += '}';
}

void append_way(std::string& out, const Way& way, const char* layer) {
    out += "{\"type\":\"Feature\",\"geometry\":";
    if (way.parts.size() == 1) {
        out += "{\"type\":\"LineString\",\"coordinates\":";
        append_coords(out, way.parts.front());
    } else {
        out += "{\"type\":\"MultiLineString\",\"coordinates\":[";
        for (std::size_t i = 0; i < way.parts.size(); ++i) {
            out += i ? "," : "";
            append_coords(out, way.parts[i]);
        }
        out += ']';
    }
    out += "},\"properties\":{\"layer\":\"";
    out += layer;
    out += "\",\"osm_type\":\"";
    out += origin_type(way.origin);
    out += "\",\"osm_id\":";
    append_json_number(out, way.id);
    out += way.clipped() ? ",\"clipped\":true" : ",\"clipped\":false";
    out += ",\"tags\":";
    append_tags(out, way.tags);
    out += "}}";
}

void append_feature(std::string& out, const Feature& f) {
    out += "{\"type\":\"Feature\",\"geometry\":";
    if (f.outline.empty()) {
        out += "{\"type\":\"Point\",\"coordinates\":[";
        append_json_number(out, f.position.lonlat.lon);
        out += ',';
        append_json_number(out, f.position.lonlat.lat);
        out += ']';
    } else if (f.area) {
        out += "{\"type\":\"Polygon\",\"coordinates\":[";
        append_coords(out, f.outline);
        out += ']';
    } else {
        out += "{\"type\":\"LineString\",\"coordinates\":";
        append_coords(out, f.outline);
    }
    out += "},\"properties\":{\"layer\":\"feature\",\"kind\":";
    append_json_string(out, f.kind);
    out += ",\"osm_type\":";
    append_json_string(out, f.osm_type);
    out += ",\"osm_id\":";
    append_json_number(out, f.id);
    out += f.on_track ? ",\"on_track\":true" : ",\"on_track\":false";
    out += ",\"tags\":";
    append_tags(out, f.tags);
    out += "}}";
}

ordered_json land_use_by_kind(const std::vector<LandUseArea>& areas) {
    std::map<std::string, std::size_t> n;
    for (const auto& a : areas) {
        ++n[a.kind];
    }
    ordered_json j = ordered_json::object();
    for (const auto& [k, v] : n) {
        j[k] = v;
    }
    return j;
}

// The simplified outline as read, back in WGS84: a Polygon of all rings
// (the even-odd rule decides inside, as in the tagger).
void append_land_use(std::string& out, const LandUseArea& a, const LocalProjection& proj) {
    out += "{\"type\":\"Feature\",\"geometry\":{\"type\":\"Polygon\",\"coordinates\":[";
    for (std::size_t r = 0; r < a.rings.size(); ++r) {
        out += r ? ",[" : "[";
        for (std::size_t i = 0; i <= a.rings[r].size(); ++i) {
            const LonLat ll = proj.inverse(a.rings[r][i % a.rings[r].size()]);
            out += i ? ",[" : "[";
            append_json_number(out, ll.lon);
            out += ',';
            append_json_number(out, ll.lat);
            out += ']';
        }
        out += ']';
    }
    out += "]},\"properties\":{\"layer\":\"land_use\",\"osm_type\":";
    append_json_string(out, a.osm_type);
    out += ",\"osm_id\":";
    append_json_number(out, a.id);
    out += ",\"kind\":";
    append_json_string(out, a.kind);
    out += ",\"tag\":";
    append_json_string(out, a.tag);
    out += ",\"area_m2\":";
    append_json_number(out, std::round(a.area_m2));
    out += "}}";
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
                  {"missing_track_nodes", c.missing_track_nodes},
                  {"duplicate_nodes", c.duplicate_nodes},
                  {"land_use_areas", c.input_land_use}};
    j["output"] = {{"track_ways", c.output_track_ways},
                   {"clipped_track_ways", clipped},
                   {"road_ways", c.output_road_ways},
                   {"features", c.output_features},
                   {"features_by_kind", counts_by_kind(r.features)},
                   {"land_use_areas", c.output_land_use},
                   {"land_use_by_kind", land_use_by_kind(r.land_use)}};
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

void write_geojson(const IngestResult& r, std::ostream& os) {
    // One feature per line: diffable, and streamable by line-oriented tools.
    // Each is printed as it is made: a large input's dump is never whole in
    // memory.
    os << "{\"type\":\"FeatureCollection\",\"features\":[\n";
    std::string out;
    const char* sep = "";
    auto next = [&] {
        os << out;
        out = sep;
        sep = ",\n";
    };
    for (const auto& t : r.tracks) {
        next();
        append_way(out, t, "track");
    }
    for (const auto& w : r.roads) {
        next();
        append_way(out, w, "road");
    }
    for (const auto& f : r.features) {
        next();
        append_feature(out, f);
    }
    for (const auto& a : r.land_use) {
        next();
        append_land_use(out, a, r.projection);
    }
    os << out << "\n]}\n";
}

std::string to_geojson(const IngestResult& r) {
    std::ostringstream os;
    write_geojson(r, os);
    return os.str();
}

} // namespace railodd::ingest
