#include "railodd/ingest/selection.hpp"

#include "railodd/util/errors.hpp"
#include "railodd/util/input_file.hpp"
#include "railodd/util/json_depth.hpp"

#include <nlohmann/json.hpp>

#include <cmath>
#include <fstream>
#include <limits>
#include <sstream>

namespace railodd::ingest {

using nlohmann::json;

BBox parse_bbox(const std::string& text) {
    std::vector<double> v;
    std::stringstream ss(text);
    std::string item;
    while (std::getline(ss, item, ',')) {
        try {
            std::size_t used = 0;
            v.push_back(std::stod(item, &used));
            if (used != item.size()) {
                throw std::invalid_argument(item);
            }
        } catch (const std::exception&) {
            throw UsageError("--bbox", "'" + text + "' is not W,S,E,N in degrees ('" + item + "' is no number)");
        }
    }
    if (v.size() != 4) {
        throw UsageError("--bbox", "'" + text + "' needs exactly four numbers W,S,E,N");
    }
    BBox b{v[0], v[1], v[2], v[3]};
    if (!(b.west < b.east && b.south < b.north) || b.west < -180 || b.east > 180 || b.south < -90 ||
        b.north > 90) {
        throw UsageError("--bbox", "'" + text + "' is empty or outside -180..180 / -90..90");
    }
    return b;
}

bool PolygonSelection::contains(LonLat p) const noexcept {
    if (!bounds.contains(p)) {
        return false;
    }
    bool inside = false;
    for (const auto& ring : rings) {
        for (std::size_t i = 0, j = ring.size() - 1; i < ring.size(); j = i++) {
            const LonLat& a = ring[i];
            const LonLat& b = ring[j];
            if ((a.lat > p.lat) != (b.lat > p.lat) &&
                p.lon < (b.lon - a.lon) * (p.lat - a.lat) / (b.lat - a.lat) + a.lon) {
                inside = !inside;
            }
        }
    }
    return inside;
}

namespace {

std::vector<LonLat> parse_ring(const json& coords, const std::string& file) {
    std::vector<LonLat> ring;
    for (const auto& c : coords) {
        if (!c.is_array() || c.size() < 2 || !c[0].is_number() || !c[1].is_number()) {
            throw InputError(file, "polygon coordinate is not [lon, lat]: " + c.dump());
        }
        ring.push_back({c[0].get<double>(), c[1].get<double>()});
    }
    if (ring.size() < 4) {
        throw InputError(file, "polygon ring has fewer than 4 positions");
    }
    return ring;
}

void collect_rings(const json& geom, const std::string& file, std::vector<std::vector<LonLat>>& rings) {
    const std::string type = geom.value("type", "");
    if (type == "FeatureCollection") {
        for (const auto& f : geom.at("features")) {
            collect_rings(f, file, rings);
        }
    } else if (type == "Feature") {
        collect_rings(geom.at("geometry"), file, rings);
    } else if (type == "Polygon") {
        for (const auto& r : geom.at("coordinates")) {
            rings.push_back(parse_ring(r, file));
        }
    } else if (type == "MultiPolygon") {
        for (const auto& poly : geom.at("coordinates")) {
            for (const auto& r : poly) {
                rings.push_back(parse_ring(r, file));
            }
        }
    } else {
        throw InputError(file, "expected a GeoJSON Polygon or MultiPolygon, found type '" + type + "'");
    }
}

} // namespace

PolygonSelection load_polygon_geojson(const std::filesystem::path& file) {
    const std::string text = read_input_file(file, "polygon file");
    require_json_depth(text, file);
    PolygonSelection sel;
    sel.source = file.string();
    try {
        collect_rings(json::parse(text), sel.source, sel.rings);
    } catch (const json::exception& e) {
        throw InputError(sel.source, std::string{"invalid GeoJSON: "} + e.what());
    }
    if (sel.rings.empty()) {
        throw InputError(sel.source, "no polygon in file");
    }
    constexpr double inf = std::numeric_limits<double>::infinity();
    sel.bounds = {inf, inf, -inf, -inf};
    for (const auto& ring : sel.rings) {
        for (const auto& p : ring) {
            sel.bounds.west = std::min(sel.bounds.west, p.lon);
            sel.bounds.east = std::max(sel.bounds.east, p.lon);
            sel.bounds.south = std::min(sel.bounds.south, p.lat);
            sel.bounds.north = std::max(sel.bounds.north, p.lat);
        }
    }
    return sel;
}

std::string Selection::describe() const {
    std::ostringstream out;
    out.precision(9);
    const char* sep = "";
    if (bbox) {
        out << "bbox " << bbox->west << ',' << bbox->south << ',' << bbox->east << ',' << bbox->north;
        sep = "; ";
    }
    if (polygon) {
        out << sep << "polygon " << polygon->source;
        sep = "; ";
    }
    if (relation) {
        out << sep << "relation " << *relation;
        sep = "; ";
    }
    if (!bbox && !polygon && !relation) {
        out << "whole file";
    }
    return out.str();
}

} // namespace railodd::ingest
