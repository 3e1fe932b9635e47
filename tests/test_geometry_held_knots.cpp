// Knots held in the least-squares polish (SolveOptions::knot_at,
// knot_weight): a knot a chain shares with a parallel track stays where
// the design search put it, while the nodes alone would slide it
// (design_fit.cpp, design_guided.cpp).
#include "fit/least_squares.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

using namespace railodd::geometry;
using namespace railodd::geometry::fit;

namespace {

// A line, a transition into an arc of R 600 m, the arc, a transition out and
// a line, the start fixed at the origin heading east; the first line
// `first` long.
CurvatureModel curve(double first) {
    CurvatureModel m;
    m.start = {0.0, 0.0, 0.0, 0.0};
    m.start_free = false;
    m.knot_var = {-1};
    m.knot_fixed = {0.0};
    m.push_segment(first, true, -1, 0.0);
    m.curv.push_back(1.0 / 600.0);
    m.push_segment(80.0, true, 0);
    m.push_segment(150.0, true, 0);
    m.push_segment(80.0, true, -1, 0.0);
    m.push_segment(200.0, true, -1, 0.0);
    return m;
}

// Points every 5 m along the curve with its first line 200 m long.
std::vector<Point2> points() {
    const Alignment a = curve(200.0).to_alignment();
    std::vector<Point2> p;
    Pose at = a.start;
    for (const Primitive& q : a.primitives) {
        for (double d = 0.0; d < q.length; d += 5.0) {
            const Pose e = evaluate(at, q, d);
            p.push_back({e.x, e.y});
        }
        at = evaluate(at, q, q.length);
    }
    p.push_back({at.x, at.y});
    return p;
}

double first_knot(const CurvatureModel& m) { return m.lengths[0]; }

} // namespace

TEST(HeldKnots, TheNodesAloneMoveAKnotToThemAndAHeldOneStays) {
    const std::vector<Point2> p = points();
    SolveOptions so;
    so.sigma_m = 0.3;
    so.pin_last = false;
    so.geodesic_acceleration = true;
    so.max_iterations = 200;
    // Started 10 m off, the nodes pull the first knot back towards 200 m
    // (to 203.6: a transition's start is a flat valley, millimetres of
    // offset for metres along).
    CurvatureModel free_knots = curve(210.0);
    solve(free_knots, p, so);
    EXPECT_LT(first_knot(free_knots), 205.0);
    // Held at 210 m (a metre along costing a thousand sigmas), it stays.
    CurvatureModel held = curve(210.0);
    so.knot_at.assign(held.segments() + 1, 0.0);
    so.knot_weight.assign(held.segments() + 1, 0.0);
    so.knot_at[1] = 210.0;
    so.knot_weight[1] = 1e6;
    solve(held, p, so);
    EXPECT_NEAR(first_knot(held), 210.0, 0.01);
    // A knot further on is held by the lengths before it together.
    CurvatureModel second = curve(210.0);
    so.knot_weight[1] = 0.0;
    so.knot_at[2] = 295.0;
    so.knot_weight[2] = 1e6;
    solve(second, p, so);
    EXPECT_NEAR(second.lengths[0] + second.lengths[1], 295.0, 0.01);
}
