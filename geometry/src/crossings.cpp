// find_crossings: the public entry of the crossing searches.
#include "railodd/geometry/crossings.hpp"

#include "crossing_context.hpp"

namespace railodd::geometry {

Crossings find_crossings(const TrackGraph& tracks, const std::vector<ingest::Way>& track_ways,
                         const std::vector<ingest::Way>& roads, const std::vector<ingest::Feature>& features) {
    const detail::CrossingContext ctx(tracks, track_ways, features);
    return {detail::road_rail_crossings(ctx, roads), detail::track_crossings(ctx)};
}

} // namespace railodd::geometry
