// Segment crossings with CGAL: box_intersection_d proposes pairs whose boxes
// overlap, exact predicates decide, and only the point is constructed inexactly.
#include "segment_intersections.hpp"

#include <CGAL/Bbox_2.h>
#include <CGAL/Box_intersection_d/Box_with_info_d.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/box_intersection_d.h>
#include <CGAL/intersections.h>

#include <algorithm>
#include <tuple>

namespace railodd::geometry::detail {

namespace {

using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using Point = Kernel::Point_2;
using Segment = Kernel::Segment_2;
using Box = CGAL::Box_intersection_d::Box_with_info_d<double, 2, std::size_t>;

std::vector<Box> boxes_of(const std::vector<NodeSegment>& segments) {
    std::vector<Box> boxes;
    boxes.reserve(segments.size());
    for (std::size_t i = 0; i < segments.size(); ++i) {
        const auto& s = segments[i];
        const CGAL::Bbox_2 bbox(std::min(s.a.x, s.b.x), std::min(s.a.y, s.b.y), std::max(s.a.x, s.b.x),
                                std::max(s.a.y, s.b.y));
        boxes.emplace_back(bbox, i);
    }
    return boxes;
}

bool share_node(const NodeSegment& p, const NodeSegment& q) {
    return p.node_a == q.node_a || p.node_a == q.node_b || p.node_b == q.node_a || p.node_b == q.node_b;
}

// Appends the crossing of p and q, if they cross in a single point.
void test_pair(const NodeSegment& p, const NodeSegment& q, std::size_t i, std::size_t j,
               std::vector<SegmentHit>& hits) {
    if (share_node(p, q)) {
        return;
    }
    const Segment sp(Point(p.a.x, p.a.y), Point(p.b.x, p.b.y));
    const Segment sq(Point(q.a.x, q.a.y), Point(q.b.x, q.b.y));
    if (sp.is_degenerate() || sq.is_degenerate() || !CGAL::do_intersect(sp, sq)) {
        return;
    }
    const auto result = CGAL::intersection(sp, sq);
    if (!result) {
        return;
    }
    if (const Point* pt = boost::get<Point>(&*result)) {
        hits.push_back({i, j, {CGAL::to_double(pt->x()), CGAL::to_double(pt->y())}});
    }
}

void sort_hits(std::vector<SegmentHit>& hits) {
    std::sort(hits.begin(), hits.end(), [](const SegmentHit& x, const SegmentHit& y) {
        return std::tie(x.first, x.second) < std::tie(y.first, y.second);
    });
}

} // namespace

std::vector<SegmentHit> crossing_segments(const std::vector<NodeSegment>& first,
                                          const std::vector<NodeSegment>& second) {
    std::vector<Box> a = boxes_of(first);
    std::vector<Box> b = boxes_of(second);
    std::vector<SegmentHit> hits;
    // The callback order depends on CGAL's internal partitioning: sort afterwards.
    CGAL::box_intersection_d(a.begin(), a.end(), b.begin(), b.end(), [&](const Box& x, const Box& y) {
        test_pair(first[x.info()], second[y.info()], x.info(), y.info(), hits);
    });
    sort_hits(hits);
    return hits;
}

std::vector<SegmentHit> crossing_segments(const std::vector<NodeSegment>& set) {
    std::vector<Box> boxes = boxes_of(set);
    std::vector<SegmentHit> hits;
    CGAL::box_self_intersection_d(boxes.begin(), boxes.end(), [&](const Box& x, const Box& y) {
        const std::size_t i = std::min(x.info(), y.info());
        const std::size_t j = std::max(x.info(), y.info());
        test_pair(set[i], set[j], i, j, hits);
    });
    sort_hits(hits);
    return hits;
}

} // namespace railodd::geometry::detail
