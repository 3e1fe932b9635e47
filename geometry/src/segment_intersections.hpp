#pragma once
// Proper crossings between many straight segments (track and road polylines):
// bounding-box candidates, then exact predicates. CGAL stays in the .cpp.
#include "railodd/ingest/projection.hpp"

#include <cstddef>
#include <cstdint>
#include <vector>

namespace railodd::geometry::detail {

struct NodeSegment {
    ingest::XY a;
    ingest::XY b;
    std::int64_t node_a = 0; // OSM node ids of the ends
    std::int64_t node_b = 0;
};

struct SegmentHit {
    std::size_t first = 0;  // index into the first (or only) set
    std::size_t second = 0; // index into the second set (or the same set, first < second)
    ingest::XY point;
};

// Segments that meet at a common node are left out: where two ways share a
// node is topology, answered from node ids, not geometry. Collinear overlaps
// are left out too: running along each other is not crossing. Sorted by
// (first, second).
std::vector<SegmentHit> crossing_segments(const std::vector<NodeSegment>& first,
                                          const std::vector<NodeSegment>& second);

// Pairs within one set, each once with first < second.
std::vector<SegmentHit> crossing_segments(const std::vector<NodeSegment>& set);

} // namespace railodd::geometry::detail
