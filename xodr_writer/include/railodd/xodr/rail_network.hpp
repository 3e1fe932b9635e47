#pragma once
// The track graph as OpenDRIVE roads: one road per graph edge (its fitted
// centreline, profile and cant), joined where tracks meet. A vertex where
// two edges meet links them directly; at a switch or crossing the legs on one
// side are cut back and their first metres become the connecting roads of a
// junction, so every movement a train can make (straight on, into the
// branch, over the crossing) is a junction connection with position,
// heading and curvature continuous. Switches also get <railroad><switch>.
#include "railodd/geometry/cant.hpp"
#include "railodd/geometry/indexed_alignment.hpp"
#include "railodd/geometry/track_fit.hpp"
#include "railodd/geometry/vertical_profile.hpp"
#include "railodd/ingest/types.hpp"
#include "railodd/xodr/ids.hpp"
#include "railodd/xodr/model.hpp"

#include <cstddef>
#include <cstdint>
#include <string>
#include <utility>
#include <vector>

namespace railodd::xodr {

struct RailInput {
    const geometry::TrackGraph& graph;
    const geometry::FittedNetwork& fitted;
    const std::vector<geometry::VerticalProfile>& profiles;          // per edge, or empty: flat
    const std::vector<std::vector<geometry::CantStretch>>& cants;    // per edge, or empty: none
    const std::vector<ingest::Way>& ways;                             // the track ways of the graph
    const std::vector<geometry::IndexedAlignment>* indexed = nullptr; // fitted indexed at 2 m, if made already
};

struct RailOptions {
    double connecting_length_m = 20.0; // of a junction's connecting roads (at most a third of the edge)
    double rail_spacing_m = 1.500;     // for superelevation from cant
};

// A stretch [s0, s1] of a graph edge's alignment written as one road.
struct RoadPiece {
    std::size_t road = 0; // index into Map::roads
    double s0 = 0.0;
    double s1 = 0.0;
};

struct RoadLocation {
    std::size_t road = 0; // index into Map::roads
    double s = 0.0;       // along that road
};

struct UnwrittenEdge {
    std::size_t edge = 0;
    std::string reason;
};

struct UnlinkedEnd {
    std::size_t vertex = 0;
    std::size_t edge = 0;
    std::string reason;
};

struct RailNetwork {
    std::vector<std::vector<RoadPiece>> pieces; // per graph edge, ascending s0; empty if not written
    // (edge, piece): the further connecting roads of a junction leg with
    // several movements, over a stretch `pieces` already maps to a road.
    std::vector<std::pair<std::size_t, RoadPiece>> copies;
    std::vector<UnwrittenEdge> unwritten;
    std::vector<UnlinkedEnd> unlinked;          // edge ends at a vertex with other tracks but no movement
    std::size_t direct_links = 0;
    std::size_t junctions = 0;
    std::size_t connections = 0;
    std::size_t switches = 0;

    // The road and road s of a point at s along a graph edge's alignment.
    RoadLocation locate(std::size_t edge, double s) const;
};

RailNetwork add_rail_network(const RailInput& input, const RailOptions& options, IdCounter& ids, Map& map);

} // namespace railodd::xodr
