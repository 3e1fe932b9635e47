#include "railodd/ingest/osm_reader.hpp"

#include "feature_selection.hpp"
#include "local_frame.hpp"
#include "osm_passes.hpp"
#include "segment_grid.hpp"
#include "way_parts.hpp"

#include "railodd/util/errors.hpp"
#include "railodd/util/phase_timer.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace railodd::ingest {

namespace fs = std::filesystem;

namespace {

Locator locator_of(const NodeLocations& locs) {
    return [&locs](std::int64_t id) { return locs.located(id); };
}

bool any_node_selected(const Way& way, const Selection& sel) {
    for (const auto& part : way.parts) {
        for (const auto& n : part) {
            if (sel.contains(n.lonlat)) {
                return true;
            }
        }
    }
    return false;
}

void add_repairs(IngestResult& result, const char* kind, std::int64_t id, const std::vector<std::string>& actions) {
    for (const auto& a : actions) {
        result.repairs.push_back({kind, "way", id, a});
    }
}

// Spatial selection and node accounting of the track ways read.
void select_tracks(std::vector<RawWay>& raw, const NodeLocations& locs, const Selection& sel, IngestResult& result) {
    for (auto& r : raw) {
        BuiltWay built = build_way(std::move(r), locator_of(locs));
        const bool unlocated = built.way.parts.empty() && built.way.missing_nodes == built.way.node_count;
        // A way of which nothing is located cannot be placed: it is kept in the
        // accounting (and dropped) rather than silently left out of the selection.
        if (sel.spatial() && !unlocated && !any_node_selected(built.way, sel)) {
            continue;
        }
        ++result.counts.input_track_ways;
        result.counts.missing_track_nodes += built.way.missing_nodes;
        if (!built.drop_reason.empty()) {
            result.dropped.push_back({"track", "way", built.way.id, built.drop_reason});
            continue;
        }
        add_repairs(result, "track", built.way.id, built.repairs);
        result.tracks.push_back(std::move(built.way));
    }
}

SegmentGrid track_grid(const std::vector<Way>& tracks, double cell) {
    SegmentGrid grid(cell);
    std::vector<XY> pts;
    for (const auto& way : tracks) {
        for (const auto& part : way.parts) {
            pts.clear();
            for (const auto& n : part) {
                pts.push_back(n.xy);
            }
            grid.add_polyline(pts);
        }
    }
    return grid;
}

void read_roads(const fs::path& file, const IngestOptions& options, const SegmentGrid& grid, IngestResult& result) {
    const double corridor = options.road_corridor_m;
    const BBox near = lonlat_bounds(result.tracks, corridor);
    const LocalProjection& proj = result.projection;
    NodeLocations in_corridor = collect_nodes(file, [&](LonLat ll) {
        return near.contains(ll) && grid.distance(proj.forward(ll), corridor) <= corridor;
    });
    std::vector<RawWay> raw = scan_road_ways(file, in_corridor);

    // Roads leave the corridor: their outer nodes are located in one more pass.
    NodeLocations outer;
    for (const auto& r : raw) {
        for (std::int64_t ref : r.refs) {
            if (!in_corridor.located(ref)) {
                outer.want(ref);
            }
        }
    }
    outer.seal();
    if (outer.size() > 0) {
        locate_nodes(file, outer, "reading road nodes");
    }
    const Locator locate = [&](std::int64_t id) {
        const auto* e = in_corridor.located(id);
        return e ? e : outer.located(id);
    };
    for (auto& r : raw) {
        ++result.counts.input_road_ways;
        BuiltWay built = build_way(std::move(r), locate);
        if (!built.drop_reason.empty()) {
            result.dropped.push_back({"road", "way", built.way.id, built.drop_reason});
            continue;
        }
        add_repairs(result, "road", built.way.id, built.repairs);
        result.roads.push_back(std::move(built.way));
    }
    project_ways(result.roads, proj);
}

std::vector<std::int64_t> sorted_track_node_ids(const std::vector<Way>& tracks) {
    std::vector<std::int64_t> ids;
    for (const auto& way : tracks) {
        for (const auto& part : way.parts) {
            for (const auto& n : part) {
                ids.push_back(n.id);
            }
        }
    }
    std::sort(ids.begin(), ids.end());
    ids.erase(std::unique(ids.begin(), ids.end()), ids.end());
    return ids;
}

} // namespace

IngestResult read_osm(const fs::path& file, const IngestOptions& options) {
    std::error_code ec;
    if (!fs::is_regular_file(file, ec)) {
        throw InputError(file.string(), fs::exists(file, ec) ? "not a regular file" : "no such file");
    }
    const Selection& sel = options.selection;
    PhaseTimer timer;
    IngestResult result;
    result.source = file.string();
    result.selection = sel.describe();

    // Phase 1: a route relation restricts the tracks to its member ways.
    std::vector<std::int64_t> members;
    if (sel.relation) {
        timer.start("read_relations");
        members = relation_way_members(file, *sel.relation);
    }

    // Phase 2: track, platform and station ways; only their node ids are known yet.
    timer.start("read_ways");
    WayScan ways = scan_track_ways(file, sel.relation ? &members : nullptr);
    NodeLocations locs;
    for (const auto& w : ways.tracks) {
        locs.want_all(w.refs);
    }
    for (const auto& f : ways.area_features) {
        locs.want_all(f.refs);
    }
    locs.seal();

    // Phase 3: locations of exactly those nodes, and railway point features.
    timer.start("read_nodes");
    NodeScan nodes = scan_nodes(file, locs);
    result.counts.input_nodes = nodes.node_count;

    // Phase 4: the selection, the local frame and the track geometry in it.
    timer.start("select_and_project");
    select_tracks(ways.tracks, locs, sel, result);
    if (result.tracks.empty()) {
        throw InputError(file.string(), "no railway track way with located nodes in the selection (" +
                                            result.selection + "); " + std::to_string(result.dropped.size()) +
                                            " track way(s) without node locations");
    }
    result.projection = LocalProjection(centre_of(result.tracks));
    project_ways(result.tracks, result.projection);
    result.counts.input_track_nodes = sorted_track_node_ids(result.tracks).size();
    const double reach = std::max({options.road_corridor_m, options.feature_distance_m, options.station_distance_m});
    const SegmentGrid grid = track_grid(result.tracks, std::max(reach, 100.0));

    // Phase 5: features on or near the selected tracks.
    timer.start("select_features");
    FeatureContext ctx{sel, options, grid, result.projection, sorted_track_node_ids(result.tracks)};
    select_features(std::move(nodes.point_features), std::move(ways.area_features), locs, ctx, result);

    // Phase 6: roads in the corridor around the tracks.
    if (options.road_corridor_m > 0) {
        timer.start("read_roads");
        read_roads(file, options, grid, result);
    }
    timer.stop();
    finalize(result);
    result.timings = timer.seconds();
    return result;
}

} // namespace railodd::ingest
