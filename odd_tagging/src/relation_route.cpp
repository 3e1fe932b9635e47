// relation_route() (route.hpp): the route along an OSM route relation. Each
// member way becomes the stretches of graph edges it was merged into, in the
// way's node order; ways are then run in member order, each turned to
// continue where the previous one ended.
#include "railodd/odd/route.hpp"

#include "route_network.hpp"

#include "railodd/geometry/indexed_alignment.hpp"
#include "railodd/util/errors.hpp"

#include <algorithm>
#include <cmath>
#include <map>
#include <memory>
#include <optional>
#include <set>
#include <string>

namespace railodd::odd {

using namespace route_detail;

namespace {

// A member way on the graph: the stretches of edges it runs along, in its node order.
struct MemberWay {
    std::int64_t id = 0;
    std::vector<RoutePiece> pieces; // s_from at the way's start side
    std::int64_t first_node = 0;    // OSM node ids at the way's two ends
    std::int64_t last_node = 0;
};

class WayIndex {
public:
    WayIndex(const geometry::TrackGraph& graph, const geometry::FittedNetwork& fitted,
             const std::vector<ingest::Way>& tracks)
        : graph_(graph), fitted_(fitted) {
        for (const auto& w : tracks) {
            way_nodes_[w.id] = &w;
        }
        for (std::size_t e = 0; e < graph.edges.size(); ++e) {
            for (std::size_t k = 0; k < graph.edges[e].ways.size(); ++k) {
                spans_[graph.edges[e].ways[k].way_id].push_back({e, k});
            }
        }
    }

    // The way's stretches of edges in its node order; nothing if it is not on the graph.
    std::optional<MemberWay> member(std::int64_t id) {
        const auto it = spans_.find(id);
        const auto w = way_nodes_.find(id);
        if (it == spans_.end() || w == way_nodes_.end()) {
            return std::nullopt;
        }
        struct Stretch {
            std::size_t position; // of its first node (in way order) along the way
            RoutePiece piece;
            std::int64_t start, end;
        };
        std::vector<Stretch> stretches;
        for (const auto& [e, k] : it->second) {
            const auto& edge = graph_.edges[e];
            const geometry::WaySpan& span = edge.ways[k];
            const std::size_t a = span.reversed ? span.last : span.first, b = span.reversed ? span.first : span.last;
            const double sa = s_at(e, a), sb = s_at(e, b);
            stretches.push_back({position(*w->second, edge.nodes[a].id), {e, sb < sa, sa, sb, 0.0},
                                 edge.nodes[a].id, edge.nodes[b].id});
        }
        std::stable_sort(stretches.begin(), stretches.end(),
                         [](const Stretch& x, const Stretch& y) { return x.position < y.position; });
        MemberWay m{id, {}, stretches.front().start, stretches.back().end};
        for (const auto& s : stretches) {
            m.pieces.push_back(s.piece);
        }
        return m;
    }

    double length(std::size_t edge) { return alignment(edge).length(); }
    ingest::XY point(TrackPoint p) {
        const auto pose = alignment(p.edge).evaluate(p.s);
        return {pose.x, pose.y};
    }

private:
    const geometry::IndexedAlignment& alignment(std::size_t e) {
        auto& slot = alignments_[e];
        if (!slot) {
            slot = std::make_unique<geometry::IndexedAlignment>(fitted_.edges[e].alignment, 2.0);
        }
        return *slot;
    }

    // s of an edge node along the alignment; the edge's end nodes are its ends exactly.
    double s_at(std::size_t e, std::size_t node) {
        const auto& edge = graph_.edges[e];
        const bool reversed = fitted_.edges[e].reversed;
        if (node == 0 || node + 1 == edge.nodes.size()) {
            return (node == 0) != reversed ? 0.0 : alignment(e).length();
        }
        const auto& xy = edge.nodes[node].xy;
        return alignment(e).project(xy.x, xy.y).s;
    }

    static std::size_t position(const ingest::Way& way, std::int64_t node) {
        std::size_t i = 0;
        for (const auto& part : way.parts) {
            for (const auto& n : part) {
                if (n.id == node) {
                    return i;
                }
                ++i;
            }
        }
        return i;
    }

