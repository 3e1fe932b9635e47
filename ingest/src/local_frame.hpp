#pragma once
// Helpers shared by the OSM and OGR readers: placing the local frame on the
// selected tracks, projecting into it, and putting results in a stable order.
#include "railodd/ingest/selection.hpp"
#include "railodd/ingest/types.hpp"

namespace railodd::ingest {

// Centre of the lon/lat bounds of all way nodes.
LonLat centre_of(const std::vector<Way>& ways);

// Lon/lat bounds of all way nodes grown by `margin_m` metres on every side.
BBox lonlat_bounds(const std::vector<Way>& ways, double margin_m);

void project_ways(std::vector<Way>& ways, const LocalProjection& proj);

// Sorts every list by id and fills the output counts, so that the result does
// not depend on input order or thread count.
void finalize(IngestResult& result);

} // namespace railodd::ingest
