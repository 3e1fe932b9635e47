#include "railodd/ingest/ogr_reader.hpp"

#include "field_mapping.hpp"
#include "local_frame.hpp"
#include "tag_rules.hpp"

#include "railodd/util/errors.hpp"
#include "railodd/util/xml_text.hpp"
#include "railodd/util/phase_timer.hpp"

#include <gdal_priv.h>
#include <ogr_spatialref.h>
#include <ogrsf_frmts.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <map>
#include <mutex>
#include <set>

namespace railodd::ingest {

namespace fs = std::filesystem;

bool is_vector_source(const fs::path& file) {
    std::string ext = file.extension().string();
    std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return std::tolower(c); });
    static const std::set<std::string> vector_exts{".geojson", ".json", ".gpkg", ".shp", ".fgb", ".gml", ".kml", ".sqlite"};
    return vector_exts.count(ext) > 0;
}

namespace {

struct VectorLayer {
    GDALDatasetUniquePtr dataset;
    OGRLayer* layer = nullptr; // owned by dataset
};

VectorLayer open_layer(const fs::path& file, const FieldMapping& m) {
    static std::once_flag registered;
    std::call_once(registered, [] { GDALAllRegister(); });
    VectorLayer v;
    v.dataset = GDALDatasetUniquePtr(GDALDataset::Open(file.c_str(), GDAL_OF_VECTOR | GDAL_OF_READONLY));
    if (!v.dataset) {
        throw InputError(file.string(), std::string{"GDAL cannot open it as vector data: "} + CPLGetLastErrorMsg());
    }
    v.layer = m.layer.empty() ? v.dataset->GetLayer(0) : v.dataset->GetLayerByName(m.layer.c_str());
    if (!v.layer) {
        throw InputError(file.string(), m.layer.empty() ? "no layer" : "no layer named '" + m.layer + "' (" + m.source + ")");
    }
    OGRFeatureDefn* defn = v.layer->GetLayerDefn();
    auto check_field = [&](const std::string& field, int line) {
        if (defn->GetFieldIndex(field.c_str()) < 0) {
            std::string names;
            for (int i = 0; i < defn->GetFieldCount(); ++i) {
                names += (i ? ", " : "") + std::string{defn->GetFieldDefn(i)->GetNameRef()};
            }
            throw InputError(m.source + ":" + std::to_string(line),
                             "field '" + field + "' is not in layer '" + v.layer->GetName() + "' of " + file.string() +
                                 " (fields: " + names + ")");
        }
    };
    for (const auto& rule : m.tags) {
        if (!rule.constant) {
            check_field(rule.field, rule.line);
        }
    }
    if (!m.id_field.empty()) {
        check_field(m.id_field, 0);
    }
    return v;
}

std::unique_ptr<OGRCoordinateTransformation> to_wgs84(const fs::path& file, const VectorLayer& v, const FieldMapping& m) {
    OGRSpatialReference src;
    if (!m.crs.empty()) {
        if (src.SetFromUserInput(m.crs.c_str()) != OGRERR_NONE) {
            throw InputError(m.source, "crs '" + m.crs + "' is not understood by GDAL/PROJ");
        }
    } else if (const OGRSpatialReference* own = v.layer->GetSpatialRef()) {
        src = *own;
    } else {
        throw InputError(file.string(), "layer has no coordinate reference system; set 'crs:' in " + m.source);
    }
    src.SetAxisMappingStrategy(OAMS_TRADITIONAL_GIS_ORDER);
    OGRSpatialReference wgs84;
    wgs84.importFromEPSG(4326);
    wgs84.SetAxisMappingStrategy(OAMS_TRADITIONAL_GIS_ORDER);
    std::unique_ptr<OGRCoordinateTransformation> ct(OGRCreateCoordinateTransformation(&src, &wgs84));
    if (!ct) {
        throw InputError(file.string(), "no transformation from the layer's CRS to WGS84");
    }
    return ct;
}

Tags map_tags(const OGRFeature& f, const FieldMapping& m) {
    Tags tags;
    for (const auto& rule : m.tags) {
        if (rule.constant) {
            tags[rule.key] = *rule.constant;
            continue;
        }
        const int idx = f.GetFieldIndex(rule.field.c_str());
        if (!f.IsFieldSetAndNotNull(idx)) {
            if (rule.fallback) {
                tags[rule.key] = *rule.fallback;
            }
            continue;
        }
        std::string value = f.GetFieldAsString(idx);
        if (const auto it = rule.values.find(value); it != rule.values.end()) {
            value = it->second;
        }
        if (!value.empty()) {
            tags[rule.key] = value;
        }
    }
    return tags;
}

// Vertices at the same position get the same synthetic node id, so that lines
// meeting end to end are joined as in OSM.
class VertexIds {
public:
    std::int64_t id_of(LonLat p) {
        const auto key = std::make_pair(std::llround(p.lon * 1e7), std::llround(p.lat * 1e7));
        return ids_.try_emplace(key, static_cast<std::int64_t>(ids_.size()) + 1).first->second;
    }

private:
    std::map<std::pair<long long, long long>, std::int64_t> ids_;
};

std::vector<std::vector<NodeRef>> line_parts(const OGRGeometry& geom, OGRCoordinateTransformation& ct, VertexIds& ids) {
    std::vector<const OGRLineString*> lines;
    const auto type = wkbFlatten(geom.getGeometryType());
    if (type == wkbLineString) {
        lines.push_back(geom.toLineString());
    } else if (type == wkbMultiLineString) {
        for (const auto* l : geom.toMultiLineString()) {
            lines.push_back(l);
        }
    }
    std::vector<std::vector<NodeRef>> parts;
    for (const auto* line : lines) {
        std::vector<NodeRef> part;
        for (int i = 0; i < line->getNumPoints(); ++i) {
            double x = line->getX(i), y = line->getY(i), z = line->getZ(i);
            if (!ct.Transform(1, &x, &y, &z)) {
                throw std::runtime_error("coordinate transformation failed");
            }
            if (!(std::abs(x) <= 180.0 && std::abs(y) <= 90.0)) { // NaN and infinities too
                throw std::runtime_error("a vertex is not a longitude/latitude (" + std::to_string(x) + ", " +
                                         std::to_string(y) + ")");
            }
            NodeRef n;
            n.lonlat = {x, y};
            n.id = ids.id_of(n.lonlat);
            if (line->Is3D() && z >= -1000.0 && z <= 10000.0) { // NaN, inf, no-data: no elevation
                n.ele = z;
            }
            if (part.empty() || part.back().id != n.id) {
                part.push_back(n);
            }
        }
        if (part.size() >= 2) {
            parts.push_back(std::move(part));
        }
    }
    return parts;
}

// One feature as a track way, or the reason it cannot be one.
struct FeatureWay {
    Way way;
    std::string reason;
    bool text_repaired = false; // attribute text made valid UTF-8 XML text
};

FeatureWay feature_way(OGRFeature& f, std::int64_t id, const FieldMapping& m, OGRCoordinateTransformation& ct,
                       VertexIds& ids, const fs::path& file) {
    FeatureWay fw;
    Way& way = fw.way;
    way.origin = Origin::ogr;
    way.id = id;
    for (auto& [key, value] : map_tags(f, m)) {
        std::string k = key;
        fw.text_repaired = make_xml_text(k) || fw.text_repaired;
        fw.text_repaired = make_xml_text(value) || fw.text_repaired;
        way.tags.emplace(std::move(k), std::move(value));
    }
    const OGRGeometry* geom = f.GetGeometryRef();
    if (!geom || geom->IsEmpty()) {
        fw.reason = "feature has no geometry";
        return fw;
    }
    try {
        way.parts = line_parts(*geom, ct, ids);
    } catch (const std::exception& e) {
        throw InputError(file.string(), "feature " + std::to_string(id) + ": " + e.what());
    }
    if (way.parts.empty()) {
        fw.reason = std::string{"geometry "} + geom->getGeometryName() + " has no line of two or more vertices";
    }
    for (const auto& part : way.parts) {
        way.node_count += part.size();
    }
    return fw;
}

bool in_selection(const Way& way, const Selection& sel) {
    return !sel.spatial() || std::any_of(way.parts.begin(), way.parts.end(), [&](const auto& part) {
               return std::any_of(part.begin(), part.end(), [&](const NodeRef& n) { return sel.contains(n.lonlat); });
           });
}

std::size_t distinct_nodes(const std::vector<Way>& ways) {
    std::set<std::int64_t> nodes;
    for (const auto& t : ways) {
        for (const auto& p : t.parts) {
            for (const auto& n : p) {
                nodes.insert(n.id);
            }
        }
    }
    return nodes.size();
}

} // namespace

