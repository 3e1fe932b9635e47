#include "plan_view.hpp"

#include <algorithm>
#include <cmath>

namespace railodd::xodr {

namespace {

// Arcs flatter than this are written as paramPoly3. LibCarla evaluates an
// arc from its centre, the radius cast to float (GeometryArc::PosFromDist):
// a ulp of the radius off, 6 cm at R 944 km, where a design between two
// curves that the nodes hold slightly bent put four roads of the sample
// route 1.5-2.8 cm from their starts. At R 50 km the ulp is 4 mm.
constexpr double flat_curvature = 1.0 / 50000.0;

// Each cubic turns at most this far: its lateral error is about
// 0.0044 * turn^3 * length, 2 micrometres at 500 m.
constexpr double piece_turn = 0.01;

// sin(a) / a - 1 and (1 - cos a) / a - a / 2 for |a| <= 0.01, by their
// series: written as differences they cancel to nothing on flat arcs.
double sinc_less_one(double a) { return -a * a / 6.0 + a * a * a * a / 120.0; }
double versine_less_half(double a) { return -a * a * a / 24.0 + a * a * a * a * a / 720.0; }

// A flat arc as paramPoly3 pieces (pRange arcLength): u = p + dU p^3,
// v = k p^2 / 2 + dV p^3, its Taylor series to third order with dU and dV
// set so each piece ends exactly where the arc does. Its start pose,
// curvature and length are the arc's: continuity is kept.
void flat_arc_as_cubics(const PlanGeometry& arc, std::vector<PlanGeometry>& out) {
    const double k = arc.curv_start;
    const auto n = static_cast<std::size_t>(std::max(1.0, std::ceil(std::abs(k) * arc.length / piece_turn - 1e-9)));
    const double l = arc.length / static_cast<double>(n);
    const double a = k * l;
    const geometry::Primitive whole = geometry::make_arc(arc.length, k);
    for (std::size_t i = 0; i < n; ++i) {
        const double s = static_cast<double>(i) * l;
        const geometry::Pose at = geometry::evaluate({arc.x, arc.y, arc.hdg}, whole, s);
        PlanGeometry g = arc;
        g.kind = PlanGeometry::Kind::param_poly3;
        g.s = arc.s + s;
        g.x = at.x;
        g.y = at.y;
        g.hdg = at.hdg;
        g.length = i + 1 == n ? arc.length - s : l;
        g.u = {0.0, 1.0, 0.0, sinc_less_one(a) / (l * l)};
        g.v = {0.0, 0.0, 0.5 * k, versine_less_half(a) / (l * l)};
        out.push_back(g);
    }
}

void flat_arcs_as_cubics(std::vector<PlanGeometry>& records) {
    std::vector<PlanGeometry> out;
    for (const PlanGeometry& g : records) {
        if (g.kind == PlanGeometry::Kind::arc && std::abs(g.curv_start) < flat_curvature && g.length > 0.0) {
            flat_arc_as_cubics(g, out);
        } else {
            out.push_back(g);
        }
    }
    records = std::move(out);
}

} // namespace

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
    flat_arcs_as_cubics(out);
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
