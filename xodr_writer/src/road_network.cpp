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
#include "plan_view.hpp"
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

using geometry::Alignment;
using geometry::Pose;
using roads::LaneLayout;

// Edges shorter than this between two junction nodes are folded into one
// junction instead of becoming a road (a zero or sub-metre road between two
// junctions cannot hold its connecting roads' ends apart).
constexpr double fold_length = 1.0;

// Two road ends are linked directly only within these; otherwise a junction
// (or, without a movement between them, no link) joins them.
constexpr double link_gap_m = 1e-6;
constexpr double link_heading_rad = 1e-6;

// Movements whose legs end at the same point (duplicate ways between the same
// nodes, cut back alike) would need a connecting road of no length: not built.
constexpr double min_connection_m = 0.01;

struct EdgeRoad {
    std::size_t edge = 0;
    Alignment full;
    double length = 0.0;
    std::array<std::size_t, 2> vertex{}; // graph vertex at the alignment's start, end
    std::vector<std::int64_t> way_ids;   // in road order
    std::array<std::int64_t, 2> node_ids{};
    std::vector<LaneSection> sections;   // on the full alignment
    std::string road_type = "town";
    std::string name;
    bool folded = false;
    std::array<double, 2> cut{};         // cut back at the start, end
    std::string id;
    Alignment kept;
    double kept_length = 0.0;
    std::vector<LaneSection> kept_sections;
    RoadLink predecessor, successor;
};

// One edge end at a node; at_end: the road's end (else its start) touches it.
struct Leg {
    std::size_t edge = 0;
    bool at_end = false;
};

struct Node {
    std::vector<std::size_t> vertices; // ascending
    std::vector<std::size_t> folded;   // edges folded into it, ascending
    std::vector<Leg> legs;             // by edge, start before end
    enum class Kind { none, direct, junction } kind = Kind::none;
};

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

template <class Section> // LaneSection or const LaneSection
auto* find_lane(Section& s, int id) {
    auto& side = id > 0 ? s.left : s.right;
    for (auto& l : side) {
        if (l.id == id) {
            return &l;
        }
    }
    return static_cast<decltype(&side[0])>(nullptr);
}

// The section touching a leg's node.
const LaneSection& end_section(const std::vector<LaneSection>& sections, bool at_end) {
    return at_end ? sections.back() : sections.front();
}

// Driving lanes entering (in) and leaving (out) the node through a leg, innermost first.
std::vector<int> lanes_in(const LaneSection& s, bool at_end) {
    return roads::driving_lanes(at_end ? s.right : s.left);
}
std::vector<int> lanes_out(const LaneSection& s, bool at_end) {
    return roads::driving_lanes(at_end ? s.left : s.right);
}

bool any_movement(const std::vector<Leg>& legs, const std::vector<EdgeRoad>& roads_, bool kept) {
    for (std::size_t i = 0; i < legs.size(); ++i) {
        const auto& si = end_section(kept ? roads_[legs[i].edge].kept_sections : roads_[legs[i].edge].sections,
                                     legs[i].at_end);
        if (lanes_in(si, legs[i].at_end).empty()) {
            continue;
        }
        for (std::size_t j = 0; j < legs.size(); ++j) {
            const auto& sj = end_section(kept ? roads_[legs[j].edge].kept_sections : roads_[legs[j].edge].sections,
                                         legs[j].at_end);
            if (j != i && !lanes_out(sj, legs[j].at_end).empty()) {
                return true;
            }
        }
    }
    return false;
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


// Pose of a leg's road at the node, heading into the node (in) or out of it.
Pose leg_pose(const EdgeRoad& r, bool at_end, bool into_node) {
    Pose p = geometry::evaluate(r.kept, at_end ? r.kept_length : 0.0);
    if (at_end != into_node) {
        p.hdg += std::numbers::pi;
    }
    p.curvature = 0.0;
    return p;
}

struct Movement {
    Leg in, out;
    std::vector<int> in_lanes, out_lanes; // paired, innermost first
    Pose from, to;
};

// Every buildable movement through a junction node, on the cut roads: ordered
// pairs of distinct legs (no U-turns) with driving lanes entering through the
// first and leaving through the second, whose cut ends are apart.
std::vector<Movement> movements_of(const Node& node, const std::vector<EdgeRoad>& rs) {
    std::vector<Movement> out;
    for (const Leg& in : node.legs) {
        const EdgeRoad& rin = rs[in.edge];
        const std::vector<int> in_lanes = lanes_in(end_section(rin.kept_sections, in.at_end), in.at_end);
        if (in_lanes.empty()) {
            continue;
        }
        for (const Leg& to : node.legs) {
            if (to.edge == in.edge && to.at_end == in.at_end) {
                continue;
            }
            const EdgeRoad& rout = rs[to.edge];
            std::vector<int> out_lanes = lanes_out(end_section(rout.kept_sections, to.at_end), to.at_end);
            const std::size_t n = std::min(in_lanes.size(), out_lanes.size());
            if (n == 0) {
                continue;
            }
            Movement m{in, to, {in_lanes.begin(), in_lanes.begin() + static_cast<std::ptrdiff_t>(n)},
                       {out_lanes.begin(), out_lanes.begin() + static_cast<std::ptrdiff_t>(n)},
                       leg_pose(rin, in.at_end, true), leg_pose(rout, to.at_end, false)};
            if (std::hypot(m.to.x - m.from.x, m.to.y - m.from.y) < min_connection_m) {
                continue;
            }
            out.push_back(std::move(m));
        }
    }
    return out;
}

// Direction from the node along a leg: the chord to a point a little way
// along (the first segment of a mapped way is often too short to trust).
double leg_direction(const EdgeRoad& r, bool at_end) {
    const double d = std::min(15.0, 0.5 * r.length);
    const Pose node = geometry::evaluate(r.full, at_end ? r.length : 0.0);
    const Pose far = geometry::evaluate(r.full, at_end ? r.length - d : d);
    if (std::hypot(far.x - node.x, far.y - node.y) < 1e-9) {
        return at_end ? node.hdg + std::numbers::pi : node.hdg;
    }
    return std::atan2(far.y - node.y, far.x - node.x);
}

// Whether two road ends at one node continue each other (same point, same
// heading through the node).
bool smooth_link(const EdgeRoad& a, bool a_end, const EdgeRoad& b, bool b_end) {
    const Pose pa = geometry::evaluate(a.full, a_end ? a.length : 0.0);
    const Pose pb = geometry::evaluate(b.full, b_end ? b.length : 0.0);
    const double turn = (a_end != b_end ? 0.0 : std::numbers::pi);
    return std::hypot(pa.x - pb.x, pa.y - pb.y) <= link_gap_m &&
           std::abs(std::remainder(pa.hdg - pb.hdg - turn, 2.0 * std::numbers::pi)) <= link_heading_rad;
}

std::string join_ids(const std::vector<std::int64_t>& ids, const char* prefix) {
    std::string out;
    for (const auto id : ids) {
        out += (out.empty() ? "" : ",") + std::string{prefix} + std::to_string(id);
    }
    return out;
}

} // namespace