IngestResult read_vector(const fs::path& file, const fs::path& mapping_file, const Selection& sel) {
    if (sel.relation) {
        throw UsageError("--relation", "route relations exist only in OSM input, not in " + file.string());
    }
    PhaseTimer timer;
    timer.start("read_vector");
    const FieldMapping m = load_field_mapping(mapping_file);
    VectorLayer v = open_layer(file, m);
    auto ct = to_wgs84(file, v, m);
    IngestResult result;
    result.source = file.string();
    result.selection = sel.describe();
    VertexIds ids;
    std::set<std::int64_t> seen_ids;
    v.layer->ResetReading();
    for (auto& f : *v.layer) {
        const std::int64_t id = m.id_field.empty() ? f->GetFID() : f->GetFieldAsInteger64(m.id_field.c_str());
        if (!seen_ids.insert(id).second) {
            throw InputError(file.string(), "feature id " + std::to_string(id) + " occurs twice" +
                                                (m.id_field.empty() ? "" : " in field '" + m.id_field + "'"));
        }
        FeatureWay fw = feature_way(*f, id, m, *ct, ids, file);
        if (!in_selection(fw.way, sel)) {
            continue;
        }
        ++result.counts.input_track_ways;
        const std::string railway = tag_or(fw.way.tags, "railway");
        if (fw.reason.empty() && !is_track_value(railway.c_str())) {
            fw.reason = "mapped railway=" + (railway.empty() ? std::string{"(none)"} : railway) + " is not a track value";
        }
        if (!fw.reason.empty()) {
            result.dropped.push_back({"track", "ogr_feature", id, fw.reason});
            continue;
        }
        if (fw.text_repaired) {
            result.repairs.push_back({"track", "ogr_feature", id,
                                      "attribute text with bytes that are not UTF-8 XML text kept with U+FFFD in "
                                      "their place"});
        }
        result.tracks.push_back(std::move(fw.way));
    }
    drop_duplicate_tracks(result.tracks, result.dropped);
    if (result.tracks.empty()) {
        throw InputError(file.string(), "no track in the selection (" + result.selection + "); " +
                                            std::to_string(result.dropped.size()) + " feature(s) dropped");
    }
    result.projection = LocalProjection(centre_of(result.tracks));
    project_ways(result.tracks, result.projection);
    check_frame_extent(result.tracks, file.string());
    result.counts.input_track_nodes = distinct_nodes(result.tracks);
    result.counts.input_nodes = result.counts.input_track_nodes;
    timer.stop();
    finalize(result);
    result.timings = timer.seconds();
    return result;
}

} // namespace railodd::ingest
