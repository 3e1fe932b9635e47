// Telling a fit that loops from one that follows its nodes; see
// fit_alignment.hpp.
#include "railodd/geometry/fit_alignment.hpp"

#include <cmath>
#include <numbers>

namespace railodd::geometry {

namespace {

// Node distances alone cannot tell a fit that loops (a spiral at the
// curvature bound somewhere along the way, every node still near some part
// of the curve) from a good one; its length and total turning can. A
// centreline fitted to nodes is about as long as the polyline through them
// and turns no more than it (mapping noise only adds turning to the
// polyline), so more than 5 % + 10 m of extra length or a full extra turn
// means a loop.
double polyline_length(const std::vector<Point>& p) {
    double l = 0.0;
    for (std::size_t i = 1; i < p.size(); ++i) {
        l += std::hypot(p[i].x - p[i - 1].x, p[i].y - p[i - 1].y);
    }
    return l;
}

double polyline_turning(const std::vector<Point>& p) {
    double turn = 0.0;
    for (std::size_t i = 1; i + 1 < p.size(); ++i) {
        const double a = std::atan2(p[i].y - p[i - 1].y, p[i].x - p[i - 1].x);
        const double b = std::atan2(p[i + 1].y - p[i].y, p[i + 1].x - p[i].x);
        turn += std::abs(std::remainder(b - a, 2 * std::numbers::pi));
    }
    return turn;
}

double alignment_turning(const Alignment& a) {
    double turn = 0.0;
    for (const Primitive& q : a.primitives) {
        if (q.curv_start * q.curv_end >= 0.0) {
            turn += 0.5 * std::abs(q.curv_start + q.curv_end) * q.length;
        } else {
            // Curvature crosses zero inside: two triangles of the diagram.
            const double a0 = std::abs(q.curv_start), a1 = std::abs(q.curv_end);
            turn += 0.5 * (a0 * a0 + a1 * a1) / (a0 + a1) * q.length;
        }
    }
    return turn;
}

} // namespace

bool loops_back(const Alignment& a, const std::vector<Point>& p) {
    const double lp = polyline_length(p);
    return length(a) > 1.05 * lp + 10.0 || alignment_turning(a) > polyline_turning(p) + 2 * std::numbers::pi;
}

} // namespace railodd::geometry
