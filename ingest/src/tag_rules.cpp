#include "tag_rules.hpp"

#include <osmium/osm/tag.hpp>

#include <array>
#include <cstring>

namespace railodd::ingest {

namespace {

template <std::size_t N>
bool one_of(const char* value, const std::array<const char*, N>& set) {
    if (!value) {
        return false;
    }
    for (const char* s : set) {
        if (std::strcmp(value, s) == 0) {
            return true;
        }
    }
    return false;
}

constexpr std::array<const char*, 7> track_values{
    "rail", "light_rail", "tram", "subway", "narrow_gauge", "monorail", "funicular"};

constexpr std::array<const char*, 12> point_values{
    "level_crossing", "crossing", "switch", "railway_crossing", "signal", "station",
    "halt", "stop", "tram_stop", "buffer_stop", "milestone", "derail"};

constexpr std::array<const char*, 7> road_lifecycle{
    "construction", "proposed", "abandoned", "disused", "razed", "platform", "planned"};

constexpr std::array<const char*, 5> rail_modes{"train", "tram", "subway", "light_rail", "monorail"};

constexpr std::array<const char*, 6> rail_routes{
    "train", "railway", "tracks", "tram", "subway", "light_rail"};

// public_transport=* objects also serve buses; only those marked for a rail mode count.
bool serves_rail(const osmium::TagList& tags) {
    for (const char* mode : rail_modes) {
        if (const char* v = tags.get_value_by_key(mode); v && std::strcmp(v, "yes") == 0) {
            return true;
        }
    }
    return false;
}

struct KindRule {
    const char* key;
    const char* value;
    const char* kind;
};

// Land use as seen from the track (docs/odd.md). landuse=grass is left out:
// it is mostly verges and embankments, inside any surroundings, and as the
// smallest area there it would override the town or field around it.
constexpr std::array<KindRule, 39> land_use_rules{{
    {"landuse", "residential", "urban"},     {"landuse", "commercial", "urban"},
    {"landuse", "retail", "urban"},          {"landuse", "education", "urban"},
    {"landuse", "institutional", "urban"},   {"landuse", "garages", "urban"},
    {"landuse", "allotments", "suburban"},   {"landuse", "village_green", "suburban"},
    {"landuse", "recreation_ground", "suburban"}, {"landuse", "cemetery", "suburban"},
    {"landuse", "farmyard", "rural"},        {"natural", "heath", "rural"},
    {"natural", "grassland", "rural"},       {"natural", "scrub", "rural"},
    {"landuse", "farmland", "agricultural"}, {"landuse", "meadow", "agricultural"},
    {"landuse", "orchard", "agricultural"},  {"landuse", "vineyard", "agricultural"},
    {"landuse", "greenfield", "agricultural"}, {"landuse", "plant_nursery", "agricultural"},
    {"landuse", "greenhouse_horticulture", "agricultural"}, {"landuse", "animal_keeping", "agricultural"},
    {"landuse", "industrial", "industrial"}, {"landuse", "railway", "industrial"},
    {"landuse", "quarry", "industrial"},     {"landuse", "landfill", "industrial"},
    {"landuse", "port", "industrial"},       {"landuse", "depot", "industrial"},
    {"landuse", "forest", "forest"},         {"natural", "wood", "forest"},
    {"natural", "water", "water"},           {"waterway", "riverbank", "water"},
    {"landuse", "reservoir", "water"},       {"landuse", "basin", "water"},
    {"water", "river", "water"},             {"water", "lake", "water"},
    {"water", "reservoir", "water"},         {"water", "canal", "water"},
    {"water", "pond", "water"},
}};

} // namespace

bool is_track_value(const char* railway_value) { return one_of(railway_value, track_values); }

bool is_track(const osmium::TagList& tags) { return is_track_value(tags.get_value_by_key("railway")); }

bool is_road(const osmium::TagList& tags) {
    const char* v = tags.get_value_by_key("highway");
    return v && !one_of(v, road_lifecycle);
}

std::optional<std::string> point_feature_kind(const osmium::TagList& tags) {
    const char* railway = tags.get_value_by_key("railway");
    if (one_of(railway, point_values)) {
        return std::string{railway};
    }
    if (railway && std::strcmp(railway, "platform") == 0) {
        return std::string{"platform"};
    }
    const char* pt = tags.get_value_by_key("public_transport");
    if (pt && serves_rail(tags)) {
        if (std::strcmp(pt, "platform") == 0) {
            return std::string{"platform"};
        }
        if (std::strcmp(pt, "station") == 0) {
            return std::string{"station"};
        }
        if (std::strcmp(pt, "stop_position") == 0) {
            return std::string{"stop"};
        }
    }
    return std::nullopt;
}

std::optional<std::string> area_feature_kind(const osmium::TagList& tags) {
    const char* railway = tags.get_value_by_key("railway");
    const char* pt = tags.get_value_by_key("public_transport");
    if ((railway && std::strcmp(railway, "platform") == 0) ||
        (pt && std::strcmp(pt, "platform") == 0 && (railway || serves_rail(tags)))) {
        return std::string{"platform"};
    }
    if ((railway && (std::strcmp(railway, "station") == 0 || std::strcmp(railway, "halt") == 0))) {
        return std::string{railway};
    }
    if (pt && std::strcmp(pt, "station") == 0 && serves_rail(tags)) {
        return std::string{"station"};
    }
    return std::nullopt;
}

bool is_rail_route(const osmium::TagList& tags) {
    const char* type = tags.get_value_by_key("type");
    return type && std::strcmp(type, "route") == 0 && one_of(tags.get_value_by_key("route"), rail_routes);
}

bool is_multipolygon(const osmium::TagList& tags) {
    const char* type = tags.get_value_by_key("type");
    return type && std::strcmp(type, "multipolygon") == 0;
}

std::optional<LandUseTag> land_use_kind(const osmium::TagList& tags) {
    // Rules are grouped by key in reading order, so the first key with a rule wins.
    for (const char* key : {"landuse", "natural", "waterway", "water"}) {
        const char* v = tags.get_value_by_key(key);
        if (!v) {
            continue;
        }
        for (const auto& r : land_use_rules) {
            if (std::strcmp(r.key, key) == 0 && std::strcmp(r.value, v) == 0) {
                if (std::strcmp(key, "landuse") == 0 && std::strcmp(v, "residential") == 0) {
                    const char* res = tags.get_value_by_key("residential");
                    if (res && std::strcmp(res, "rural") == 0) {
                        return LandUseTag{"rural", "landuse=residential"}; // residential=rural: scattered farms
                    }
                }
                return LandUseTag{r.kind, std::string{key} + "=" + v};
            }
        }
        if (std::strcmp(key, "landuse") == 0) {
            return std::nullopt; // a landuse the table leaves out is not overridden by natural=*
        }
    }
    return std::nullopt;
}

} // namespace railodd::ingest
