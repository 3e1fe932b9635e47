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

} // namespace railodd::ingest
