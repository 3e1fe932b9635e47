// Arcs too flat for a reader that evaluates an arc from its centre in float
// (LibCarla: a ulp of the radius, 6 cm at R 944 km) are written as
// paramPoly3 cubics: checked against the exact arc with the independent
// checker's closed forms (xodr_check::evaluate), and against the float
// arithmetic LibCarla's GeometryArc uses.
#include "plan_view.hpp"

#include "railodd/xodr_check/geometry_eval.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

namespace {

using railodd::geometry::Alignment;
using railodd::geometry::make_arc;
using railodd::geometry::make_line;
using railodd::geometry::make_spiral;
using railodd::xodr::PlanGeometry;
namespace check = railodd::xodr_check;

check::GeometryRecord record(const PlanGeometry& g) {
    check::GeometryRecord r;
    switch (g.kind) {
    case PlanGeometry::Kind::line: r.kind = check::GeometryKind::line; break;
    case PlanGeometry::Kind::arc: r.kind = check::GeometryKind::arc; break;
    case PlanGeometry::Kind::spiral: r.kind = check::GeometryKind::spiral; break;
    case PlanGeometry::Kind::param_poly3: r.kind = check::GeometryKind::param_poly3; break;
    }
    r.s = g.s, r.x = g.x, r.y = g.y, r.hdg = g.hdg, r.length = g.length;
    r.curvature = g.curv_start, r.curv_start = g.curv_start, r.curv_end = g.curv_end;
    r.au = g.u[0], r.bu = g.u[1], r.cu = g.u[2], r.du = g.u[3];
    r.av = g.v[0], r.bv = g.v[1], r.cv = g.v[2], r.dv = g.v[3];
    return r;
}

// The records' largest distance from the alignment, every metre.
double worst_offset(const std::vector<PlanGeometry>& recs, const Alignment& a) {
    double worst = 0.0;
    for (const PlanGeometry& g : recs) {
        for (double ds = 0.0; ds <= g.length; ds += std::min(1.0, g.length)) {
            const check::Pose p = check::evaluate(record(g), ds);
            const auto q = railodd::geometry::evaluate(a, g.s + ds);
            worst = std::max(worst, std::hypot(p.x - q.x, p.y - q.y));
        }
    }
    return worst;
}

Alignment route(double flat_curvature, double flat_length) {
    Alignment a;
    a.start = {1234.5, -987.0, 0.3};
    a.primitives = {make_line(300.0),           make_spiral(120.0, 0.0, 1.0 / 900.0), make_arc(400.0, 1.0 / 900.0),
                    make_spiral(120.0, 1.0 / 900.0, flat_curvature), make_arc(flat_length, flat_curvature),
                    make_spiral(60.0, flat_curvature, 0.0),          make_line(200.0)};
    return a;
}

std::size_t count(const std::vector<PlanGeometry>& recs, PlanGeometry::Kind k) {
    return static_cast<std::size_t>(
        std::count_if(recs.begin(), recs.end(), [&](const PlanGeometry& g) { return g.kind == k; }));
}

TEST(XodrFlatArcs, AFlatArcIsWrittenAsACubicOnTheArc) {
    // The sample route's: R 944 km over 1,458 m, 0.28 m off its chord.
    const Alignment a = route(-1.06e-6, 1458.0);
    const std::vector<PlanGeometry> recs = railodd::xodr::plan_view_of(a, true);
    EXPECT_EQ(count(recs, PlanGeometry::Kind::param_poly3), 1u);
    EXPECT_EQ(count(recs, PlanGeometry::Kind::arc), 1u); // R 900 m stays an arc
    EXPECT_LT(worst_offset(recs, a), 1e-6);
    for (std::size_t i = 0; i + 1 < recs.size(); ++i) {
        const check::Pose e = check::evaluate(record(recs[i]), recs[i].length);
        EXPECT_LT(std::hypot(e.x - recs[i + 1].x, e.y - recs[i + 1].y), 1e-6) << "record " << i;
        EXPECT_LT(std::abs(std::remainder(e.hdg - recs[i + 1].hdg, 2 * std::numbers::pi)), 1e-9) << "record " << i;
        EXPECT_NEAR(recs[i].s + recs[i].length, recs[i + 1].s, 1e-9);
        const check::Pose b = check::evaluate(record(recs[i + 1]), 0.0);
        EXPECT_NEAR(e.curvature, b.curvature, 1e-9) << "record " << i;
    }
    EXPECT_NEAR(recs.back().s + recs.back().length, railodd::geometry::length(a), 1e-9);
}

TEST(XodrFlatArcs, ALongFlatArcIsCutIntoCubicsThatEachTurnLittle) {
    // R 60 km over 3 km turns 0.05 rad: five cubics, each within microns.
    const Alignment a = route(1.0 / 60000.0, 3000.0);
    const std::vector<PlanGeometry> recs = railodd::xodr::plan_view_of(a, true);
    EXPECT_EQ(count(recs, PlanGeometry::Kind::param_poly3), 5u);
    EXPECT_LT(worst_offset(recs, a), 1e-5);
    for (const PlanGeometry& g : recs) {
        if (g.kind == PlanGeometry::Kind::param_poly3) {
            EXPECT_NEAR(check::curve_length(record(g)), g.length, 1e-6);
        }
    }
}

// LibCarla's arc (GeometryArc::PosFromDist): the offsets to the centre and
// back each cast to float; its largest error in x along the arc.
double carla_arc_error(double curvature, double length) {
    const double r = 1.0 / curvature, hdg = 0.3, half_pi = std::numbers::pi / 2.0, x0 = 1234.5;
    double worst = 0.0;
    for (double s = 0.0; s <= length; s += length / 100.0) {
        float x = static_cast<float>(x0);
        x += static_cast<float>(r * std::cos(hdg + half_pi));
        x -= static_cast<float>(r * std::cos(hdg + curvature * s + half_pi));
        const double exact = x0 + (std::sin(hdg + curvature * s) - std::sin(hdg)) / curvature;
        worst = std::max(worst, std::abs(x - exact));
    }
    return worst;
}

TEST(XodrFlatArcs, TheLimitIsWhereAFloatArcDriftsByMillimetres) {
    // Why: at the sample's radius the float arc is centimetres off, at the
    // flattest arc still written as one a few millimetres at most.
    EXPECT_GT(carla_arc_error(-1.06e-6, 1458.0), 0.01);
    EXPECT_LT(carla_arc_error(1.0 / 49000.0, 1458.0), 0.005);
    const std::vector<PlanGeometry> recs = railodd::xodr::plan_view_of(route(1.0 / 49000.0, 1458.0), true);
    EXPECT_EQ(count(recs, PlanGeometry::Kind::param_poly3), 0u);
}

} // namespace
