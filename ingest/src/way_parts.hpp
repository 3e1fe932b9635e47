#pragma once
// Turns a way's node references into located parts, cutting it where nodes are
// missing from a clipped extract and recording each repair explicitly.
#include "node_locations.hpp"
#include "osm_passes.hpp"
#include "railodd/ingest/types.hpp"

#include <functional>
#include <string>

namespace railodd::ingest {

using Locator = std::function<const NodeLocations::Entry*(std::int64_t)>;

struct BuiltWay {
    Way way;
    std::string drop_reason;        // non-empty: the way has no part of two or more nodes
    std::vector<std::string> repairs; // what was done to the input to use it
};

// Dropped, with the reason, when two consecutive nodes lie farther apart.
inline constexpr double max_segment_m = 50000.0;

BuiltWay build_way(RawWay raw, const Locator& locate);

// The drop reason of a track way that outlines an area: closed, and tagged
// area=yes or with a key that always means an area (landuse, building, ...).
// Mappers put railway=* on a station's landuse outline or on an engine
// shed's walls (Cologne: a 1.85 km landuse=railway polygon of 33 nodes; VDE
// 8.2: two building=yes rectangles); fitted, they are tracks with square
// corners. A closed way without such a tag stays a track (a test loop).
// Empty where the way is a track.
std::string area_outline_reason(const RawWay& raw);

inline Locator locator_of(const NodeLocations& locs) {
    return [&locs](std::int64_t id) { return locs.located(id); };
}

// Records a built way's repairs in the result under `kind` ("track", "road").
void add_repairs(IngestResult& result, const char* kind, const BuiltWay& built);

} // namespace railodd::ingest
