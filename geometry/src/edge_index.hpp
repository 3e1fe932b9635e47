#pragma once
// Which track edges pass near a point: an AABB tree over every polyline
// segment of the graph (CGAL, kept behind a pointer to stay out of headers).
#include "railodd/geometry/track_graph.hpp"

#include <memory>
#include <vector>

namespace railodd::geometry::detail {

class EdgeIndex {
public:
    explicit EdgeIndex(const TrackGraph& graph);
    ~EdgeIndex();
    EdgeIndex(const EdgeIndex&) = delete;
    EdgeIndex& operator=(const EdgeIndex&) = delete;

    struct Near {
        double distance = 0.0;          // to the nearest polyline; infinite without edges
        std::vector<std::size_t> edges; // ascending
    };

    // The nearest polyline's distance and every edge with a segment within
    // that distance plus `slack` of p (in the square of that half-width: a
    // superset, to be decided by exact projection onto the alignments).
    Near near(ingest::XY p, double slack) const;

private:
    struct Impl;
    std::unique_ptr<Impl> impl_;
};

} // namespace railodd::geometry::detail
