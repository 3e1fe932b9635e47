#pragma once
// The two companion files of odd_profile.json (docs/odd.md "Profile outputs"):
// odd_profile.geojson for GIS viewers and odd_profile.csv for spreadsheets.
// Both list the profile's elements in its order, one feature / row each.
#include "railodd/odd/profile.hpp"

#include <iosfwd>
#include <string>

namespace railodd::odd {

// RFC 7946 FeatureCollection in WGS84 lon/lat (7 decimals, about 1 cm): a
// Point for point elements, a LineString for s-ranges, both from `lonlat`
// (a range with a single position becomes a Point, none a null geometry).
// Properties: odd_element, element_id, attributes (object), road_id, track,
// s_start, s_end, chainage_start, chainage_end, osm_ids, source.
std::string to_geojson(const OddProfile& profile);
void write_geojson(const OddProfile& profile, std::ostream& out);

// RFC 4180 CSV with a header row and CRLF line ends: odd_element, element_id,
// road_id, s_start, s_end, chainage_start, chainage_end (metres, 3 decimals),
// track, point, attributes ("name=value;name=value"), osm_ids (space
// separated), source. Fields holding a comma, quote or line break are quoted.
std::string to_csv(const OddProfile& profile);
void write_csv(const OddProfile& profile, std::ostream& out);

} // namespace railodd::odd
