// Telling a fit that loops from one that follows its nodes; see
// fit_alignment.hpp.
#include "railodd/geometry/fit_alignment.hpp"

#include "loop_bounds.hpp"
#include "railodd/geometry/indexed_alignment.hpp"

#include <cmath>

namespace railodd::geometry {

bool closes_on_itself(const std::vector<Point>& p) {
    return p.size() > 2 && p.front().x == p.back().x && p.front().y == p.back().y;
}

// Node distances alone cannot tell a fit that loops (a spiral at the
// curvature bound somewhere along the way, every node still near some part
// of the curve) from a good one; its length and total turning can
// (loop_bounds.hpp), where the loop is long against the whole chain. A loop
// short against it shows between two nodes: the curve runs far further
// between their feet than the nodes lie apart (Cologne: 567 m between the
// last two nodes of a 12 km chain, 24 m apart, the chain 4.6 % longer than
// its nodes' polyline).
bool loops_back(const Alignment& a, const std::vector<Point>& p) {
    double turning = 0.0;
    for (const Primitive& q : a.primitives) {
        turning += piece_turning(q.curv_start, q.curv_end, q.length);
    }
    if (LoopBounds(p).exceeded(length(a), turning)) {
        return true;
    }
    const IndexedAlignment ia(a);
    // A ring's first and last node are one: its feet are the curve's two
    // ends, which a projection cannot tell apart (Cologne: two rings of 1.9
    // and 2.0 km, each then built by corners).
    const bool ring = closes_on_itself(p);
    double last = 0.0;
    for (std::size_t i = 0; i < p.size(); ++i) {
        const bool end = ring && (i == 0 || i + 1 == p.size());
        const double s = end ? (i == 0 ? 0.0 : ia.length()) : ia.project(p[i].x, p[i].y).s;
        if (i > 0 && std::abs(s - last) > 2.0 * std::hypot(p[i].x - p[i - 1].x, p[i].y - p[i - 1].y) + 50.0) {
            return true;
        }
        last = s;
    }
    return false;
}

} // namespace railodd::geometry
