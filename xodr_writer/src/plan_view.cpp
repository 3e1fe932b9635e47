#include "plan_view.hpp"

#include <algorithm>
#include <cmath>

namespace railodd::xodr {

std::vector<PlanGeometry> plan_view_of(const geometry::Alignment& alignment, bool rail) {
    std::vector<PlanGeometry> out;
    const std::vector<geometry::Pose> starts = geometry::primitive_starts(alignment);
    double s = 0.0;
    for (std::size_t i = 0; i < alignment.primitives.size(); ++i) {
        const geometry::Primitive& p = alignment.primitives[i];
        PlanGeometry g;
        switch (p.kind) {
        case geometry::PrimitiveKind::line:
            g.kind = PlanGeometry::Kind::line;
            break;
        case geometry::PrimitiveKind::arc:
            g.kind = PlanGeometry::Kind::arc;
            break;
        case geometry::PrimitiveKind::spiral:
            // One whose curvature does not change is a line or an arc:
            // SUMO's netconvert cannot draw a spiral of rate 0.
            g.kind = p.curv_start != p.curv_end ? PlanGeometry::Kind::spiral
                     : p.curv_start == 0.0      ? PlanGeometry::Kind::line
                                                : PlanGeometry::Kind::arc;
            break;
        }
        g.s = s;
        g.x = starts[i].x;
        g.y = starts[i].y;
        g.hdg = starts[i].hdg;
        g.length = p.length;
        g.curv_start = p.curv_start;
        g.curv_end = p.curv_end;
        out.push_back(g);
        s += p.length;
    }
    if (out.empty()) { // no primitive at all: a zero-length line at the start
        PlanGeometry g;
        g.x = alignment.start.x;
        g.y = alignment.start.y;
        g.hdg = alignment.start.hdg;
        out.push_back(g);
    }
    merge_short_records(out, min_record_length_m, rail);
    return out;
}

namespace {

// Any record with s, a, b, c, d (cubic in ds = s' - s).
template <class Poly>
Poly shifted(const Poly& p, double s0) {
    const double h = s0 - p.s;
    Poly q = p;
    q.s = 0.0;
    q.a = p.a + h * (p.b + h * (p.c + h * p.d));
    q.b = p.b + h * (2.0 * p.c + 3.0 * h * p.d);
    q.c = p.c + 3.0 * h * p.d;
    return q;
}

template <class Poly>
std::vector<Poly> cut(const std::vector<Poly>& polys, double s0, double s1) {
    std::vector<Poly> out;
    if (polys.empty()) {
        return out;
    }
    // The record in force at s0: the last one starting at or before it.
    std::size_t first = 0;
    for (std::size_t i = 0; i < polys.size(); ++i) {
        if (polys[i].s <= s0 + 1e-9) {
            first = i;
        }
    }
    out.push_back(shifted(polys[first], s0));
    for (std::size_t i = first + 1; i < polys.size(); ++i) {
        if (polys[i].s >= s1 - 1e-9) {
            break;
        }
        if (polys[i].s > s0 + 1e-9) {
            Poly q = polys[i];
            q.s -= s0;
            out.push_back(q);
        }
    }
    return out;
}

} // namespace

std::vector<geometry::ElevationPoly> cut_polys(const std::vector<geometry::ElevationPoly>& polys, double s0,
                                               double s1) {
    return cut(polys, s0, s1);
}

std::vector<Superelevation> cut_superelevation(const std::vector<Superelevation>& records, double s0, double s1) {
    return cut(records, s0, s1);
}

std::vector<Superelevation> superelevation_of(const std::vector<geometry::CantStretch>& cant, double length,
                                              double rail_spacing_m) {
    std::vector<Superelevation> out;
    if (cant.empty()) {
        return out;
    }
    double covered = 0.0; // end of the last stretch written
    for (const auto& c : cant) {
        if (c.s_start > covered + 1e-9) {
            out.push_back({covered, 0.0, 0.0, 0.0, 0.0}); // level between stretches
        }
        const double sign = c.left_curve ? -1.0 : 1.0;
        const double a = sign * geometry::superelevation_rad(c.cant_start_m, rail_spacing_m);
        const double e = sign * geometry::superelevation_rad(c.cant_end_m, rail_spacing_m);
        const double len = c.s_end - c.s_start;
        out.push_back({c.s_start, a, len > 0.0 ? (e - a) / len : 0.0, 0.0, 0.0});
        covered = c.s_end;
    }
    if (covered < length - 1e-9) {
        out.push_back({covered, 0.0, 0.0, 0.0, 0.0});
    }
    return out;
}

} // namespace railodd::xodr
