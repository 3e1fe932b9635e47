// AABB tree of the track polylines as 3D segments at z = 0: CGAL's nearest
// point query needs three dimensions, the plane costs nothing.
#include "edge_index.hpp"

#include <CGAL/AABB_segment_primitive.h>
#include <CGAL/AABB_traits.h>
#include <CGAL/AABB_tree.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>

#include <algorithm>
#include <cmath>
#include <iterator>
#include <limits>

namespace railodd::geometry::detail {

namespace {

using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using Point = Kernel::Point_3;
using Segment = Kernel::Segment_3;
using SegmentIterator = std::vector<Segment>::const_iterator;
using Primitive = CGAL::AABB_segment_primitive<Kernel, SegmentIterator>;
using Tree = CGAL::AABB_tree<CGAL::AABB_traits<Kernel, Primitive>>;

} // namespace

struct EdgeIndex::Impl {
    std::vector<Segment> segments; // must not move while the tree refers to it
    std::vector<std::size_t> edge_of;
    Tree tree;
};

EdgeIndex::EdgeIndex(const TrackGraph& graph) : impl_(std::make_unique<Impl>()) {
    for (const auto& e : graph.edges) {
        for (std::size_t k = 0; k + 1 < e.nodes.size(); ++k) {
            const auto& a = e.nodes[k].xy;
            const auto& b = e.nodes[k + 1].xy;
            impl_->segments.emplace_back(Point(a.x, a.y, 0.0), Point(b.x, b.y, 0.0));
            impl_->edge_of.push_back(e.id);
        }
    }
    if (!impl_->segments.empty()) {
        impl_->tree.insert(impl_->segments.cbegin(), impl_->segments.cend());
        impl_->tree.build();
        impl_->tree.accelerate_distance_queries();
    }
}

EdgeIndex::~EdgeIndex() = default;

EdgeIndex::Near EdgeIndex::near(ingest::XY p, double slack) const {
    Near result;
    if (impl_->segments.empty()) {
        result.distance = std::numeric_limits<double>::infinity();
        return result;
    }
    const Point q(p.x, p.y, 0.0);
    const Point closest = impl_->tree.closest_point(q);
    result.distance = std::sqrt(CGAL::to_double(CGAL::squared_distance(q, closest)));
    const double r = result.distance + slack;
    const Kernel::Iso_cuboid_3 box(Point(p.x - r, p.y - r, -1.0), Point(p.x + r, p.y + r, 1.0));
    std::vector<Tree::Primitive_id> hits;
    impl_->tree.all_intersected_primitives(box, std::back_inserter(hits));
    for (const auto& id : hits) {
        result.edges.push_back(impl_->edge_of[static_cast<std::size_t>(id - impl_->segments.cbegin())]);
    }
    std::sort(result.edges.begin(), result.edges.end());
    result.edges.erase(std::unique(result.edges.begin(), result.edges.end()), result.edges.end());
    return result;
}

} // namespace railodd::geometry::detail
