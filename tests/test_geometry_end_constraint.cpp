// A tied end pose as the least-squares fit's constraint
// (geometry/src/fit/end_constraint.hpp): its gap taken a turn apart as no
// gap, and a curve millimetres off it moved onto it (meet_end).
#include "fit/end_constraint.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

using namespace railodd::geometry;
using namespace railodd::geometry::fit;

namespace {

constexpr double turn = 2.0 * std::numbers::pi;

// A model tied at the origin, heading hdg, starting at zero curvature.
CurvatureModel tied_at_origin(double hdg) {
    CurvatureModel m;
    m.start = {0.0, 0.0, hdg, 0.0};
    m.start_free = false;
    m.knot_var = {-1};
    m.knot_fixed = {0.0};
    return m;
}

// A line, a transition into an arc of R 600 m, the arc, a transition out and
// a line, as the design search's structure keeps it (the arc's curvature one
// variable, the lines' knots fixed at zero).
CurvatureModel curve() {
    CurvatureModel m = tied_at_origin(3.0);
    m.push_segment(200.0, true, -1, 0.0);
    m.curv.push_back(1.0 / 600.0);
    m.push_segment(80.0, true, 0);
    m.push_segment(150.0, true, 0);
    m.push_segment(80.0, true, -1, 0.0);
    m.push_segment(200.0, true, -1, 0.0);
    return m;
}

} // namespace

TEST(EndConstraint, HeadingsATurnApartAreOneHeading) {
    const CurvatureModel m = curve();
    Pose end = m.knot_poses().back();
    ASSERT_GT(end.hdg, std::numbers::pi); // integrated past pi
    const Pose tie{end.x, end.y, std::remainder(end.hdg, turn), 0.0};
    EXPECT_LT(end_gap(m, end, tie).cwiseAbs().maxCoeff(), 1e-9);
}

TEST(EndConstraint, ACurveMillimetresOffItsEndIsMovedOntoIt) {
    const CurvatureModel m = curve();
    const Pose end = m.knot_poses().back();
    const double off = 3e-4; // to the left, as the frame's design misses
    const Pose tie{end.x - off * std::sin(end.hdg), end.y + off * std::cos(end.hdg),
                   std::remainder(end.hdg + 2e-6, turn), 0.0};
    CurvatureModel moved = m;
    ASSERT_TRUE(meet_end(moved, tie));
    const Pose met = moved.knot_poses().back();
    EXPECT_LT(std::hypot(met.x - tie.x, met.y - tie.y), 1e-8);
    EXPECT_LT(std::abs(std::remainder(met.hdg - tie.hdg, turn)), 1e-10);
    for (std::size_t j = 0; j < m.segments(); ++j) {
        EXPECT_LT(std::abs(moved.lengths[j] - m.lengths[j]), 0.01) << "segment " << j;
    }
    EXPECT_LT(std::abs(moved.curv[0] - m.curv[0]), 1e-6);
}

TEST(EndConstraint, AnEndNoParameterReachesIsLeftAlone) {
    // One line: its length moves the end along it, never beside it.
    CurvatureModel m = tied_at_origin(0.0);
    m.push_segment(100.0, true, -1, 0.0);
    CurvatureModel moved = m;
    EXPECT_FALSE(meet_end(moved, Pose{100.0, 1e-3, 0.0, 0.0}));
    EXPECT_EQ(moved.lengths, m.lengths);
}
