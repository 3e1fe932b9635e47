#pragma once
// Where roads cross tracks and tracks cross tracks: at nodes the ways share
// (topology) and where their polylines cross without a shared node
// (geometry), each marked at grade or grade-separated.
#include "railodd/geometry/track_graph.hpp"
#include "railodd/ingest/types.hpp"

#include <cstddef>
#include <cstdint>
#include <vector>

namespace railodd::geometry {

// A railway=level_crossing|crossing node this close to a crossing found
// geometrically is linked to it.
inline constexpr double level_crossing_link_m = 5.0;

struct RoadRailCrossing {
    std::size_t edge = 0;
    std::int64_t road_way_id = 0; // the smaller id where a road is split at the crossing node
    ingest::XY point;
    double s = 0.0;                       // polyline distance from the edge's first node
    std::int64_t shared_node = 0;         // 0: found geometrically
    std::int64_t level_crossing_node = 0; // railway=level_crossing|crossing node at that point, 0 if none
    double angle_deg = 0.0;               // between road and track, [0, 90]
    // The road's line counterclockwise from the edge's direction, [0, 180):
    // which way the road runs across the track (scenarios put road users on it).
    double road_line_deg = 90.0;
    bool grade_separated = false;
};

struct TrackCrossing {
    std::size_t edge_a = 0; // edge_a <= edge_b; equal when an edge crosses itself
    std::size_t edge_b = 0;
    ingest::XY point;
    double s_a = 0.0; // polyline distances along edge_a and edge_b
    double s_b = 0.0;
    std::int64_t shared_node = 0; // the crossing vertex's node; 0: found geometrically
    double angle_deg = 0.0;
    bool grade_separated = false;
};

struct Crossings {
    std::vector<RoadRailCrossing> road_rail; // by edge, road way id, s
    std::vector<TrackCrossing> tracks;       // by edge_a, edge_b, s_a, s_b
};

// `track_ways` are the ways the graph was built from: their bridge, tunnel and
// layer tags decide grade separation. Road and track are separated when one
// is on a bridge or in a tunnel and the other is not (or on the other kind of
// structure), or when their layers differ; two ways on one bridge deck at one
// layer (a tram on a road bridge) meet at grade. At a shared node a structure
// counts only if it continues through the node, so a bridge ending at a level
// crossing leaves it at grade.
//
// At a shared node a road crosses when it leaves on both sides of the track;
// a road that only touches the track (ends at it, or turns back) crosses only
// if the node is tagged railway=level_crossing|crossing, as where a clipped or
// unmapped road continues. Track-track crossings at shared nodes are taken at
// vertices of kind crossing whose two straightest routes cross.
//
// Throws std::invalid_argument when an edge names a way absent from track_ways.
Crossings find_crossings(const TrackGraph& tracks, const std::vector<ingest::Way>& track_ways,
                         const std::vector<ingest::Way>& roads, const std::vector<ingest::Feature>& features);

} // namespace railodd::geometry
