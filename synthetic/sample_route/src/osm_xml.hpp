#pragma once
// Serialises the sample route as OSM XML 0.6: nodes, then ways, then
// relations, each in id order, with fixed-precision coordinates so the text is
// identical on every run.
#include "osm_model.hpp"

#include <string>

namespace railodd::sample {

std::string to_osm_xml(const OsmData& data);

} // namespace railodd::sample
