// Cutting a chain's fit round the nodes it misses
// (geometry/src/stretch_patch.cpp): which stretches, the runs between them,
// and the chain assembled G2 from the runs' fits and corners across the
// stretches.
#include "stretch_patch.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

using namespace railodd::geometry;

namespace {

using Ranges = std::vector<std::pair<std::size_t, std::size_t>>;

// 41 nodes 10 m apart along the x axis, and a line through them.
std::vector<Point> straight_nodes() {
    std::vector<Point> p;
    for (int i = 0; i <= 40; ++i) {
        p.push_back({10.0 * i, 0.0});
    }
    return p;
}

Alignment line(double from, double len) {
    Alignment a;
    a.start = {from, 0.0, 0.0, 0.0};
    a.primitives.push_back(make_line(len));
    return a;
}

} // namespace

TEST(StretchPatch, AMissedNodeGetsTwoNodesEitherSide) {
    std::vector<Point> p = straight_nodes();
    p[20].y = 3.0;
    const std::vector<char> none(p.size(), 0);
    EXPECT_EQ(missed_stretches(line(0.0, 400.0), p, none, 2.0, 4), (Ranges{{18, 22}}));
    std::vector<char> stray(p.size(), 0);
    stray[20] = 1;
    EXPECT_TRUE(missed_stretches(line(0.0, 400.0), p, stray, 2.0, 4).empty());
    EXPECT_TRUE(missed_stretches(line(0.0, 400.0), p, none, 3.5, 4).empty());
}

TEST(StretchPatch, StretchesNearEachOtherOrAnEndReachAcross) {
    std::vector<Point> p = straight_nodes();
    p[2].y = 3.0;
    p[20].y = 3.0;
    p[24].y = -3.0;
    p[39].y = 3.0;
    const std::vector<char> none(p.size(), 0);
    // [0, 4]: a run of three before it is too short to fit; [18, 22] and
    // [22, 26] meet; [37, 40] runs to the end.
    EXPECT_EQ(missed_stretches(line(0.0, 400.0), p, none, 2.0, 4), (Ranges{{0, 4}, {18, 26}, {37, 40}}));
}

TEST(StretchPatch, RunsLieBetweenTheStretchesSharingTheirEnds) {
    EXPECT_EQ(runs_between({{18, 22}}, 41), (Ranges{{0, 18}, {22, 40}}));
    EXPECT_EQ(runs_between({{0, 4}, {18, 26}, {37, 40}}, 41), (Ranges{{4, 18}, {26, 37}}));
    EXPECT_TRUE(runs_between({{0, 40}}, 41).empty());
    EXPECT_EQ(runs_between({}, 41), (Ranges{{0, 40}}));
}

// A run whose fit failed joins the stretches beside it, and touching
// stretches merge: the runs left are those that fitted.
TEST(StretchPatch, AFailedRunJoinsTheStretchesBesideIt) {
    const Ranges stretches{{0, 4}, {18, 26}, {37, 40}};
    const Ranges runs = runs_between(stretches, 41);
    EXPECT_EQ(with_failed_runs(stretches, runs, {1, 1}), stretches);
    EXPECT_EQ(with_failed_runs(stretches, runs, {0, 1}), (Ranges{{0, 26}, {37, 40}}));
    EXPECT_EQ(with_failed_runs(stretches, runs, {1, 0}), (Ranges{{0, 4}, {18, 40}}));
    EXPECT_EQ(with_failed_runs(stretches, runs, {0, 0}), (Ranges{{0, 40}}));
    EXPECT_EQ(runs_between(with_failed_runs(stretches, runs, {0, 1}), 41), (Ranges{{26, 37}}));
    // The run at the chain's start failed: corners from the start.
    EXPECT_EQ(with_failed_runs({{18, 22}}, runs_between({{18, 22}}, 41), {0, 1}), (Ranges{{0, 22}}));
}

// A kink the first fit missed at [18, 24] and a second run that failed
// (nodes 30-34 zigzag 3 m): corners from node 18 to the chain's end, from
// the pose where the first run's fit ends, within the limit of every node.
TEST(StretchPatch, AFailedRunIsBuiltByCornersWithItsStretch) {
    std::vector<Point> p = straight_nodes();
    for (const std::size_t k : {20u, 21u, 22u}) {
        p[k].y = 3.0;
    }
    for (const std::size_t k : {30u, 32u, 34u}) {
        p[k].y = 3.0;
    }
    const Ranges missed{{18, 24}};
    const Ranges stretches = with_failed_runs(missed, runs_between(missed, p.size()), {1, 0});
    ASSERT_EQ(stretches, (Ranges{{18, 40}}));
    const std::optional<Alignment> patched =
        assemble_patched(p, stretches, {line(0.0, 180.0)}, std::nullopt, std::nullopt, {1000.0, 0.25}, 2.0);
    ASSERT_TRUE(patched);
    ASSERT_NO_THROW(validate(*patched));
    EXPECT_EQ(patched->primitives.front().kind, PrimitiveKind::line);
    EXPECT_NEAR(patched->primitives.front().length, 180.0, 1e-6);
    for (std::size_t k = 0; k < p.size(); ++k) {
        EXPECT_LT(project_point(*patched, p[k].x, p[k].y).distance, 2.0) << k;
    }
}

// Two straight runs either side of a kink of three nodes 3 m aside: the
// corners across [18, 24] start where the first run's fit ends and end where
// the second's begins, G2 at both joints, passing every node of the stretch.
TEST(StretchPatch, TheChainIsAssembledG2) {
    std::vector<Point> p = straight_nodes();
    for (const std::size_t k : {20u, 21u, 22u}) {
        p[k].y = 3.0;
    }
    const Ranges stretches{{18, 24}};
    const std::vector<Alignment> fits{line(0.0, 180.0), line(240.0, 160.0)};
    const std::optional<Alignment> patched =
        assemble_patched(p, stretches, fits, std::nullopt, std::nullopt, {1000.0, 0.25}, 2.0);
    ASSERT_TRUE(patched);
    const Alignment& a = *patched;
    ASSERT_NO_THROW(validate(a));
    EXPECT_NEAR(length(a), 400.0, 2.0);
    const std::vector<double> s = primitive_s(a);
    const std::vector<Pose> starts = primitive_starts(a);
    for (std::size_t i = 0; i + 1 < a.primitives.size(); ++i) {
        const Pose end = evaluate(starts[i], a.primitives[i], a.primitives[i].length);
        EXPECT_LT(std::hypot(end.x - starts[i + 1].x, end.y - starts[i + 1].y), 1e-6) << i;
        EXPECT_LT(std::abs(std::remainder(end.hdg - starts[i + 1].hdg, 2 * std::numbers::pi)), 1e-9) << i;
        EXPECT_LT(std::abs(a.primitives[i].curv_end - a.primitives[i + 1].curv_start), 1e-9) << i;
    }
    for (const std::size_t k : {19u, 20u, 21u, 22u, 23u}) {
        EXPECT_LT(project_point(a, p[k].x, p[k].y).distance, 0.25 + 1e-9) << k;
    }
    EXPECT_EQ(a.primitives.front().kind, PrimitiveKind::line);
    EXPECT_EQ(a.primitives.back().kind, PrimitiveKind::line);
}
