#pragma once
// Internal to the road network: road_network.cpp builds one road per graph
// edge and the nodes where they meet; road_network_links.cpp the movements
// through the nodes, the direct links, the junctions with their connecting
// roads, and the roads into the map.
#include "railodd/xodr/road_network.hpp"

#include <array>
#include <cstdint>
#include <string>
#include <vector>

namespace railodd::xodr::network {

using geometry::Alignment;
using geometry::Pose;

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

struct Movement {
    Leg in, out;
    std::vector<int> in_lanes, out_lanes; // paired, innermost first
    Pose from, to;
};

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
const LaneSection& end_section(const std::vector<LaneSection>& sections, bool at_end);

// Whether driving lanes enter through one leg and leave through another
// (kept: on the cut roads, else on the full ones).
bool any_movement(const std::vector<Leg>& legs, const std::vector<EdgeRoad>& roads_, bool kept);

// Every buildable movement through a junction node, on the cut roads.
std::vector<Movement> movements_of(const Node& node, const std::vector<EdgeRoad>& rs);

// Direction from the node along a leg.
double leg_direction(const EdgeRoad& r, bool at_end);

// Whether two road ends at one node continue each other.
bool smooth_link(const EdgeRoad& a, bool a_end, const EdgeRoad& b, bool b_end);

std::string join_ids(const std::vector<std::int64_t>& ids, const char* prefix);

// Two road ends linked road to road, lane by lane where the lanes continue.
void link_direct(const Node& node, std::vector<EdgeRoad>& rs);

// A junction node: its legs linked to it and one connecting road per movement
// (appended to connecting).
Junction build_junction(const Node& node, std::vector<EdgeRoad>& rs, const geometry::TrackGraph& graph, IdCounter& ids,
                        std::vector<Road>& connecting);

// The edge roads, then the connecting roads and junctions, into the map.
std::vector<BuiltRoad> emit(std::vector<EdgeRoad>& rs, std::vector<Road>& connecting, std::vector<Junction>& junctions,
                            Map& map);

} // namespace railodd::xodr::network
