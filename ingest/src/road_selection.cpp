#include "road_selection.hpp"

#include "local_frame.hpp"
#include "way_parts.hpp"

#include <algorithm>

namespace railodd::ingest {

namespace {

bool in_corridor(LonLat ll, const RoadContext& ctx, const LocalProjection& proj) {
    return ctx.near.contains(ll) && ctx.tracks.within(proj.forward(ll), ctx.corridor_m);
}

void add_roads(std::vector<RawWay> raw, const Locator& locate, IngestResult& result) {
    for (auto& r : raw) {
        ++result.counts.input_road_ways;
        BuiltWay built = build_way(std::move(r), locate);
        if (!built.drop_reason.empty()) {
            result.dropped.push_back({"road", "way", built.way.id, built.drop_reason});
            continue;
        }
        add_repairs(result, "road", built);
        result.roads.push_back(std::move(built.way));
    }
    project_ways(result.roads, result.projection);
}

} // namespace

void select_prefetched_roads(std::vector<RawWay> roads, const NodeLocations& locs, const RoadContext& ctx,
                             IngestResult& result) {
    std::vector<RawWay> near;
    for (auto& r : roads) {
        const bool touches = std::any_of(r.refs.begin(), r.refs.end(), [&](std::int64_t ref) {
            const auto* e = locs.located(ref);
            return e && in_corridor(e->lonlat, ctx, result.projection);
        });
        if (touches) {
            near.push_back(std::move(r));
        }
    }
    add_roads(std::move(near), locator_of(locs), result);
}

void read_corridor_roads(const RoadContext& ctx, IngestResult& result) {
    NodeLocations corridor =
        collect_nodes(ctx.file, [&](LonLat ll) { return in_corridor(ll, ctx, result.projection); });
    std::vector<RawWay> raw = scan_road_ways(ctx.file, corridor);

    // Roads leave the corridor: their outer nodes are located in one more pass.
    NodeLocations outer;
    for (const auto& r : raw) {
        for (std::int64_t ref : r.refs) {
            if (!corridor.located(ref)) {
                outer.want(ref);
            }
        }
    }
    outer.seal();
    if (outer.size() > 0) {
        locate_nodes(ctx.file, outer, "reading road nodes");
    }
    add_roads(std::move(raw), [&](std::int64_t id) {
        const auto* e = corridor.located(id);
        return e ? e : outer.located(id);
    }, result);
}

} // namespace railodd::ingest
