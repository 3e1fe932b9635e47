// Road-rail crossings: at nodes shared by a road and a track, and where road
// and track polylines cross without one.
#include "crossing_context.hpp"

#include <algorithm>
#include <cmath>
#include <span>
#include <tuple>

namespace railodd::geometry::detail {

namespace {

// A road passing a node that some track also passes.
struct RoadBranch {
    std::int64_t node;
    std::size_t road;
    Branch branch;
};

// The track through a shared node: the branch pair a train runs along, the
// edge the crossing is recorded on and its level at the node.
struct TrackPath {
    Branch back;
    Branch fwd;
    std::size_t edge = 0;
    double s = 0.0;
    Level level;
};

std::vector<RoadBranch> road_branches_at_track_nodes(const CrossingContext& ctx, const std::vector<ingest::Way>& roads) {
    const auto& at = ctx.edge_nodes();
    const auto on_track = [&](std::int64_t id) {
        const auto it = std::lower_bound(at.begin(), at.end(), id, [](const EdgeNode& e, std::int64_t v) { return e.node < v; });
        return it != at.end() && it->node == id;
    };
    std::vector<RoadBranch> out;
    for (std::size_t r = 0; r < roads.size(); ++r) {
        for (const auto& part : roads[r].parts) {
            for (std::size_t i = 0; i < part.size(); ++i) {
                if (!on_track(part[i].id)) {
                    continue;
                }
                if (i > 0) {
                    out.push_back({part[i].id, r, {r, part[i - 1].id, unit(part[i].xy, part[i - 1].xy)}});
                }
                if (i + 1 < part.size()) {
                    out.push_back({part[i].id, r, {r, part[i + 1].id, unit(part[i].xy, part[i + 1].xy)}});
                }
            }
        }
    }
    std::stable_sort(out.begin(), out.end(), [&](const RoadBranch& a, const RoadBranch& b) {
        return std::tie(a.node, roads[a.road].id, a.branch.neighbour) <
               std::tie(b.node, roads[b.road].id, b.branch.neighbour);
    });
    return out;
}

// The straightest pair of track branches at the node, recorded on the lower
// edge in its own direction; a track ending here is extended straight.
TrackPath track_path(const CrossingContext& ctx, std::span<const EdgeNode> passes) {
    struct Where {
        std::size_t index;
        int step;
    };
    std::vector<Branch> branches;
    std::vector<Where> where;
    for (const EdgeNode& n : passes) {
        const std::size_t size = ctx.graph().edges[n.edge].nodes.size();
        for (const int step : {-1, 1}) {
            if ((step < 0 && n.index > 0) || (step > 0 && n.index + 1 < size)) {
                branches.push_back(ctx.branch(n.edge, n.index, step));
                where.push_back({n.index, step});
            }
        }
    }
    const Route r = pair_routes(branches).front();
    std::size_t rec = r.a;
    if (r.b && branches[*r.b].owner < branches[rec].owner) {
        rec = *r.b;
    }
    const Branch other = r.b ? branches[rec == r.a ? *r.b : r.a] : opposite(branches[rec]);
    const auto segment = [&](std::size_t i) { return where[i].step < 0 ? where[i].index - 1 : where[i].index; };
    const std::size_t edge = branches[rec].owner;
    Level level = ctx.track_level(edge, segment(rec));
    if (r.b) {
        const std::size_t o = rec == r.a ? *r.b : r.a;
        level = common_level(level, ctx.track_level(branches[o].owner, segment(o)));
    }
    TrackPath path{other, branches[rec], edge, ctx.node_s(edge, where[rec].index), level};
    if (where[rec].step < 0) {
        std::swap(path.back, path.fwd);
    }
    return path;
}

void crossings_at_node(const CrossingContext& ctx, const std::vector<ingest::Way>& roads, const TrackPath& track,
                       ingest::XY point, std::int64_t node, std::span<const RoadBranch> at_node,
                       std::vector<RoadRailCrossing>& out) {
    std::vector<Branch> branches;
    for (const auto& rb : at_node) {
        branches.push_back(rb.branch);
    }
    const std::int64_t tagged = ctx.level_crossing_near(node, point);
    for (const Route& route : pair_routes(branches)) {
        const Branch& a = branches[route.a];
        const Side side_a = side_of(track.back, track.fwd, a);
        const Side side_b = route.b ? side_of(track.back, track.fwd, branches[*route.b]) : side_a;
        const bool through = route.b && side_a != Side::along && side_b != Side::along && side_a != side_b;
        // A road touching the track crosses only where the node says so.
        const bool touches_tagged = tagged == node && side_a != Side::along && side_b != Side::along;
        if (!through && !touches_tagged) {
            continue;
        }
        RoadRailCrossing c;
        c.edge = track.edge;
        c.road_way_id = roads[a.owner].id;
        Level road_level = level_of(roads[a.owner].tags);
        ingest::XY road_dir = a.dir;
        if (route.b) {
            const Branch& b = branches[*route.b];
            c.road_way_id = std::min(c.road_way_id, roads[b.owner].id);
            road_level = common_level(road_level, level_of(roads[b.owner].tags));
            road_dir = {a.dir.x - b.dir.x, a.dir.y - b.dir.y};
        }
        c.point = point;
        c.s = track.s;
        c.shared_node = node;
        c.level_crossing_node = tagged;
        const ingest::XY track_dir{track.fwd.dir.x - track.back.dir.x, track.fwd.dir.y - track.back.dir.y};
        c.angle_deg = line_angle_deg(track_dir, road_dir);
        c.road_line_deg = line_direction_deg(track_dir, road_dir);
        c.grade_separated = grade_separated(track.level, road_level);
        out.push_back(c);
    }
}

void shared_node_crossings(const CrossingContext& ctx, const std::vector<ingest::Way>& roads,
                           std::vector<RoadRailCrossing>& out) {
    const std::vector<RoadBranch> rbs = road_branches_at_track_nodes(ctx, roads);
    const auto& at = ctx.edge_nodes();
    auto t = at.begin();
    for (auto r = rbs.begin(); r != rbs.end();) {
        const std::int64_t node = r->node;
        const auto r_end = std::find_if(r, rbs.end(), [&](const RoadBranch& x) { return x.node != node; });
        t = std::lower_bound(t, at.end(), node, [](const EdgeNode& e, std::int64_t id) { return e.node < id; });
        const auto t_end = std::find_if(t, at.end(), [&](const EdgeNode& e) { return e.node != node; });
        const TrackPath path = track_path(ctx, {t, t_end});
        const ingest::XY point = ctx.graph().edges[t->edge].nodes[t->index].xy;
        crossings_at_node(ctx, roads, path, point, node, {r, r_end}, out);
        r = r_end;
    }
}

void geometric_crossings(const CrossingContext& ctx, const std::vector<ingest::Way>& roads,
                         std::vector<RoadRailCrossing>& out) {
    std::vector<NodeSegment> road_segments;
    std::vector<std::size_t> road_of;
    for (std::size_t r = 0; r < roads.size(); ++r) {
        for (const auto& part : roads[r].parts) {
            for (std::size_t i = 0; i + 1 < part.size(); ++i) {
                road_segments.push_back({part[i].xy, part[i + 1].xy, part[i].id, part[i + 1].id});
                road_of.push_back(r);
            }
        }
    }
    for (const SegmentHit& hit : crossing_segments(ctx.segments(), road_segments)) {
        const EdgeSegment& es = ctx.segment_refs()[hit.first];
        const NodeSegment& track = ctx.segments()[hit.first];
        const NodeSegment& road = road_segments[hit.second];
        const ingest::Way& way = roads[road_of[hit.second]];
        RoadRailCrossing c;
        c.edge = es.edge;
        c.road_way_id = way.id;
        c.point = hit.point;
        c.s = ctx.s_at(es.edge, es.index, hit.point);
        c.level_crossing_node = ctx.level_crossing_near(0, hit.point);
        c.angle_deg = line_angle_deg({track.b.x - track.a.x, track.b.y - track.a.y},
                                     {road.b.x - road.a.x, road.b.y - road.a.y});
        c.grade_separated = grade_separated(ctx.track_level(es.edge, es.index), level_of(way.tags));
        out.push_back(c);
    }
}

} // namespace

std::vector<RoadRailCrossing> road_rail_crossings(const CrossingContext& ctx, const std::vector<ingest::Way>& roads) {
    std::vector<RoadRailCrossing> out;
    shared_node_crossings(ctx, roads, out);
    geometric_crossings(ctx, roads, out);
    const auto key = [](const RoadRailCrossing& c) {
        return std::make_tuple(c.edge, c.road_way_id, c.s, c.shared_node, c.point.x, c.point.y);
    };
    std::sort(out.begin(), out.end(), [&](const auto& a, const auto& b) { return key(a) < key(b); });
    // A road passing exactly through a track node (or a track through a road
    // node) is hit from the segments on both sides of that node.
    const auto same = [](const RoadRailCrossing& a, const RoadRailCrossing& b) {
        return a.edge == b.edge && a.road_way_id == b.road_way_id && a.shared_node == 0 && b.shared_node == 0 &&
               std::abs(a.s - b.s) < 1e-6;
    };
    out.erase(std::unique(out.begin(), out.end(), same), out.end());
    return out;
}

} // namespace railodd::geometry::detail
