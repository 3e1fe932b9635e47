// Telling a fit that loops from one that follows its nodes; see
// fit_alignment.hpp.
#include "railodd/geometry/fit_alignment.hpp"

#include "loop_bounds.hpp"

namespace railodd::geometry {

// Node distances alone cannot tell a fit that loops (a spiral at the
// curvature bound somewhere along the way, every node still near some part
// of the curve) from a good one; its length and total turning can
// (loop_bounds.hpp).
bool loops_back(const Alignment& a, const std::vector<Point>& p) {
    double turning = 0.0;
    for (const Primitive& q : a.primitives) {
        turning += piece_turning(q.curv_start, q.curv_end, q.length);
    }
    return LoopBounds(p).exceeded(length(a), turning);
}

} // namespace railodd::geometry
