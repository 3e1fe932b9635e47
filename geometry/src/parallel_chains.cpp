#include "parallel_chains.hpp"

#include "railodd/util/cell_grid.hpp"

#include <algorithm>
#include <cmath>
#include <map>
#include <utility>

namespace railodd::geometry {

namespace {

constexpr double min_offset_m = 2.5, max_offset_m = 6.5, cell_m = 20.0;
constexpr double min_cos = 0.99; // within 8 degrees of parallel
constexpr std::size_t min_nodes = 5;

struct Segment {
    std::size_t chain;
    Point a, b;
};

// Every chain's segments, binned by grid cell (a segment in each cell its
// box, grown by the largest offset, touches).
class SegmentGrid {
public:
    explicit SegmentGrid(const std::vector<std::vector<Point>>& points) {
        for (std::size_t c = 0; c < points.size(); ++c) {
            for (std::size_t i = 1; i < points[c].size(); ++i) {
                add({c, points[c][i - 1], points[c][i]});
            }
        }
    }

    template <class F>
    void near(const Point& q, F&& visit) const {
        if (const std::vector<std::size_t>* ids = cells_.at(cells_.cell_of(q.x), cells_.cell_of(q.y))) {
            for (const std::size_t s : *ids) {
                visit(segments_[s]);
            }
        }
    }

private:
    void add(const Segment& s) {
        const std::size_t id = segments_.size();
        segments_.push_back(s);
        // A segment kilometres long is left out: no double track is drawn so.
        cells_.add_box(std::min(s.a.x, s.b.x) - max_offset_m, std::min(s.a.y, s.b.y) - max_offset_m,
                       std::max(s.a.x, s.b.x) + max_offset_m, std::max(s.a.y, s.b.y) + max_offset_m, id, 10000);
    }

    std::vector<Segment> segments_;
    util::CellGrid<std::size_t> cells_{cell_m};
};

// Does node i of chain `pts` lie beside segment s, along it?
bool beside(const std::vector<Point>& pts, std::size_t i, const Segment& s) {
    const double dx = s.b.x - s.a.x, dy = s.b.y - s.a.y, len2 = dx * dx + dy * dy;
    if (len2 < 1e-6) {
        return false;
    }
    const Point& q = pts[i];
    const double u = ((q.x - s.a.x) * dx + (q.y - s.a.y) * dy) / len2;
    if (u < 0.0 || u > 1.0) {
        return false;
    }
    const double d = std::abs((q.x - s.a.x) * dy - (q.y - s.a.y) * dx) / std::sqrt(len2);
    if (d < min_offset_m || d > max_offset_m) {
        return false;
    }
    const Point& p0 = pts[i > 0 ? i - 1 : i];
    const Point& p1 = pts[i + 1 < pts.size() ? i + 1 : i];
    const double ex = p1.x - p0.x, ey = p1.y - p0.y, elen = std::hypot(ex, ey);
    return elen > 1e-6 && std::abs(ex * dx + ey * dy) / (elen * std::sqrt(len2)) >= min_cos;
}

} // namespace

std::vector<std::vector<std::size_t>> parallel_guides(const std::vector<std::vector<Point>>& points,
                                                      const std::vector<std::size_t>& rank) {
    const SegmentGrid grid(points);
    std::vector<std::vector<std::size_t>> out(points.size());
    for (std::size_t c = 0; c < points.size(); ++c) {
        std::map<std::size_t, std::size_t> count; // ordered: ties go to the lower index
        for (std::size_t i = 0; i < points[c].size(); ++i) {
            std::optional<std::size_t> found;
            grid.near(points[c][i], [&](const Segment& s) {
                if (!found && rank[s.chain] < rank[c] && beside(points[c], i, s)) {
                    found = s.chain;
                }
            });
            if (found) {
                ++count[*found];
            }
        }
        std::vector<std::pair<std::size_t, std::size_t>> found; // (nodes, chain)
        for (const auto& [g, n] : count) {
            if (n >= min_nodes) {
                found.push_back({n, g});
            }
        }
        std::stable_sort(found.begin(), found.end(), [](const auto& a, const auto& b) { return a.first > b.first; });
        for (const auto& f : found) {
            out[c].push_back(f.second);
        }
    }
    return out;
}

} // namespace railodd::geometry
