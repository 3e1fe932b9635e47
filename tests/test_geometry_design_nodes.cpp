// Which left-out nodes a design-search fit is excused from following
// (geometry/src/fit/design_fit.cpp, followed_max): strays shown out of line
// by their neighbours, not stretches the design missed.
#include "fit/design_pass.hpp"

#include <gtest/gtest.h>

#include <vector>

using namespace railodd::geometry;

namespace {

// A straight line along x, 700 m, and nodes every 100 m on it.
Alignment straight() {
    Alignment a;
    a.start = Pose{0.0, 0.0, 0.0, 0.0};
    a.primitives.push_back(make_line(700.0));
    return a;
}

std::vector<Point> on_line() {
    std::vector<Point> p;
    for (int i = 0; i <= 7; ++i) {
        p.push_back({100.0 * i, 0.0});
    }
    return p;
}

} // namespace

TEST(DesignNodes, AStrayBetweenFollowedNodesIsExcused) {
    std::vector<Point> p = on_line();
    p[3].y = 20.0;
    std::vector<double> w(p.size(), 1.0);
    w[3] = 0.0;
    EXPECT_NEAR(fit::followed_max(straight(), p, w), 0.0, 1e-9);
    p[4].y = -15.0;
    w[4] = 0.0;
    EXPECT_NEAR(fit::followed_max(straight(), p, w), 0.0, 1e-9) << "two side by side are a stray pair";
}

TEST(DesignNodes, ANodeWithoutTwoWitnessesEachSideCounts) {
    std::vector<Point> p = on_line();
    p[1].y = 17.0;
    std::vector<double> w(p.size(), 1.0);
    w[1] = 0.0;
    EXPECT_NEAR(fit::followed_max(straight(), p, w), 17.0, 1e-6);
}

TEST(DesignNodes, AStretchLeftOutCounts) {
    std::vector<Point> p = on_line();
    std::vector<double> w(p.size(), 1.0);
    for (int i = 2; i <= 4; ++i) {
        p[i].y = 10.0 * i;
        w[i] = 0.0;
    }
    EXPECT_NEAR(fit::followed_max(straight(), p, w), 40.0, 1e-6);
}
