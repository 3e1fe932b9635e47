#pragma once
// The movements a train can make over the fitted track graph, and the
// shortest path between two points of it (docs/odd.md "Routes"): shared by
// routes between stations and routes along a relation.
#include "railodd/geometry/alignment.hpp"
#include "railodd/geometry/track_fit.hpp"
#include "railodd/geometry/track_graph.hpp"
#include "railodd/odd/route.hpp"

#include <cstddef>
#include <limits>
#include <numbers>
#include <string>
#include <vector>

namespace railodd::odd::route_detail {

inline constexpr double infinity = std::numeric_limits<double>::infinity();

// An end of an edge's alignment, as an index: 2 * edge (s = 0) or
// 2 * edge + 1 (s = length). The route search runs over these ends.
inline std::size_t end_index(std::size_t edge, bool at_end) { return 2 * edge + (at_end ? 1 : 0); }
inline std::size_t edge_of(std::size_t end) { return end / 2; }
inline bool at_end(std::size_t end) { return end % 2 == 1; }

struct Network {
    const geometry::TrackGraph& graph;
    const geometry::FittedNetwork& fitted;
    std::vector<double> lengths;                 // per edge, of its alignment
    std::vector<std::vector<std::size_t>> moves; // per end: the ends a train may continue into at its vertex

    double s_of(std::size_t end) const { return at_end(end) ? lengths[edge_of(end)] : 0.0; }

    std::size_t vertex_of(std::size_t end) const {
        const auto& e = graph.edges[edge_of(end)];
        // An alignment fitted against the node order starts at the edge's `to`.
        return at_end(end) != fitted.edges[edge_of(end)].reversed ? e.to : e.from;
    }

    // Heading of the track leaving the vertex through this end.
    double outgoing_heading(std::size_t end) const {
        const auto& a = fitted.edges[edge_of(end)].alignment;
        const geometry::Pose p = geometry::evaluate(a, s_of(end));
        return at_end(end) ? p.hdg + std::numbers::pi : p.hdg;
    }

    // A chain item is left through its alignment end when chain and alignment
    // run the same way along the graph edge.
    std::size_t exit_end(const geometry::ChainItem& item) const {
        return end_index(item.edge, item.reversed == fitted.edges[item.edge].reversed);
    }
    std::size_t entry_end(const geometry::ChainItem& item) const { return exit_end(item) ^ 1U; }

    void link(std::size_t a, std::size_t b) {
        moves[a].push_back(b);
        moves[b].push_back(a);
    }
};

Network build_network(const geometry::TrackGraph& graph, const geometry::FittedNetwork& fitted);

// A point of the track: s along an edge's alignment.
struct TrackPoint {
    std::size_t edge = 0;
    double s = 0.0;
};

struct Path {
    double length = infinity;
    std::vector<RoutePiece> pieces;
};

void add_piece(Path& p, std::size_t edge, double s_from, double s_to);

// Zero-length pieces (a station on a vertex) dropped, chainage accumulated.
void finish(Path& p);

// Dijkstra over alignment ends from a to b; length infinity when no path joins them.
Path shortest_path(const Network& n, TrackPoint a, TrackPoint b);

// "way:ID" of the ways behind the pieces' edges, ascending, for Route::osm_ways.
std::vector<std::string> route_way_ids(const geometry::TrackGraph& graph, const std::vector<RoutePiece>& pieces);

} // namespace railodd::odd::route_detail
