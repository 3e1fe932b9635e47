#pragma once
// What part of the input to convert: a bounding box, a polygon, a route
// relation, or any combination (all given conditions must hold).
#include "railodd/ingest/projection.hpp"

#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

namespace railodd::ingest {

struct BBox {
    double west = 0, south = 0, east = 0, north = 0;
    bool contains(LonLat p) const noexcept {
        return p.lon >= west && p.lon <= east && p.lat >= south && p.lat <= north;
    }
};

// Parses "W,S,E,N" in degrees; throws UsageError on malformed or empty boxes.
BBox parse_bbox(const std::string& text);

// Rings of one or more polygons; a point is inside by the even-odd rule over all rings,
// so holes of GeoJSON polygons are honoured.
struct PolygonSelection {
    std::string source;
    std::vector<std::vector<LonLat>> rings;
    BBox bounds;
    bool contains(LonLat p) const noexcept;
};

// Reads a GeoJSON Polygon / MultiPolygon (bare geometry, Feature or FeatureCollection).
PolygonSelection load_polygon_geojson(const std::filesystem::path& file);

struct Selection {
    std::optional<BBox> bbox;
    std::optional<PolygonSelection> polygon;
    std::optional<std::int64_t> relation;

    bool spatial() const noexcept { return bbox.has_value() || polygon.has_value(); }
    bool contains(LonLat p) const noexcept {
        return (!bbox || bbox->contains(p)) && (!polygon || polygon->contains(p));
    }
    std::string describe() const;
};

} // namespace railodd::ingest
