#pragma once
// The track graph: OSM track ways merged into continuous edges across way
// splits (tag changes never break geometry) and split only at topological
// vertices: switches, ends, crossings of tracks and joins.
#include "railodd/ingest/types.hpp"

#include <cstddef>
#include <cstdint>
#include <vector>

namespace railodd::geometry {

enum class VertexKind {
    end,      // one incident edge: buffer stop, clipped end, end of the extract
    switch_,  // three incident edge ends, or railway=switch
    crossing, // four incident edge ends (diamond crossing sharing a node), or railway=railway_crossing
    join,     // any other degree (5+), or a degree-2 node tagged as a switch with one branch unmapped
};

const char* to_string(VertexKind kind);

struct GraphVertex {
    std::int64_t node_id = 0;
    ingest::XY xy;
    VertexKind kind = VertexKind::end;
    std::vector<std::size_t> edges; // incident edges, ascending; an edge appears twice if it is a loop
};

// Which OSM way (or OGR feature) a stretch of an edge came from: nodes
// [first, last] of the edge, both inclusive, so consecutive spans share a node.
struct WaySpan {
    std::int64_t way_id = 0;
    std::size_t first = 0;
    std::size_t last = 0;
    bool reversed = false; // the way runs against the edge's direction
};

struct GraphEdge {
    std::size_t id = 0;
    std::vector<ingest::NodeRef> nodes; // polyline in edge direction, node ids kept
    std::vector<WaySpan> ways;          // in edge order, covering every segment exactly once
    std::size_t from = 0;               // vertex index at nodes.front()
    std::size_t to = 0;                 // vertex index at nodes.back()
};

struct TrackGraph {
    std::vector<GraphVertex> vertices;
    std::vector<GraphEdge> edges;
};

// Deterministic: vertex and edge order depend only on node and way ids.
// Every part of every input way appears in exactly one edge.
TrackGraph build_track_graph(const std::vector<ingest::Way>& ways, const std::vector<ingest::Feature>& features);

} // namespace railodd::geometry
