// loops_back: a fit that loops keeps every node near the curve, so only its
// length and turning give it away. Exact alignments against sampled nodes.
#include "railodd/geometry/fit_alignment.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <random>

using namespace railodd::geometry;

namespace {

constexpr double pi = std::numbers::pi;

// Nodes every `step` metres along an alignment, with optional lateral noise.
std::vector<Point> nodes_along(const Alignment& a, double step, double noise = 0.0, unsigned seed = 1) {
    std::mt19937 rng(seed);
    std::normal_distribution<double> n(0.0, noise);
    std::vector<Point> pts;
    const double len = length(a);
    for (double s = 0.0; s <= len + 1e-9; s += step) {
        const Pose p = evaluate(a, std::min(s, len));
        const double d = noise > 0 ? n(rng) : 0.0;
        pts.push_back({p.x - d * std::sin(p.hdg), p.y + d * std::cos(p.hdg)});
    }
    return pts;
}

Alignment straight(double len) {
    Alignment a;
    a.primitives = {make_line(len)};
    return a;
}

// A right-angle curve with transitions: R 300 m, 60 m spirals.
Alignment curve() {
    Alignment a;
    const double k = 1.0 / 300.0;
    const double arc = 0.5 * pi / k - 60.0; // the two spirals turn as much as 60 m of arc
    a.primitives = {make_line(200.0), make_spiral(60.0, 0.0, k), make_arc(arc, k), make_spiral(60.0, k, 0.0),
                    make_line(200.0)};
    return a;
}

} // namespace

TEST(FitLoops, AlignmentsThatFollowTheirNodesDoNotLoop) {
    EXPECT_FALSE(loops_back(straight(600.0), nodes_along(straight(600.0), 25.0)));
    EXPECT_FALSE(loops_back(curve(), nodes_along(curve(), 15.0)));
    // Noise adds turning and length to the polyline, never to the fit.
    EXPECT_FALSE(loops_back(curve(), nodes_along(curve(), 10.0, 0.3)));
    // Sparse nodes on a curve: the polyline is shorter than the arc, within the slack.
    EXPECT_FALSE(loops_back(curve(), nodes_along(curve(), 60.0)));
}

TEST(FitLoops, AFullCircleAtTheCurvatureBoundIsALoop) {
    // 300 m straight, one full circle of R 10 m (63 m), 300 m straight: every
    // node of the straight 600 m polyline lies on the curve or within 20 m.
    Alignment looped;
    looped.primitives = {make_line(300.0), make_arc(2 * pi * 10.0, 0.1), make_line(300.0)};
    const std::vector<Point> nodes = nodes_along(straight(600.0), 25.0);
    EXPECT_TRUE(loops_back(looped, nodes));
    // Half a circle more turning than the nodes show, and no extra length
    // beyond the slack, is not a loop yet.
    Alignment s_bend;
    s_bend.primitives = {make_line(280.0), make_arc(10.0 * pi / 2, 0.1), make_arc(10.0 * pi / 2, -0.1),
                         make_line(280.0)};
    EXPECT_FALSE(loops_back(s_bend, nodes));
}

TEST(FitLoops, ExtraLengthAloneIsALoop) {
    // A spiral out and back that wanders 40 % beyond the nodes' polyline.
    Alignment wander;
    wander.primitives = {make_line(100.0), make_spiral(150.0, 0.0, 0.02), make_spiral(150.0, 0.02, 0.0),
                         make_line(100.0)};
    const std::vector<Point> nodes = nodes_along(straight(360.0), 20.0);
    EXPECT_TRUE(loops_back(wander, nodes));
}

TEST(FitLoops, ALoopBetweenTwoNodesIsALoop) {
    // A full circle of R 70 m (440 m) halfway along 10 km of straight: 4.4 %
    // longer than the nodes' polyline and one turn, within the whole chain's
    // slack; but the two nodes beside it, 25 m apart, have feet 465 m apart.
    Alignment looped;
    looped.primitives = {make_line(5000.0), make_arc(2 * pi * 70.0, 1.0 / 70.0), make_line(5000.0)};
    std::vector<Point> nodes = nodes_along(straight(10000.0), 25.0, 0.3);
    for (Point& q : nodes) {
        q.x += 12.5; // no node where the circle leaves the line, whose foot is either end of it
    }
    nodes.pop_back();
    EXPECT_TRUE(loops_back(looped, nodes));
    EXPECT_FALSE(loops_back(straight(10000.0), nodes));
}
