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

SegmentGrid::SegmentGrid(double cell_size_m) : cell_(std::max(cell_size_m, 1.0)), cells_(cell_) {}

std::int64_t SegmentGrid::cell(double v) const noexcept { return cells_.cell_of(v); }

void SegmentGrid::add_polyline(const std::vector<XY>& points) {
    for (std::size_t i = 1; i < points.size(); ++i) {
        segments_.push_back({points[i - 1], points[i]});
        register_cells(static_cast<std::uint32_t>(segments_.size() - 1));
    }
}

// Exact grid traversal (Amanatides & Woo): only the cells the segment passes
// through, so a long diagonal straight does not fill its whole bounding box.
void SegmentGrid::register_cells(std::uint32_t index) {
    const XY a = segments_[index].a;
    const XY b = segments_[index].b;
    std::int64_t cx = cell(a.x), cy = cell(a.y);
    const std::int64_t ex = cell(b.x), ey = cell(b.y);
    const double dx = b.x - a.x, dy = b.y - a.y;
    const int step_x = dx > 0 ? 1 : -1, step_y = dy > 0 ? 1 : -1;
    constexpr double inf = std::numeric_limits<double>::infinity();
    const double delta_x = dx != 0 ? cell_ / std::abs(dx) : inf;
    const double delta_y = dy != 0 ? cell_ / std::abs(dy) : inf;
    const double next_x = (static_cast<double>(cx + (step_x > 0 ? 1 : 0)) * cell_ - a.x);
    const double next_y = (static_cast<double>(cy + (step_y > 0 ? 1 : 0)) * cell_ - a.y);
    double t_x = dx != 0 ? next_x / dx : inf;
    double t_y = dy != 0 ? next_y / dy : inf;
    cells_.add(cx, cy, index);
    const std::int64_t steps = std::abs(ex - cx) + std::abs(ey - cy);
    for (std::int64_t i = 0; i < steps; ++i) {
        if (t_x < t_y) {
            cx += step_x;
            t_x += delta_x;
        } else {
            cy += step_y;
            t_y += delta_y;
        }
        cells_.add(cx, cy, index);
    }
}

bool SegmentGrid::cell_within(std::int64_t cx, std::int64_t cy, XY p, double max_distance) const {
    const std::vector<std::uint32_t>* ids = cells_.at(cx, cy);
    if (!ids) {
        return false;
    }
    for (std::uint32_t i : *ids) {
        if (point_segment_distance(p, segments_[i].a, segments_[i].b) <= max_distance) {
            return true;
        }
    }
    return false;
}

bool SegmentGrid::within(XY p, double max_distance) const {
    const std::int64_t px = cell(p.x), py = cell(p.y);
    const auto reach = static_cast<std::int64_t>(std::ceil(max_distance / cell_));
    // Square rings of cells around p's cell, nearest ring first.
    for (std::int64_t r = 0; r <= reach; ++r) {
        for (std::int64_t cx = px - r; cx <= px + r; ++cx) {
            const bool edge_column = (cx == px - r || cx == px + r);
            for (std::int64_t cy = py - r; cy <= py + r; cy += (edge_column || r == 0) ? 1 : 2 * r) {
                if (cell_within(cx, cy, p, max_distance)) {
                    return true;
                }
            }
        }
    }
    return false;
}

} // namespace railodd::ingest