std::vector<BuiltRoad> add_road_network(const geometry::TrackGraph& graph, const geometry::FittedNetwork& fitted,
                                        const std::vector<ingest::Way>& ways, const RoadNetworkOptions& options,
                                        IdCounter& ids, Map& map) {
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

    // Nodes: vertices joined by folded edges. A cluster of short edges is
    // folded only where it becomes a junction (two or more outside legs and a
    // movement among them); otherwise its short edges stay roads.
    const std::size_t nv = graph.vertices.size();
    const auto legs_of = [&](UnionFind& uf) {
        std::map<std::size_t, std::vector<Leg>> legs;
        for (std::size_t e = 0; e < rs.size(); ++e) {
            if (!rs[e].folded) {
                legs[uf.find(rs[e].vertex[0])].push_back({e, false});
                legs[uf.find(rs[e].vertex[1])].push_back({e, true});
            }
        }
        return legs;
    };
    {
        for (auto& r : rs) {
            r.folded = r.length < fold_length;
        }
        UnionFind uf(nv);
        for (const auto& r : rs) {
            if (r.folded) {
                uf.unite(r.vertex[0], r.vertex[1]);
            }
        }
        auto legs = legs_of(uf);
        for (auto& r : rs) {
            if (r.folded) {
                const auto& l = legs[uf.find(r.vertex[0])];
                r.folded = l.size() >= 2 && any_movement(l, rs, false);
            }
        }
    }
    UnionFind uf(nv);
    for (const auto& r : rs) {
        if (r.folded) {
            uf.unite(r.vertex[0], r.vertex[1]);
        }
    }
    std::map<std::size_t, Node> nodes; // by root = smallest vertex index
    for (std::size_t v = 0; v < nv; ++v) {
        nodes[uf.find(v)].vertices.push_back(v);
    }
    for (auto& [root, legs] : legs_of(uf)) {
        nodes[root].legs = legs;
    }
    for (std::size_t e = 0; e < rs.size(); ++e) {
        if (rs[e].folded) {
            nodes[uf.find(rs[e].vertex[0])].folded.push_back(e);
        }
    }
    for (auto& [root, node] : nodes) {
        const bool movement = any_movement(node.legs, rs, false);
        if (!node.folded.empty() || (node.legs.size() >= 3 && movement)) {
            node.kind = Node::Kind::junction;
        } else if (node.legs.size() == 2) {
            // Two ends meeting at a kink (a closed way starting at a corner)
            // cannot be linked directly: a junction rounds the corner.
            const bool smooth = smooth_link(rs[node.legs[0].edge], node.legs[0].at_end, rs[node.legs[1].edge],
                                            node.legs[1].at_end);
            node.kind = smooth ? Node::Kind::direct : (movement ? Node::Kind::junction : Node::Kind::none);
        }
    }

    // Cut back the legs of each junction.
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

    const auto cut_road = [](EdgeRoad& r) {
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
    };
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
    // Road ids, in edge order.
    for (auto& r : rs) {
        if (!r.folded) {
            r.id = ids.road();
        }
    }

    // Links and junctions, in node order.
    std::vector<Junction> junctions;
    std::vector<Road> connecting;
    for (auto& [root, node] : nodes) {
        if (node.kind == Node::Kind::direct) {
            const std::array<Leg, 2> leg{node.legs[0], node.legs[1]};
            for (int k = 0; k < 2; ++k) {
                const Leg& a = leg[k];
                const Leg& b = leg[1 - k];
                EdgeRoad& ra = rs[a.edge];
                EdgeRoad& rb = rs[b.edge];
                RoadLink link{ElementType::road, rb.id, b.at_end ? Contact::end : Contact::start};
                (a.at_end ? ra.successor : ra.predecessor) = link;
                LaneSection& sa = a.at_end ? ra.kept_sections.back() : ra.kept_sections.front();
                LaneSection& sb = b.at_end ? rb.kept_sections.back() : rb.kept_sections.front();
                const bool same_sense = a.at_end != b.at_end;
                for (auto* side : {&sa.left, &sa.right}) {
                    for (auto& l : *side) {
                        const int target = same_sense ? l.id : -l.id;
                        const Lane* other = find_lane(sb, target);
                        if (other && other->type == l.type) {
                            (a.at_end ? l.link.successor : l.link.predecessor) = target;
                        }
                    }
                }
            }
            continue;
        }
        if (node.kind != Node::Kind::junction) {
            continue;
        }
        Junction j;
        j.id = ids.junction();
        std::vector<std::int64_t> node_ids;
        for (const std::size_t v : node.vertices) {
            node_ids.push_back(graph.vertices[v].node_id);
        }
        std::vector<std::int64_t> folded_ways;
        for (const std::size_t e : node.folded) {
            folded_ways.insert(folded_ways.end(), rs[e].way_ids.begin(), rs[e].way_ids.end());
        }
        std::string osm = join_ids(node_ids, "node:");
        if (!folded_ways.empty()) {
            osm += "," + join_ids(folded_ways, "way:");
        }
        j.user_data.push_back({"osm", osm});
        for (const Leg& leg : node.legs) {
            (leg.at_end ? rs[leg.edge].successor : rs[leg.edge].predecessor) = {ElementType::junction, j.id,
                                                                                  Contact::start};
        }
        for (const Movement& m : movements_of(node, rs)) {
            const EdgeRoad& rin = rs[m.in.edge];
            const EdgeRoad& rout = rs[m.out.edge];
            Road c;
            c.id = ids.road();
            c.junction = j.id;
            c.rule = "RHT";
            c.type = rin.road_type;
            c.predecessor = {ElementType::road, rin.id, m.in.at_end ? Contact::end : Contact::start};
            c.successor = {ElementType::road, rout.id, m.out.at_end ? Contact::end : Contact::start};
            c.plan_view.push_back(roads::connecting_geometry(m.from, m.to));
            const LaneSection& in_sec = end_section(rin.kept_sections, m.in.at_end);
            Connection conn;
            conn.id = ids.other();
            conn.incoming_road = rin.id;
            conn.connecting_road = c.id;
            conn.contact = Contact::start;
            LaneSection sec;
            for (std::size_t q = 0; q < m.in_lanes.size(); ++q) {
                Lane l;
                l.id = -static_cast<int>(q + 1);
                l.type = "driving";
                l.width = find_lane(in_sec, m.in_lanes[q])->width;
                l.link.predecessor = m.in_lanes[q];
                l.link.successor = m.out_lanes[q];
                sec.right.push_back(l);
                conn.lane_links.push_back({m.in_lanes[q], l.id});
            }
            c.lane_sections.push_back(sec);
            c.user_data.push_back({"osm", osm});
            connecting.push_back(std::move(c));
            j.connections.push_back(std::move(conn));
        }
        junctions.push_back(std::move(j));
    }

    std::vector<BuiltRoad> built;
    for (auto& r : rs) {
        if (r.folded) {
            continue;
        }
        Road road;
        road.id = r.id;
        road.name = r.name;
        road.rule = "RHT";
        road.type = r.road_type;
        road.predecessor = r.predecessor;
        road.successor = r.successor;
        road.plan_view = plan_view_of(r.kept, false);
        road.lane_sections = r.kept_sections;
        road.user_data.push_back({"osm", join_ids(r.way_ids, "way:")});
        road.user_data.push_back({"osm_edge_nodes", std::to_string(r.node_ids[0]) + "," + std::to_string(r.node_ids[1])});
        map.roads.push_back(std::move(road));
        built.push_back({r.id, r.edge, r.kept, r.way_ids});
    }
    for (auto& c : connecting) {
        map.roads.push_back(std::move(c));
    }
    for (auto& j : junctions) {
        map.junctions.push_back(std::move(j));
    }
    return built;
}

} // namespace railodd::xodr
