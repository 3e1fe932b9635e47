#pragma once
// The fitted edge ends that meet at each track-graph vertex, and which pairs
// of them a train passes between: the ends meet with opposite headings and
// matching curvature (G2). The map writer joins roads by these movements;
// the chain orientation makes as many of them as it can run end -> start.
#include "railodd/geometry/track_fit.hpp"

#include <cstddef>
#include <string>
#include <utility>
#include <vector>

namespace railodd::geometry {

struct Leg {
    std::size_t edge = 0;
    bool at_start = false; // the edge's alignment starts at the vertex
    Pose out;              // pose leaving the vertex along the edge
};

struct LegTolerances {
    double gap_m = 1e-3;
    double heading_rad = 1e-6;
    double curvature = 1e-6;
};

// Per vertex, the ends of the edges with written[e] (an empty `written`
// takes every edge), in edge order.
std::vector<std::vector<Leg>> legs_by_vertex(const TrackGraph& graph, const FittedNetwork& fitted,
                                             const std::vector<bool>& written = {});

// Why a train cannot pass from one leg into the other ("ends 0.2 m apart",
// "deflection 3 deg", "curvature jump ..."); empty when it can.
std::string g2_mismatch(const Leg& a, const Leg& b, const LegTolerances& tolerances = {});

// The sides of a vertex: movements always join legs leaving on opposite
// sides, so the graph they form over n legs is bipartite. Per leg, its colour
// (0 / 1; -1 where no movement touches it) and its component (the lowest leg
// of it; -1 likewise). Each component is coloured from its lowest leg, 0.
struct LegSides {
    std::vector<int> colour;
    std::vector<long> component;
};
LegSides movement_sides(std::size_t n, const std::vector<std::pair<std::size_t, std::size_t>>& movements);

} // namespace railodd::geometry
