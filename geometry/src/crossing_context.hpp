#pragma once
// What both kinds of crossing search need to know about the track graph:
// where each polyline segment came from, its way's level (bridge, tunnel,
// layer), distances along edges, and railway=level_crossing|crossing nodes.
#include "node_routes.hpp"
#include "segment_intersections.hpp"

#include "railodd/geometry/crossings.hpp"

#include <optional>
#include <vector>

namespace railodd::geometry::detail {

enum class Structure { none, bridge, tunnel };

// How a way is lifted off (or sunk below) the ground.
struct Level {
    Structure structure = Structure::none; // bridge or tunnel tag other than "no"
    std::optional<int> layer = 0;          // nothing: the ways at a node disagree
};

Level level_of(const ingest::Tags& tags);
// The level through a node from the ways on its two sides: a structure only
// if it continues through the node, a layer only if both agree.
Level common_level(const Level& a, const Level& b);
// Different structures or different layers. Two ways on one bridge deck (a
// tram on a road bridge) or in one tunnel at one layer meet at grade.
bool grade_separated(const Level& a, const Level& b);

// Segment `index` (nodes index, index + 1) of a track edge.
struct EdgeSegment {
    std::size_t edge = 0;
    std::size_t index = 0;
};

// An edge passing a node: node `index` of the edge.
struct EdgeNode {
    std::int64_t node = 0;
    std::size_t edge = 0;
    std::size_t index = 0;
};

class CrossingContext {
public:
    CrossingContext(const TrackGraph& graph, const std::vector<ingest::Way>& track_ways,
                    const std::vector<ingest::Feature>& features);

    const TrackGraph& graph() const noexcept { return graph_; }
    const std::vector<NodeSegment>& segments() const noexcept { return segments_; }
    const std::vector<EdgeSegment>& segment_refs() const noexcept { return segment_refs_; }
    // Every (node, edge, index), sorted by node id, then edge, then index.
    const std::vector<EdgeNode>& edge_nodes() const noexcept { return edge_nodes_; }

    // Level of the way covering a segment of an edge.
    Level track_level(std::size_t edge, std::size_t segment) const;
    double node_s(std::size_t edge, std::size_t index) const { return node_s_[edge][index]; }
    double s_at(std::size_t edge, std::size_t segment, ingest::XY p) const;
    // The branch of an edge at its node `index` towards node `index + step` (step = -1 or +1).
    Branch branch(std::size_t edge, std::size_t index, int step) const;

    // `node` itself when it is a railway=level_crossing|crossing node, else
    // the nearest such node within level_crossing_link_m of p, else 0.
    std::int64_t level_crossing_near(std::int64_t node, ingest::XY p) const;

private:
    struct Marker {
        double x;
        double y;
        std::int64_t id;
    };

    void index_ways(const std::vector<ingest::Way>& track_ways);

    const TrackGraph& graph_;
    std::vector<std::vector<double>> node_s_;
    std::vector<std::vector<Level>> segment_level_;
    std::vector<NodeSegment> segments_;
    std::vector<EdgeSegment> segment_refs_;
    std::vector<EdgeNode> edge_nodes_;
    std::vector<Marker> markers_; // level crossing nodes by x, then id
};

std::vector<RoadRailCrossing> road_rail_crossings(const CrossingContext& ctx, const std::vector<ingest::Way>& roads);
std::vector<TrackCrossing> track_crossings(const CrossingContext& ctx);

} // namespace railodd::geometry::detail