    const geometry::TrackGraph& graph_;
    const geometry::FittedNetwork& fitted_;
    std::map<std::int64_t, const ingest::Way*> way_nodes_;
    std::map<std::int64_t, std::vector<std::pair<std::size_t, std::size_t>>> spans_; // way -> (edge, span)
    std::map<std::size_t, std::unique_ptr<geometry::IndexedAlignment>> alignments_;
};

// The way turned to run in travel direction.
std::vector<RoutePiece> in_travel_order(const MemberWay& m, bool forward) {
    std::vector<RoutePiece> out = m.pieces;
    if (!forward) {
        std::reverse(out.begin(), out.end());
        for (auto& p : out) {
            std::swap(p.s_from, p.s_to);
            p.reversed = p.s_to < p.s_from;
        }
    }
    return out;
}

// Runs the way forward when its last node meets the next way, backward when its first does.
bool forward_towards(const MemberWay& m, const MemberWay* next) {
    if (!next) {
        return true;
    }
    const bool last_meets = m.last_node == next->first_node || m.last_node == next->last_node;
    const bool first_meets = m.first_node == next->first_node || m.first_node == next->last_node;
    return last_meets || !first_meets;
}

double chainage_of(const std::vector<RoutePiece>& pieces) {
    double c = 0.0;
    for (const auto& p : pieces) {
        c += std::abs(p.s_to - p.s_from);
    }
    return c;
}

// Pieces that continue one another on the same edge become one.
std::vector<RoutePiece> merged(const std::vector<RoutePiece>& pieces) {
    std::vector<RoutePiece> out;
    for (const auto& p : pieces) {
        if (!out.empty() && out.back().edge == p.edge && std::abs(out.back().s_to - p.s_from) < 1e-6 &&
            out.back().reversed == p.reversed) {
            out.back().s_to = p.s_to;
        } else {
            out.push_back(p);
        }
    }
    return out;
}

std::string tag(const ingest::Tags& tags, const char* key) { return ingest::tag_or(tags, key); }

// Joins the route's end to the next member's entry by the shortest path over
// the selected tracks if there is one; the gap is listed either way.
void bridge(const Network& n, WayIndex& index, Path& path, const RoutePiece& entry, std::int64_t after,
            std::int64_t before, Route& route) {
    const RoutePiece& last = path.pieces.back();
    const TrackPoint from{last.edge, last.s_to}, to{entry.edge, entry.s_from};
    const ingest::XY a = index.point(from), b = index.point(to);
    RouteGap gap{chainage_of(path.pieces), after, before, std::hypot(b.x - a.x, b.y - a.y), false, 0.0};
    Path joint = shortest_path(n, from, to);
    if (joint.length < infinity) {
        gap.bridged = true;
        gap.bridge_length_m = joint.length;
        path.pieces.insert(path.pieces.end(), joint.pieces.begin(), joint.pieces.end());
    }
    route.gaps.push_back(gap);
}

} // namespace

Route relation_route(const geometry::TrackGraph& graph, const geometry::FittedNetwork& fitted,
                     const std::vector<ingest::Way>& tracks, const ingest::RouteRelation& relation,
                     const std::string& file) {
    WayIndex index(graph, fitted, tracks);
    std::vector<MemberWay> members;
    for (const std::int64_t id : relation.ways) {
        if (auto m = index.member(id); m && (members.empty() || members.back().id != id)) {
            members.push_back(std::move(*m));
        }
    }
    const std::string rel = "relation " + std::to_string(relation.id);
    if (members.empty()) {
        throw InputError(file, rel + " has no railway track member in the selection (" +
                                   std::to_string(relation.ways.size()) + " member way(s))");
    }
    Route route;
    route.relation = relation.id;
    route.name = tag(relation.tags, "name");
    route.from = tag(relation.tags, "from");
    route.to = tag(relation.tags, "to");
    route.description = rel + (route.name.empty() ? "" : ": " + route.name);
    route.member_ways = relation.ways.size();
    const Network network = build_network(graph, fitted);
    Path path;
    std::int64_t at_node = 0; // the OSM node the route has reached; 0 before the first member
    std::set<std::int64_t> on_route;
    for (std::size_t i = 0; i < members.size(); ++i) {
        const MemberWay& m = members[i];
        bool forward = at_node == m.first_node;
        if (at_node == 0 || (at_node != m.first_node && at_node != m.last_node)) {
            forward = forward_towards(m, i + 1 < members.size() ? &members[i + 1] : nullptr);
        }
        const std::vector<RoutePiece> run = in_travel_order(m, forward);
        if (at_node != 0 && at_node != m.first_node && at_node != m.last_node) {
            bridge(network, index, path, run.front(), members[i - 1].id, m.id, route);
        }
        path.pieces.insert(path.pieces.end(), run.begin(), run.end());
        at_node = forward ? m.last_node : m.first_node;
        on_route.insert(m.id);
    }
    path.pieces = merged(path.pieces);
    finish(path);
    route.length_m = chainage_of(path.pieces);
    route.pieces = std::move(path.pieces);
    route.ways_on_route = on_route.size();
    route.osm_ways = route_way_ids(graph, route.pieces);
    return route;
}

} // namespace railodd::odd
