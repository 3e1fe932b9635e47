#include "segment_grid.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace railodd::ingest {

namespace {

double point_segment_distance(XY p, XY a, XY b) {
    const double dx = b.x - a.x;
    const double dy = b.y - a.y;
    const double len2 = dx * dx + dy * dy;
    double t = len2 > 0 ? ((p.x - a.x) * dx + (p.y - a.y) * dy) / len2 : 0.0;
    t = std::clamp(t, 0.0, 1.0);
    return std::hypot(p.x - (a.x + t * dx), p.y - (a.y + t * dy));
}

} // namespace

SegmentGrid::SegmentGrid(double cell_size_m) : cell_(std::max(cell_size_m, 1.0)) {}

std::int64_t SegmentGrid::cell(double v) const noexcept {
    return static_cast<std::int64_t>(std::floor(v / cell_));
}

void SegmentGrid::add_polyline(const std::vector<XY>& points) {
    for (std::size_t i = 1; i < points.size(); ++i) {
        const XY a = points[i - 1];
        const XY b = points[i];
        const auto index = static_cast<std::uint32_t>(segments_.size());
        segments_.push_back({a, b});
        // Every cell the segment's bounding box touches: cheap and conservative.
        for (std::int64_t cx = cell(std::min(a.x, b.x)); cx <= cell(std::max(a.x, b.x)); ++cx) {
            for (std::int64_t cy = cell(std::min(a.y, b.y)); cy <= cell(std::max(a.y, b.y)); ++cy) {
                cells_[key(cx, cy)].push_back(index);
            }
        }
    }
}

double SegmentGrid::distance(XY p, double max_distance) const {
    double best = std::numeric_limits<double>::infinity();
    const std::int64_t x0 = cell(p.x - max_distance), x1 = cell(p.x + max_distance);
    const std::int64_t y0 = cell(p.y - max_distance), y1 = cell(p.y + max_distance);
    for (std::int64_t cx = x0; cx <= x1; ++cx) {
        for (std::int64_t cy = y0; cy <= y1; ++cy) {
            const auto it = cells_.find(key(cx, cy));
            if (it == cells_.end()) {
                continue;
            }
            for (std::uint32_t i : it->second) {
                best = std::min(best, point_segment_distance(p, segments_[i].a, segments_[i].b));
            }
        }
    }
    return best;
}

} // namespace railodd::ingest
