#pragma once
// Which OSM objects railodd reads, decided by their tags alone.
#include <optional>
#include <string>
#include <string_view>

namespace osmium {
class TagList;
}

namespace railodd::ingest {

// railway=rail|light_rail|tram|subway|narrow_gauge|monorail|funicular. Lifecycle
// values (disused, abandoned, construction, proposed, razed) are not tracks.
bool is_track(const osmium::TagList& tags);
bool is_track_value(const char* railway_value);

// highway=* except lifecycle values and highway=platform (a bus stop, not a road).
bool is_road(const osmium::TagList& tags);

// The kind of a railway point feature node, or nothing.
std::optional<std::string> point_feature_kind(const osmium::TagList& tags);

// "platform" or "station" for platform ways/areas and station areas, or nothing.
std::optional<std::string> area_feature_kind(const osmium::TagList& tags);

// route=train|railway|tracks|tram|subway|light_rail
bool is_rail_route(const osmium::TagList& tags);

// type=multipolygon
bool is_multipolygon(const osmium::TagList& tags);

struct LandUseTag {
    std::string kind; // the taxonomy's Land use kind
    std::string tag;  // "landuse=residential"
};

// The land-use kind of an area's tags (the table in docs/odd.md "Land use"),
// or nothing for tags that say nothing about the surroundings (landuse=grass,
// construction, ...). landuse=* is read before natural=* and waterway=*.
std::optional<LandUseTag> land_use_kind(const osmium::TagList& tags);

} // namespace railodd::ingest
