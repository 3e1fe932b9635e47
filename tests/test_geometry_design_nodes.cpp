// Which left-out nodes a design-search fit is excused from following
// (geometry/src/fit/design_fit.cpp, followed_max): strays shown out of line
// by their neighbours, not stretches the design missed.
#include "fit/design_pass.hpp"

#include <gtest/gtest.h>

#include <utility>
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

// Nodes every 100 m on it, those at `off` moved sideways by the given
// amounts and left out of the fit; the furthest node the fit must answer for.
double followed(const std::vector<std::pair<int, double>>& off, bool tied_start = false, bool tied_end = false) {
    std::vector<Point> p;
    for (int i = 0; i <= 7; ++i) {
        p.push_back({100.0 * i, 0.0});
    }
    std::vector<double> w(p.size(), 1.0);
    for (const auto& [i, y] : off) {
        p[static_cast<std::size_t>(i)].y = y;
        w[static_cast<std::size_t>(i)] = 0.0;
    }
    return fit::followed_max(straight(), p, fit::strays(w, tied_start, tied_end));
}

} // namespace

TEST(DesignNodes, AStrayBetweenFollowedNodesIsExcused) {
    EXPECT_NEAR(followed({{3, 20.0}}), 0.0, 1e-9);
    EXPECT_NEAR(followed({{3, 20.0}, {4, -15.0}}), 0.0, 1e-9) << "two side by side are a stray pair";
}

TEST(DesignNodes, ANodeWithoutTwoWitnessesEachSideCounts) {
    EXPECT_NEAR(followed({{1, 17.0}}), 17.0, 1e-6);
    EXPECT_NEAR(followed({{6, -9.0}}), 9.0, 1e-6);
}

// A tied end's pose witnesses as a node beside it does: the second node of
// a chain tied at its switch, left out, is a stray; without the tie, or
// with the tie at the other end, it counts.
TEST(DesignNodes, ATiedEndWitnessesTheNodeBesideIt) {
    EXPECT_NEAR(followed({{1, 17.0}}, true, false), 0.0, 1e-9);
    EXPECT_NEAR(followed({{6, -9.0}}, false, true), 0.0, 1e-9);
    EXPECT_NEAR(followed({{1, 17.0}}, false, true), 17.0, 1e-6);
    EXPECT_NEAR(followed({{1, 17.0}, {2, 12.0}}, true, false), 0.0, 1e-9) << "a stray pair beside the tie";
    EXPECT_NEAR(followed({{1, 17.0}, {2, 12.0}}), 17.0, 1e-6) << "the same pair beside a free end";
}

TEST(DesignNodes, AStretchLeftOutCounts) {
    EXPECT_NEAR(followed({{2, 20.0}, {3, 30.0}, {4, 40.0}}), 40.0, 1e-6);
}
