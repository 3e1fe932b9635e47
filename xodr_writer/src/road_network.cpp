// The corridor's road graph as OpenDRIVE roads and junctions (docs/xodr.md,
// "Road lanes"):
// - one road per road-graph edge, lane sections at the way boundaries where
//   the lanes change;
// - nodes where three or more edge ends meet become junctions: the legs are
//   cut back (road_junctions.hpp) and one connecting road is built per
//   movement; two ends meeting are linked road to road;
// - edges shorter than fold_length between such nodes are folded into one
//   junction with the nodes they join (their ways are named in the
//   junction's and its connecting roads' userData);
// ids in the order edge index, then node (smallest vertex index).
#include "railodd/xodr/road_network.hpp"

#include "railodd/geometry/indexed_alignment.hpp"
#include "road_network_parts.hpp"
#include "road_junctions.hpp"
#include "road_lanes.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <map>
#include <numbers>
#include <numeric>
#include <optional>
#include <stdexcept>

namespace railodd::xodr {

namespace {

using namespace network;
using geometry::Alignment;
using geometry::Pose;
using roads::LaneLayout;

// Edges shorter than this between two junction nodes are folded into one
// junction instead of becoming a road (a zero or sub-metre road between two
// junctions cannot hold its connecting roads' ends apart).
constexpr double fold_length = 1.0;

class UnionFind {
public:
    explicit UnionFind(std::size_t n) : parent_(n) { std::iota(parent_.begin(), parent_.end(), std::size_t{0}); }
    std::size_t find(std::size_t x) {
        while (parent_[x] != x) {
            parent_[x] = parent_[parent_[x]];
            x = parent_[x];
        }
        return x;
    }
    void unite(std::size_t a, std::size_t b) {
        a = find(a);
        b = find(b);
        if (a != b) {
            parent_[std::max(a, b)] = std::min(a, b); // the root is the smallest vertex
        }
    }

private:
    std::vector<std::size_t> parent_;
};

bool same_lanes(const std::vector<Lane>& a, const std::vector<Lane>& b) {
    return std::equal(a.begin(), a.end(), b.begin(), b.end(), [](const Lane& x, const Lane& y) {
        return x.id == y.id && x.type == y.type && x.width == y.width && x.road_mark == y.road_mark;
    });
}

bool same_lanes(const LaneSection& a, const LaneSection& b) {
    return same_lanes(a.left, b.left) && same_lanes(a.right, b.right);
}

// Arc length on the alignment of each node of the edge (edge order), from the
// polyline chainage refined by a local projection; non-decreasing.
std::vector<double> node_chainage(const geometry::GraphEdge& e, const geometry::IndexedAlignment& a, bool reversed) {
    const std::size_t n = e.nodes.size();
    std::vector<double> poly(n, 0.0);
    for (std::size_t i = 1; i < n; ++i) {
        poly[i] = poly[i - 1] + std::hypot(e.nodes[i].xy.x - e.nodes[i - 1].xy.x, e.nodes[i].xy.y - e.nodes[i - 1].xy.y);
    }
    const double total = poly.back();
    const double len = a.length();
    std::vector<double> s(n, 0.0);
    for (std::size_t i = 0; i < n; ++i) {
        const double chain = reversed ? total - poly[i] : poly[i];
        const double guess = total > 0.0 ? chain * len / total : 0.0;
        const double window = 10.0 + 0.02 * len;
        s[i] = a.project_within(e.nodes[i].xy.x, e.nodes[i].xy.y, std::max(0.0, guess - window),
                                std::min(len, guess + window))
                   .s;
    }
    return s;
}

EdgeRoad make_edge_road(const geometry::TrackGraph& graph, const geometry::FittedEdge& fe,
                        const std::map<std::int64_t, const ingest::Way*>& ways) {
    const geometry::GraphEdge& e = graph.edges.at(fe.edge);
    EdgeRoad r;
    r.edge = fe.edge;
    r.full = fe.alignment;
    r.length = geometry::length(r.full);
    r.vertex = fe.reversed ? std::array{e.to, e.from} : std::array{e.from, e.to};
    r.node_ids = fe.reversed ? std::array{e.nodes.back().id, e.nodes.front().id}
                             : std::array{e.nodes.front().id, e.nodes.back().id};
    const geometry::IndexedAlignment indexed(r.full);
    const std::vector<double> chainage = node_chainage(e, indexed, fe.reversed);

    std::vector<geometry::WaySpan> spans = e.ways;
    if (fe.reversed) {
        std::reverse(spans.begin(), spans.end());
    }
    std::map<std::string, double> type_length; // road type of the longest stretch
    for (std::size_t k = 0; k < spans.size(); ++k) {
        const auto& span = spans[k];
        r.way_ids.push_back(span.way_id);
        const auto it = ways.find(span.way_id);
        static const ingest::Tags no_tags;
        const ingest::Tags& tags = it != ways.end() ? it->second->tags : no_tags;
        if (r.name.empty()) {
            r.name = ingest::tag_or(tags, "name", ingest::tag_or(tags, "ref"));
        }
        const LaneLayout layout = roads::lane_layout(tags);
        const bool along = span.reversed == fe.reversed;
        const double s0 = k == 0 ? 0.0 : chainage[fe.reversed ? span.last : span.first];
        const double s1 = k + 1 == spans.size() ? r.length : chainage[fe.reversed ? span.first : span.last];
        type_length[layout.road_type] += std::max(0.0, s1 - s0);
        LaneSection section = roads::lane_section(layout, along, s0);
        if (!r.sections.empty() && same_lanes(r.sections.back(), section)) {
            continue;
        }
        if (!r.sections.empty() && (s0 <= r.sections.back().s + 1e-6 || s0 >= r.length - 1e-6)) {
            // No room for the earlier (or this) section: the later way wins at its start.
            if (s0 >= r.length - 1e-6) {
                continue;
            }
            section.s = r.sections.back().s;
            r.sections.back() = section;
            if (r.sections.size() >= 2 && same_lanes(r.sections[r.sections.size() - 2], section)) {
                r.sections.pop_back();
            }
            continue;
        }
        r.sections.push_back(section);
    }
    double best = -1.0;
    for (const auto& [type, len] : type_length) {
        if (len > best) {
            best = len;
            r.road_type = type;
        }
    }
    return r;
}

// The sections of the full road within [cut0, length - cut1], re-based to s = 0.
std::vector<LaneSection> cut_sections(const std::vector<LaneSection>& sections, double cut0, double kept_length) {
    std::vector<LaneSection> out;
    for (const auto& sec : sections) {
        LaneSection s = sec;
        s.s = sec.s - cut0;
        if (s.s <= 1e-6) {
            s.s = 0.0;
            if (!out.empty()) {
                out.back() = s; // the section in force at the cut
                continue;
            }
        } else if (s.s >= kept_length - 1e-6) {
            break;
        }
        out.push_back(s);
    }
    // Lanes continue into the next section where it has the same id.
    for (std::size_t i = 0; i + 1 < out.size(); ++i) {
        for (auto* side : {&out[i].left, &out[i].right}) {
            for (auto& l : *side) {
                if (Lane* next = find_lane(out[i + 1], l.id)) {
                    l.link.successor = l.id;
                    next->link.predecessor = l.id;
                }
            }
        }
    }
    return out;
}



// The roads of the graph's edges, in edge order.
std::vector<EdgeRoad> edge_roads(const geometry::TrackGraph& graph, const geometry::FittedNetwork& fitted,
                                 const std::vector<ingest::Way>& ways) {
    if (fitted.edges.size() != graph.edges.size()) {
        throw std::invalid_argument("road network: " + std::to_string(fitted.edges.size()) + " fitted edges for " +
                                    std::to_string(graph.edges.size()) + " graph edges");
    }
    std::map<std::int64_t, const ingest::Way*> way_index;
    for (const auto& w : ways) {
        way_index.emplace(w.id, &w);
    }
    std::vector<EdgeRoad> rs;
    for (std::size_t e = 0; e < graph.edges.size(); ++e) {
        if (fitted.edges[e].edge != e) {
            throw std::invalid_argument("road network: fitted edges are not in graph edge order");
        }
        rs.push_back(make_edge_road(graph, fitted.edges[e], way_index));
    }
    return rs;
}

// Vertices joined by the folded edges.
UnionFind folded_components(const std::vector<EdgeRoad>& rs, std::size_t nv) {
    UnionFind uf(nv);
    for (const auto& r : rs) {
        if (r.folded) {
            uf.unite(r.vertex[0], r.vertex[1]);
        }
    }
    return uf;
}

// The unfolded edge ends at each component (by root).
std::map<std::size_t, std::vector<Leg>> legs_of(const std::vector<EdgeRoad>& rs, UnionFind& uf) {
    std::map<std::size_t, std::vector<Leg>> legs;
    for (std::size_t e = 0; e < rs.size(); ++e) {
        if (!rs[e].folded) {
            legs[uf.find(rs[e].vertex[0])].push_back({e, false});
            legs[uf.find(rs[e].vertex[1])].push_back({e, true});
        }
    }
    return legs;
}

// A cluster of short edges is folded only where it becomes a junction (two or
// more outside legs and a movement among them); otherwise its short edges
// stay roads.
void mark_folded(std::vector<EdgeRoad>& rs, std::size_t nv) {
    for (auto& r : rs) {
        r.folded = r.length < fold_length;
    }
    UnionFind uf = folded_components(rs, nv);
    auto legs = legs_of(rs, uf);
    for (auto& r : rs) {
        if (r.folded) {
            const auto& l = legs[uf.find(r.vertex[0])];
            r.folded = l.size() >= 2 && any_movement(l, rs, false);
        }
    }
}

// Two legs: linked directly where they meet smoothly; three or more with a
// movement, or folded edges: a junction.
Node::Kind node_kind(const Node& node, const std::vector<EdgeRoad>& rs) {
    const bool movement = any_movement(node.legs, rs, false);
    if (!node.folded.empty() || (node.legs.size() >= 3 && movement)) {
        return Node::Kind::junction;
    }
    if (node.legs.size() == 2) {
        // Two ends meeting at a kink (a closed way starting at a corner)
        // cannot be linked directly: a junction rounds the corner.
        const bool smooth =
            smooth_link(rs[node.legs[0].edge], node.legs[0].at_end, rs[node.legs[1].edge], node.legs[1].at_end);
        return smooth ? Node::Kind::direct : (movement ? Node::Kind::junction : Node::Kind::none);
    }
    return Node::Kind::none;
}

// Nodes: vertices joined by folded edges, by root = smallest vertex index.
std::map<std::size_t, Node> build_nodes(const std::vector<EdgeRoad>& rs, std::size_t nv) {
    UnionFind uf = folded_components(rs, nv);
    std::map<std::size_t, Node> nodes;
    for (std::size_t v = 0; v < nv; ++v) {
        nodes[uf.find(v)].vertices.push_back(v);
    }
    for (auto& [root, legs] : legs_of(rs, uf)) {
        nodes[root].legs = legs;
    }
    for (std::size_t e = 0; e < rs.size(); ++e) {
        if (rs[e].folded) {
            nodes[uf.find(rs[e].vertex[0])].folded.push_back(e);
        }
    }
    for (auto& [root, node] : nodes) {
        node.kind = node_kind(node, rs);
    }
    return nodes;
}

void cut_road(EdgeRoad& r) {
    std::vector<double> cuts;
    if (r.cut[0] > 0.0) {
        cuts.push_back(r.cut[0]);
    }
    if (r.cut[1] > 0.0) {
        cuts.push_back(r.length - r.cut[1]);
    }
    const auto pieces = geometry::split_alignment(r.full, cuts);
    r.kept = pieces[r.cut[0] > 0.0 ? 1 : 0];
    r.kept_length = geometry::length(r.kept);
    r.kept_sections = cut_sections(r.sections, r.cut[0], r.kept_length);
}

// Cut back the legs of each junction, and every unfolded road to its kept part.
void cut_back_legs(std::map<std::size_t, Node>& nodes, std::vector<EdgeRoad>& rs, const RoadNetworkOptions& options) {
    for (auto& [root, node] : nodes) {
        if (node.kind != Node::Kind::junction) {
            continue;
        }
        std::vector<roads::LegShape> shapes;
        for (const Leg& leg : node.legs) {
            const EdgeRoad& r = rs[leg.edge];
            shapes.push_back({leg_direction(r, leg.at_end), roads::half_width(end_section(r.sections, leg.at_end)),
                              r.length});
        }
        const std::vector<double> cuts = roads::cut_back(shapes, options.min_clearance_m);
        for (std::size_t i = 0; i < node.legs.size(); ++i) {
            rs[node.legs[i].edge].cut[node.legs[i].at_end ? 1 : 0] = cuts[i];
        }
    }
    for (auto& r : rs) {
        if (!r.folded) {
            cut_road(r);
        }
    }
    // A cut can pass a way boundary, so the lanes at a leg's cut end may not
    // be those at the node (a road turning into a footway just before it). A
    // junction left without a movement is no junction: its legs are restored
    // and stay unlinked. (Restoring one end changes nothing at the other.) A
    // junction holding folded edges stays one, with its legs uncut: they had
    // a movement at the node.
    for (auto& [root, node] : nodes) {
        if (node.kind != Node::Kind::junction || !movements_of(node, rs).empty()) {
            continue;
        }
        if (node.folded.empty()) {
            node.kind = Node::Kind::none;
        }
        for (const Leg& leg : node.legs) {
            rs[leg.edge].cut[leg.at_end ? 1 : 0] = 0.0;
        }
        for (const Leg& leg : node.legs) {
            cut_road(rs[leg.edge]);
        }
    }
}

} // namespace

std::vector<BuiltRoad> add_road_network(const geometry::TrackGraph& graph, const geometry::FittedNetwork& fitted,
                                        const std::vector<ingest::Way>& ways, const RoadNetworkOptions& options,
                                        IdCounter& ids, Map& map) {
    std::vector<EdgeRoad> rs = edge_roads(graph, fitted, ways);
    mark_folded(rs, graph.vertices.size());
    std::map<std::size_t, Node> nodes = build_nodes(rs, graph.vertices.size());
    cut_back_legs(nodes, rs, options);
    for (auto& r : rs) { // road ids in edge order
        if (!r.folded) {
            r.id = ids.road();
        }
    }
    // Links and junctions, in node order.
    std::vector<Junction> junctions;
    std::vector<Road> connecting;
    for (auto& [root, node] : nodes) {
        if (node.kind == Node::Kind::direct) {
            link_direct(node, rs);
        } else if (node.kind == Node::Kind::junction) {
            junctions.push_back(build_junction(node, rs, graph, ids, connecting));
        }
    }
    return emit(rs, connecting, junctions, map);
}

} // namespace railodd::xodr
