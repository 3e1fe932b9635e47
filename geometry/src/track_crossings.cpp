// Track-track crossings: diamond crossings sharing a node (crossing vertices)
// and tracks crossing without a shared node (mostly one on a bridge).
#include "crossing_context.hpp"

#include <algorithm>
#include <cmath>
#include <optional>
#include <tuple>

namespace railodd::geometry::detail {

namespace {

// An edge end at a vertex: the branch plus where it sits on the edge.
struct EdgeEnd {
    Branch branch;
    std::size_t index;   // node index of the vertex on the edge
    std::size_t segment; // the edge's segment leaving the vertex
};

std::vector<EdgeEnd> ends_at(const CrossingContext& ctx, const GraphVertex& v) {
    std::vector<EdgeEnd> ends;
    std::optional<std::size_t> previous;
    for (const std::size_t e : v.edges) {
        if (previous == e) {
            continue; // a loop is listed twice; both of its ends are taken below
        }
        previous = e;
        const auto& nodes = ctx.graph().edges[e].nodes;
        if (nodes.front().id == v.node_id) {
            ends.push_back({ctx.branch(e, 0, 1), 0, 0});
        }
        if (nodes.back().id == v.node_id) {
            ends.push_back({ctx.branch(e, nodes.size() - 1, -1), nodes.size() - 1, nodes.size() - 2});
        }
    }
    return ends;
}

// Of a route's two ends, the one on the lower edge (nearer its start on a tie).
const EdgeEnd& lead(const EdgeEnd& a, const EdgeEnd& b) {
    return std::tie(a.branch.owner, a.index) <= std::tie(b.branch.owner, b.index) ? a : b;
}

void vertex_crossings(const CrossingContext& ctx, std::vector<TrackCrossing>& out) {
    for (const auto& v : ctx.graph().vertices) {
        if (v.kind != VertexKind::crossing) {
            continue;
        }
        const std::vector<EdgeEnd> ends = ends_at(ctx, v);
        if (ends.size() != 4) {
            continue; // a crossing with a branch unmapped has no second route to cross
        }
        std::vector<Branch> branches;
        for (const auto& e : ends) {
            branches.push_back(e.branch);
        }
        const std::vector<Route> routes = pair_routes(branches);
        const EdgeEnd &a1 = ends[routes[0].a], &a2 = ends[*routes[0].b];
        const EdgeEnd &b1 = ends[routes[1].a], &b2 = ends[*routes[1].b];
        const Side s1 = side_of(a1.branch, a2.branch, b1.branch);
        const Side s2 = side_of(a1.branch, a2.branch, b2.branch);
        if (s1 == Side::along || s2 == Side::along || s1 == s2) {
            continue; // the routes touch without crossing
        }
        const EdgeEnd* la = &lead(a1, a2);
        const EdgeEnd* lb = &lead(b1, b2);
        const Level level_a = common_level(ctx.track_level(a1.branch.owner, a1.segment),
                                           ctx.track_level(a2.branch.owner, a2.segment));
        const Level level_b = common_level(ctx.track_level(b1.branch.owner, b1.segment),
                                           ctx.track_level(b2.branch.owner, b2.segment));
        if (lb->branch.owner < la->branch.owner) {
            std::swap(la, lb);
        }
        TrackCrossing c;
        c.edge_a = la->branch.owner;
        c.edge_b = lb->branch.owner;
        c.point = v.xy;
        c.s_a = ctx.node_s(c.edge_a, la->index);
        c.s_b = ctx.node_s(c.edge_b, lb->index);
        c.shared_node = v.node_id;
        c.angle_deg = line_angle_deg({a1.branch.dir.x - a2.branch.dir.x, a1.branch.dir.y - a2.branch.dir.y},
                                     {b1.branch.dir.x - b2.branch.dir.x, b1.branch.dir.y - b2.branch.dir.y});
        c.grade_separated = grade_separated(level_a, level_b);
        out.push_back(c);
    }
}

// Side-by-side tracks are at least this far apart (centre to centre), so two
// polylines never this far apart since leaving a common vertex are one turnout.
constexpr double turnout_spread_m = 3.0;

// Nodes of an edge from one of its ends up to (and including) the first node
// of segment `segment`, or the second node when walking from the back.
std::vector<ingest::XY> stretch(const GraphEdge& e, std::size_t segment, bool from_front, ingest::XY crossing) {
    std::vector<ingest::XY> pts;
    if (from_front) {
        for (std::size_t k = 0; k <= segment; ++k) {
            pts.push_back(e.nodes[k].xy);
        }
    } else {
        for (std::size_t k = e.nodes.size() - 1; k > segment; --k) {
            pts.push_back(e.nodes[k].xy);
        }
    }
    pts.push_back(crossing);
    return pts;
}

double distance_to_polyline(ingest::XY p, const std::vector<ingest::XY>& line) {
    double best = std::hypot(p.x - line[0].x, p.y - line[0].y);
    for (std::size_t i = 0; i + 1 < line.size(); ++i) {
        const double dx = line[i + 1].x - line[i].x, dy = line[i + 1].y - line[i].y;
        const double len2 = dx * dx + dy * dy;
        const double t = len2 > 0.0 ? std::clamp(((p.x - line[i].x) * dx + (p.y - line[i].y) * dy) / len2, 0.0, 1.0) : 0.0;
        best = std::min(best, std::hypot(line[i].x + t * dx - p.x, line[i].y + t * dy - p.y));
    }
    return best;
}

bool never_spread(const std::vector<ingest::XY>& a, const std::vector<ingest::XY>& b) {
    const auto close = [](const auto& from, const auto& to) {
        return std::all_of(from.begin(), from.end(),
                           [&](ingest::XY p) { return distance_to_polyline(p, to) <= turnout_spread_m; });
    };
    return close(a, b) && close(b, a);
}

// Noisy polylines of a turnout's two legs cross each other soon after the
// switch, where the true tracks are still centimetres apart: not a crossing.
bool turnout_artifact(const CrossingContext& ctx, EdgeSegment a, EdgeSegment b, ingest::XY point) {
    const GraphEdge& ea = ctx.graph().edges[a.edge];
    const GraphEdge& eb = ctx.graph().edges[b.edge];
    for (const bool front_a : {true, false}) {
        for (const bool front_b : {true, false}) {
            const std::size_t va = front_a ? ea.from : ea.to;
            const std::size_t vb = front_b ? eb.from : eb.to;
            // The same end of one edge is no pair of legs.
            const bool same_end = a.edge == b.edge && front_a == front_b;
            if (va == vb && !same_end &&
                never_spread(stretch(ea, a.index, front_a, point), stretch(eb, b.index, front_b, point))) {
                return true;
            }
        }
    }
    return false;
}

void geometric_crossings(const CrossingContext& ctx, std::vector<TrackCrossing>& out) {
    for (const SegmentHit& hit : crossing_segments(ctx.segments())) {
        EdgeSegment a = ctx.segment_refs()[hit.first];
        EdgeSegment b = ctx.segment_refs()[hit.second];
        if (turnout_artifact(ctx, a, b, hit.point)) {
            continue;
        }
        const NodeSegment& sa = ctx.segments()[hit.first];
        const NodeSegment& sb = ctx.segments()[hit.second];
        TrackCrossing c;
        c.point = hit.point;
        c.s_a = ctx.s_at(a.edge, a.index, hit.point);
        c.s_b = ctx.s_at(b.edge, b.index, hit.point);
        if (std::tie(b.edge, c.s_b) < std::tie(a.edge, c.s_a)) {
            std::swap(a, b);
            std::swap(c.s_a, c.s_b);
        }
        c.edge_a = a.edge;
        c.edge_b = b.edge;
        c.angle_deg = line_angle_deg({sa.b.x - sa.a.x, sa.b.y - sa.a.y}, {sb.b.x - sb.a.x, sb.b.y - sb.a.y});
        c.grade_separated = grade_separated(ctx.track_level(a.edge, a.index), ctx.track_level(b.edge, b.index));
        out.push_back(c);
    }
}

} // namespace

std::vector<TrackCrossing> track_crossings(const CrossingContext& ctx) {
    std::vector<TrackCrossing> out;
    vertex_crossings(ctx, out);
    geometric_crossings(ctx, out);
    const auto key = [](const TrackCrossing& c) {
        return std::make_tuple(c.edge_a, c.edge_b, c.s_a, c.s_b, c.shared_node);
    };
    std::sort(out.begin(), out.end(), [&](const auto& x, const auto& y) { return key(x) < key(y); });
    // A track passing exactly through a node of another is hit from the
    // segments on both sides of that node.
    const auto same = [](const TrackCrossing& x, const TrackCrossing& y) {
        return x.edge_a == y.edge_a && x.edge_b == y.edge_b && x.shared_node == 0 && y.shared_node == 0 &&
               std::abs(x.s_a - y.s_a) < 1e-6 && std::abs(x.s_b - y.s_b) < 1e-6;
    };
    out.erase(std::unique(out.begin(), out.end(), same), out.end());
    return out;
}

} // namespace railodd::geometry::detail
