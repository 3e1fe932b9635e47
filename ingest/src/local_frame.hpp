#pragma once
// Helpers shared by the OSM and OGR readers: placing the local frame on the
// selected tracks, projecting into it, and putting results in a stable order.
#include "railodd/ingest/selection.hpp"
#include "railodd/ingest/types.hpp"

namespace railodd::ingest {

// Centre of the lon/lat bounds of all way nodes.
LonLat centre_of(const std::vector<Way>& ways);

// Tracks whose nodes are another track's (same order or reversed) are
// dropped with the reason; the lowest way id is kept.
void drop_duplicate_tracks(std::vector<Way>& tracks, std::vector<Dropped>& dropped);

// Lon/lat bounds of all way nodes grown by `margin_m` metres on every side.
BBox lonlat_bounds(const std::vector<Way>& ways, double margin_m);

void project_ways(std::vector<Way>& ways, const LocalProjection& proj);

// How far from its origin the local transverse Mercator frame is used: its
// scale error there is 1.2 % (k = 1 + d^2 / 2R^2) and grows fast beyond.
inline constexpr double max_frame_radius_m = 1000000.0;

// Throws InputError(file, ...) naming the first projected way with a node
// farther than max_frame_radius_m from the origin.
void check_frame_extent(const std::vector<Way>& ways, const std::string& file);

// Sorts every list by id and fills the output counts, so that the result does
// not depend on input order or thread count.
void finalize(IngestResult& result);

} // namespace railodd::ingest
