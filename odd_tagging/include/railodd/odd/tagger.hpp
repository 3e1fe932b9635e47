#pragma once
// Tags every stretch and point of track with the ODD elements of the taxonomy
// it belongs to (docs/odd.md, "Tagging"), from the fitted geometry, the OSM
// tags behind it and the OpenDRIVE map built from it, so that each tag names
// the road and s it applies to and the OSM ids it came from.
#include "railodd/odd/profile.hpp"
#include "railodd/odd/taxonomy.hpp"
#include "railodd/xodr/map_builder.hpp"

namespace railodd::odd {

struct TaggerInput {
    const xodr::MapInput& map_input; // the geometry stage's results
    const xodr::MapBuild& map;       // where each track went in map.xodr
};

OddProfile tag_route(const TaggerInput& input, const Taxonomy& taxonomy);

// The tags as <userData code="odd"> on the roads they belong to, one per
// element: "ID s=START-END name=value ...".
void add_odd_user_data(const OddProfile& profile, xodr::Map& map);

} // namespace railodd::odd
