// Movements through the road network's nodes, and what joins the roads
// there: direct links, junctions and their connecting roads (docs/xodr.md,
// "Road lanes").
#include "road_network_parts.hpp"

#include "plan_view.hpp"
#include "road_junctions.hpp"
#include "road_lanes.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace railodd::xodr::network {

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

// Pose of a leg's road at the node, heading into the node (in) or out of it.
Pose leg_pose(const EdgeRoad& r, bool at_end, bool into_node) {
    Pose p = geometry::evaluate(r.kept, at_end ? r.kept_length : 0.0);
    if (at_end != into_node) {
        p.hdg += std::numbers::pi;
    }
    p.curvature = 0.0;
    return p;
}

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

// Two road ends linked road to road, lane by lane where the lanes continue.
void link_direct(const Node& node, std::vector<EdgeRoad>& rs) {
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
}

// The junction's OSM ids: its nodes, and the ways folded into it.
std::string junction_osm(const Node& node, const std::vector<EdgeRoad>& rs, const geometry::TrackGraph& graph) {
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
    return osm;
}

// The connecting road of one movement, with its connection in the junction.
Road connecting_road(const Movement& m, const std::vector<EdgeRoad>& rs, Junction& j, const std::string& osm,
                     IdCounter& ids) {
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
    j.connections.push_back(std::move(conn));
    return c;
}

// A junction node: its legs linked to it and one connecting road per movement.
Junction build_junction(const Node& node, std::vector<EdgeRoad>& rs, const geometry::TrackGraph& graph, IdCounter& ids,
                        std::vector<Road>& connecting) {
    Junction j;
    j.id = ids.junction();
    const std::string osm = junction_osm(node, rs, graph);
    j.user_data.push_back({"osm", osm});
    for (const Leg& leg : node.legs) {
        (leg.at_end ? rs[leg.edge].successor : rs[leg.edge].predecessor) = {ElementType::junction, j.id,
                                                                              Contact::start};
    }
    for (const Movement& m : movements_of(node, rs)) {
        connecting.push_back(connecting_road(m, rs, j, osm, ids));
    }
    return j;
}

// The edge roads, then the connecting roads and junctions, into the map.
std::vector<BuiltRoad> emit(std::vector<EdgeRoad>& rs, std::vector<Road>& connecting, std::vector<Junction>& junctions,
                            Map& map) {
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
} // namespace railodd::xodr::network
