#include "railodd/geometry/alignment.hpp"

#include <algorithm>

namespace railodd::geometry {

namespace {

// The part [ds0, ds1] of one primitive as a primitive of its own.
Primitive part_of(const Primitive& p, double ds0, double ds1) {
    Primitive q = p;
    q.length = ds1 - ds0;
    if (p.kind == PrimitiveKind::spiral && p.length > 0) {
        const double rate = (p.curv_end - p.curv_start) / p.length;
        // The primitive's own end values where the part reaches them, so that
        // curvature matches its neighbours exactly, not to the last bit.
        q.curv_start = ds0 == 0.0 ? p.curv_start : p.curv_start + rate * ds0;
        q.curv_end = ds1 == p.length ? p.curv_end : p.curv_start + rate * ds1;
    }
    return q;
}

// A cut this close to a knot is at the knot: a cut placed on one (a switch
// taken at its through track's knot, track_fit.cpp) and moved with the
// chain by rounding must not leave a piece of 1e-13 m.
constexpr double at_knot_m = 1e-9;

} // namespace

std::vector<Alignment> split_alignment(const Alignment& a, const std::vector<double>& cuts) {
    std::vector<Alignment> out(1);
    out.back().start = a.start;
    std::size_t next_cut = 0;
    Pose at = a.start;
    double s0 = 0.0;
    for (const Primitive& p : a.primitives) {
        double from = 0.0; // within p
        while (next_cut < cuts.size() && cuts[next_cut] < s0 + p.length - at_knot_m) {
            const double ds = cuts[next_cut] - s0 < from + at_knot_m ? from : cuts[next_cut] - s0;
            if (ds > from) {
                out.back().primitives.push_back(part_of(p, from, ds));
            }
            Alignment piece;
            piece.start = evaluate(at, p, ds);
            out.push_back(piece);
            from = ds;
            ++next_cut;
        }
        if (p.length > from || p.length == 0.0) {
            out.back().primitives.push_back(part_of(p, from, p.length));
        }
        at = evaluate(at, p, p.length);
        s0 += p.length;
    }
    while (next_cut++ < cuts.size()) {
        Alignment piece;
        piece.start = at; // cuts at (or beyond) the end give empty pieces there
        out.push_back(piece);
    }
    return out;
}

} // namespace railodd::geometry
