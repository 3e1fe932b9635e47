// planView records under 1 cm merged into their neighbours (issue 22): on
// known alignments, checked by re-evaluating every record from its own start
// pose with the independent checker's closed forms (xodr_check::evaluate).
#include "plan_view.hpp"

#include "railodd/xodr_check/geometry_eval.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <iostream>
#include <numbers>

namespace {

using railodd::geometry::Alignment;
using railodd::geometry::make_arc;
using railodd::geometry::make_line;
using railodd::geometry::make_spiral;
using railodd::xodr::PlanGeometry;

railodd::xodr_check::GeometryRecord record(const PlanGeometry& g) {
    railodd::xodr_check::GeometryRecord r;
    r.kind = g.kind == PlanGeometry::Kind::line  ? railodd::xodr_check::GeometryKind::line
             : g.kind == PlanGeometry::Kind::arc ? railodd::xodr_check::GeometryKind::arc
                                                 : railodd::xodr_check::GeometryKind::spiral;
    r.s = g.s, r.x = g.x, r.y = g.y, r.hdg = g.hdg, r.length = g.length;
    r.curvature = g.curv_start, r.curv_start = g.curv_start, r.curv_end = g.curv_end;
    return r;
}

railodd::xodr_check::Pose end_of(const PlanGeometry& g) { return railodd::xodr_check::evaluate(record(g), g.length); }

struct Joints {
    double gap = 0.0, heading = 0.0, curvature = 0.0;
};

// The worst joint of the records, and the s chain.
Joints joints(const std::vector<PlanGeometry>& recs) {
    Joints j;
    for (std::size_t i = 0; i + 1 < recs.size(); ++i) {
        const auto e = end_of(recs[i]);
        const auto& n = recs[i + 1];
        j.gap = std::max(j.gap, std::hypot(e.x - n.x, e.y - n.y));
        j.heading = std::max(j.heading, std::abs(std::remainder(e.hdg - n.hdg, 2 * std::numbers::pi)));
        j.curvature = std::max(j.curvature, std::abs(recs[i].curv_end - n.curv_start));
        EXPECT_NEAR(recs[i].s + recs[i].length, n.s, 1e-9) << "record " << i;
    }
    return j;
}

double total(const std::vector<PlanGeometry>& recs) {
    double t = 0.0;
    for (const auto& g : recs) t += g.length;
    return t;
}

double shortest(const std::vector<PlanGeometry>& recs) {
    double m = 1e300;
    for (const auto& g : recs) m = std::min(m, g.length);
    return m;
}

Alignment alignment(std::vector<railodd::geometry::Primitive> ps) {
    Alignment a;
    a.start = {10.0, -5.0, 0.3, 0.0};
    a.primitives = std::move(ps);
    return a;
}

TEST(XodrShortRecords, ZeroLengthRecordsGoWithoutMovingAnything) {
    // A cut a rounding error from a primitive's end: a 1e-14 m spiral between arcs.
    const auto a = alignment({make_line(50), make_spiral(40, 0, 0.004), make_spiral(1e-14, 0.004, 0.004),
                              make_arc(80, 0.004), make_line(1e-13)});
    const auto recs = railodd::xodr::plan_view_of(a, true);
    // The zero spiral goes; the zero line at the end, where the curvature
    // falls to 0, becomes a 1 cm spiral taken from the arc.
    ASSERT_EQ(recs.size(), 4u);
    EXPECT_EQ(recs[3].kind, PlanGeometry::Kind::spiral);
    EXPECT_GE(shortest(recs), 0.01);
    EXPECT_NEAR(total(recs), 170.0, 1e-9);
    const Joints j = joints(recs);
    EXPECT_LT(j.gap, 1e-9);
    EXPECT_LT(j.heading, 1e-7);
    EXPECT_LT(j.curvature, 1e-12);
    EXPECT_EQ(recs.back().curv_end, 0.0);
    // The end is where the alignment ends.
    const auto e = end_of(recs.back());
    const auto truth = railodd::geometry::evaluate(a, 170.0);
    EXPECT_NEAR(e.x, truth.x, 1e-6);
    EXPECT_NEAR(e.y, truth.y, 1e-6);
}

TEST(XodrShortRecords, AMillimetreCornerIsTakenUpByTheLineBesideIt) {
    // The corner construction at a node with a tiny deflection: spiral-arc-spiral of 1.5 mm each.
    const auto a = alignment({make_line(30), make_spiral(0.0015, 0, 0.001), make_arc(0.0015, 0.001),
                              make_spiral(0.0015, 0.001, 0), make_line(40)});
    const auto recs = railodd::xodr::plan_view_of(a, true);
    ASSERT_EQ(recs.size(), 2u);
    EXPECT_NEAR(total(recs), 70.0045, 1e-9);
    const Joints j = joints(recs);
    EXPECT_LT(j.gap, 1e-8);
    EXPECT_LT(j.heading, 1e-5); // the corner turned by 3e-6 rad
    EXPECT_EQ(j.curvature, 0.0);
}

TEST(XodrShortRecords, AShortTransitionIsLengthenedFromALongNeighbourKeepingCurvatureContinuous) {
    // A 5 mm spiral from a straight into an arc: it cannot go (the curvature
    // jumps across it); it becomes 1 cm, the line before it giving the 5 mm.
    const auto a = alignment(
        {make_line(100), make_spiral(0.005, 0, 0.002), make_arc(100, 0.002), make_spiral(50, 0.002, 0), make_line(20)});
    const auto recs = railodd::xodr::plan_view_of(a, true);
    ASSERT_EQ(recs.size(), 5u);
    EXPECT_NEAR(recs[1].length, 0.01, 1e-12);
    EXPECT_NEAR(recs[0].length, 99.995, 1e-9); // the longer neighbour (the first of equals) lends
    EXPECT_NEAR(recs[2].length, 100.0, 1e-9);
    EXPECT_NEAR(total(recs), 270.005, 1e-9);
    const Joints j = joints(recs);
    EXPECT_LT(j.curvature, 1e-12);
    EXPECT_LT(j.gap, 1e-7);
    EXPECT_LT(j.heading, 1e-5);
}

TEST(XodrShortRecords, ASharpShortCornerIsScaledSoItTurnsAsItDid) {
    // A road corner at a node: 0.2 rad in 3 x 3 mm between straights. Dropped,
    // it would leave a 0.2 rad kink; lengthened at its curvature it would turn
    // further. Scaled, its lengths grow and its curvature falls alike.
    const double k = 0.2 / 0.006;
    const auto a = alignment({make_line(20), make_spiral(0.003, 0, k), make_arc(0.003, k), make_spiral(0.003, k, 0),
                              make_line(20)});
    const auto recs = railodd::xodr::plan_view_of(a, false);
    ASSERT_EQ(recs.size(), 5u);
    EXPECT_GE(shortest(recs), 0.01 - 1e-12);
    EXPECT_NEAR(total(recs), 40.009, 1e-3); // shorter by the chord's shortfall only
    double turn = 0.0;
    for (std::size_t i = 1; i <= 3; ++i) turn += 0.5 * (recs[i].curv_start + recs[i].curv_end) * recs[i].length;
    EXPECT_NEAR(turn, 0.2, 1e-9);
    const Joints j = joints(recs);
    EXPECT_LT(j.curvature, 1e-12);
    EXPECT_LT(j.gap, 1e-9);
    EXPECT_LT(j.heading, 1e-9);
}

TEST(XodrShortRecords, ATrackShorterThanACentimetreStaysAsItIs) {
    const auto a = alignment({make_line(0.004), make_arc(0.003, 0.01)});
    const auto recs = railodd::xodr::plan_view_of(a, true);
    ASSERT_EQ(recs.size(), 2u);
    EXPECT_NEAR(total(recs), 0.007, 1e-12);
}

// Random alignments with short records strewn in: nothing is under 1 cm
// afterwards unless it had to be, and the joints hold the checker's limits.
TEST(XodrShortRecords, RandomAlignmentsKeepTheirJointsWithinTheLimits) {
    std::uint64_t state = 12345;
    const auto uniform = [&](double lo, double hi) {
        state = state * 6364136223846793005ULL + 1442695040888963407ULL;
        return lo + (hi - lo) * static_cast<double>(state >> 11) / 9007199254740992.0;
    };
    std::size_t short_in = 0, short_out = 0;
    for (int trial = 0; trial < 300; ++trial) {
        std::vector<railodd::geometry::Primitive> ps;
        double k = 0.0;
        for (int i = 0; i < 12; ++i) {
            const bool tiny = uniform(0, 1) < 0.3;
            const double len = tiny ? uniform(0, 0.009) : uniform(5, 200);
            const double r = uniform(0, 1);
            if (r < 0.3) {
                ps.push_back(k == 0.0 ? make_line(len) : make_arc(len, k));
            } else {
                const double k1 = uniform(0, 1) < 0.3 ? 0.0 : uniform(-0.004, 0.004); // R >= 250 m
                ps.push_back(make_spiral(len, k, k1));
                k = k1;
            }
        }
        const auto recs = railodd::xodr::plan_view_of(alignment(ps), true);
        for (const auto& p : ps) short_in += p.length < 0.01 ? 1 : 0;
        for (const auto& g : recs) short_out += g.length < 0.01 ? 1 : 0;
        const Joints j = joints(recs);
        EXPECT_LT(j.gap, 1e-3) << "trial " << trial;
        EXPECT_LT(j.heading, 1e-4) << "trial " << trial;
        EXPECT_LT(j.curvature, 1e-9) << "trial " << trial;
        double sum = 0.0;
        for (const auto& p : ps) sum += p.length;
        EXPECT_NEAR(total(recs), sum, 1e-9) << "trial " << trial;
    }
    // Left only where no neighbour could take the run within the limits
    // (sharp spirals on both sides).
    std::cout << short_out << " of " << short_in << " short records left\n";
    EXPECT_LT(short_out * 20, short_in);
}

} // namespace
