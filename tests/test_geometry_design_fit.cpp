// The design search as a chain's fit (FitMethod::design_search,
// geometry/src/fit/design_fit.cpp) on routes of known design
// (synthetic/alignment_truth): near the true centreline, about the design's
// element count, the noise read from the nodes, tied ends met.
#include "design_fit_support.hpp"
#include "railodd/geometry/fit_alignment.hpp"
#include "railodd/truth/alignment_truth.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <stdexcept>
#include <string>
#include <tuple>
#include <vector>

using namespace railodd;
using test::design_search;

namespace {

// Nodes every `step` metres on a curve of radius r leaving the origin
// heading east, turning left: n + 1 of them, the inner ones moved `wobble`
// in and out by turns.
std::vector<geometry::Point> turnout_nodes(double r, double step, int n, double wobble) {
    std::vector<geometry::Point> p;
    for (int i = 0; i <= n; ++i) {
        const double rr = r + (i == 0 || i == n ? 0.0 : (i % 2 == 0 ? wobble : -wobble));
        p.push_back({rr * std::sin(step * i / r), r - rr * std::cos(step * i / r)});
    }
    return p;
}

// The design search's fit of a branch tied at its start to a switch on a
// straight through track at the origin, heading east.
geometry::FitResult from_switch(const std::vector<geometry::Point>& nodes) {
    geometry::FitResult fit = geometry::fit_alignment(nodes, geometry::Pose{0.0, 0.0, 0.0, 0.0}, std::nullopt, design_search());
    if (fit.alignment.primitives.empty()) {
        throw std::runtime_error("no alignment");
    }
    return fit;
}

} // namespace

TEST(DesignFit, OsmLikeNodesGiveTheDesign) {
    std::vector<double> max_dev;
    for (int seed = 1000; seed < 1010; ++seed) {
        truth::TruthOptions t;
        t.sigma_m = 0.3;
        const truth::TruthRoute r = truth::make_route(static_cast<std::uint64_t>(seed), t);
        const geometry::FitResult fit = geometry::fit_alignment(r.nodes, std::nullopt, std::nullopt, design_search());
        geometry::validate(fit.alignment);
        const truth::TruthScore s = truth::score(r, fit.alignment);
        max_dev.push_back(s.deviation_max_m);
        EXPECT_LT(s.deviation_p95_m, 0.8) << "seed " << seed;
        EXPECT_LE(s.fit_elements, s.design_elements * 3 / 2) << "seed " << seed;
        EXPECT_GT(fit.quality.noise_sigma_m, 0.7 * 0.3) << "seed " << seed;
        EXPECT_LT(fit.quality.noise_sigma_m, 1.6 * 0.3) << "seed " << seed;
        EXPECT_LE(s.spurious_sign_changes, 1) << "seed " << seed;
    }
    std::sort(max_dev.begin(), max_dev.end());
    EXPECT_LT(max_dev[max_dev.size() / 2], 1.0);
}

// A single sparse route's estimate swings with rounding (seed 1000: 1.05
// built by gcc, 0.69 by clang, where the search takes another structure);
// the routes' median is what the noise estimate is held to.
TEST(DesignFit, SparseNodesKeepTheElementCountAndTheNoise) {
    std::vector<double> ratio;
    for (int seed = 1000; seed < 1010; ++seed) {
        truth::TruthOptions t;
        t.sigma_m = 1.0;
        t.spacing = truth::Spacing::sparse;
        const truth::TruthRoute r = truth::make_route(static_cast<std::uint64_t>(seed), t);
        const geometry::FitResult fit = geometry::fit_alignment(r.nodes, std::nullopt, std::nullopt, design_search());
        const truth::TruthScore s = truth::score(r, fit.alignment);
        EXPECT_LE(s.fit_elements, s.design_elements * 3 / 2) << "seed " << seed;
        EXPECT_GT(fit.quality.noise_sigma_m, 0.6) << "seed " << seed;
        EXPECT_LT(fit.quality.noise_sigma_m, 1.6) << "seed " << seed;
        ratio.push_back(fit.quality.noise_sigma_m);
    }
    std::sort(ratio.begin(), ratio.end());
    EXPECT_GT(ratio[ratio.size() / 2], 0.85);
    EXPECT_LT(ratio[ratio.size() / 2], 1.2);
}

// Within the chain fit's tolerances (0.1 mm, 1e-6 rad; chain_fit.cpp splices
// a stretch by corners beyond them), and with the routes turned so that their
// headings run past pi: the ties' headings are normalised, the design's
// integrated. Counted as a full turn off, the end was never met and the
// frame's design, a fraction of a millimetre off, was kept (VDE 8.2: 58 of
// 160 spliced ends).
TEST(DesignFit, TiedEndsAreMet) {
    truth::TruthOptions t;
    t.sigma_m = 0.3;
    t.outlier_fraction = 0.0;
    t.length_m = 3000.0;
    for (int seed = 1000; seed < 1005; ++seed) {
        for (const double turn : {0.0, 3.0, -3.0}) {
            const truth::TruthRoute r = truth::make_route(static_cast<std::uint64_t>(seed), t);
            const auto turned = [](geometry::Pose q, double by) {
                const double c = std::cos(by), s = std::sin(by);
                return geometry::Pose{c * q.x - s * q.y, s * q.x + c * q.y, std::remainder(q.hdg + by, 2 * M_PI),
                                      q.curvature};
            };
            const geometry::Pose start = turned(geometry::evaluate(r.design, 0.0), turn);
            const geometry::Pose end = turned(geometry::evaluate(r.design, geometry::length(r.design)), turn);
            std::vector<geometry::Point> nodes;
            for (const geometry::Point& q : r.nodes) {
                const geometry::Pose m = turned({q.x, q.y, 0.0, 0.0}, turn);
                nodes.push_back({m.x, m.y});
            }
            nodes.front() = {start.x, start.y};
            nodes.back() = {end.x, end.y};
            const geometry::FitResult fit = geometry::fit_alignment(nodes, start, end, design_search());
            const geometry::Pose a = geometry::evaluate(fit.alignment, 0.0);
            const geometry::Pose b = geometry::evaluate(fit.alignment, geometry::length(fit.alignment));
            const std::string at = "seed " + std::to_string(seed) + " turned " + std::to_string(turn);
            EXPECT_NEAR(a.x, start.x, 1e-6) << at;
            EXPECT_NEAR(a.y, start.y, 1e-6) << at;
            EXPECT_NEAR(a.hdg, start.hdg, 1e-8) << at;
            EXPECT_LT(std::hypot(b.x - end.x, b.y - end.y), 1e-4) << at;
            EXPECT_NEAR(std::remainder(b.hdg - end.hdg, 2 * M_PI), 0.0, 1e-6) << at;
            geometry::Alignment back = fit.alignment;
            back.start = turned(back.start, -turn);
            EXPECT_LT(truth::score(r, back).deviation_max_m, 1.5) << at;
        }
    }
}

// A stray node where nodes are sparse (issue 37): beside a free end, 225 m
// from it, 8 m off a straight. Fitted, it costs a few short elements and
// leaves no residual; the design leaves it out instead, since that costs less
// than the elements (one parameter for the node's own position).
TEST(DesignFit, AStrayNodeWhereNodesAreSparseIsLeftOut) {
    std::vector<geometry::Point> nodes{{0.0, 0.3}, {225.0, -8.0}, {288.0, -0.1}, {536.0, 0.25}};
    for (int i = 0; i < 12; ++i) {
        nodes.push_back({786.0 + 250.0 * i, 0.3 * std::sin(1.7 * i)});
    }
    const geometry::FitResult fit = geometry::fit_alignment(nodes, std::nullopt, std::nullopt, design_search());
    EXPECT_GE(fit.quality.outliers, 1u);
    EXPECT_LE(fit.alignment.primitives.size(), 2u);
    const double total = geometry::length(fit.alignment);
    for (double s = 0.0; s <= total; s += 5.0) {
        EXPECT_LT(std::abs(geometry::evaluate(fit.alignment, s).y), 1.0) << "at s " << s;
    }
}

// Beside a free end a node is left out only where it lies off the chord
// between its neighbours. Sparse nodes at 0.1 m, two on a 416 m straight
// before the first curve: left out, the second let the free start swing
// onto a 433 m transition, 32 m off the centreline.
TEST(DesignFit, AGoodNodeBesideAFreeEndIsFollowed) {
    const truth::TruthRoute r = test::truth_route(1090, 0.1, 0.0, truth::Spacing::sparse);
    const geometry::FitResult fit = geometry::fit_alignment(r.nodes, std::nullopt, std::nullopt, design_search());
    EXPECT_LT(truth::score(r, fit.alignment).deviation_max_m, 1.5);
}

// Two strays side by side (8.3 and 3.9 m off, dense nodes at 0.3 m on a
// 32 km route) that the design followed by curves of R 21 m, leaving out
// the good nodes before them: taken back together for the pair left out
// (design_nodes.cpp, add_pair_swaps). Swapped one at a time, the other
// stray kept the design off the node taken back; the route was 9.0 m off.
TEST(DesignFit, TwoStraysSideBySideGiveWayToTheGoodNodesBesideThem) {
    truth::TruthOptions t;
    t.sigma_m = 0.3;
    t.spacing = truth::Spacing::dense;
    t.length_m = 32000.0;
    const truth::TruthRoute r = truth::make_route(1024, t);
    const geometry::FitResult fit = geometry::fit_alignment(r.nodes, std::nullopt, std::nullopt, design_search());
    const truth::TruthScore s = truth::score(r, fit.alignment);
    EXPECT_LT(s.deviation_max_m, 1.0);
    EXPECT_LE(s.fit_elements, s.design_elements);
}

// Dense noisy nodes (every 5-15 m at 1 m): the transitions' lengths are
// held to the design rule in the exact polish as in the search, so the arcs
// between them keep their radii (without, the median error on these routes
// was 1.95 %; 1.25 % with).
TEST(DesignFit, DenseNoisyNodesKeepTheRadii) {
    std::vector<double> errors;
    for (int seed = 1000; seed < 1024; ++seed) {
        truth::TruthOptions t;
        t.sigma_m = 1.0;
        t.spacing = truth::Spacing::dense;
        const truth::TruthRoute r = truth::make_route(static_cast<std::uint64_t>(seed), t);
        const geometry::FitResult fit = geometry::fit_alignment(r.nodes, std::nullopt, std::nullopt, design_search());
        const truth::TruthScore s = truth::score(r, fit.alignment);
        errors.insert(errors.end(), s.radius_errors.begin(), s.radius_errors.end());
    }
    std::sort(errors.begin(), errors.end());
    ASSERT_FALSE(errors.empty());
    std::printf("median radius error %.2f %% over %zu arcs\n", 100 * errors[errors.size() / 2], errors.size());
    EXPECT_LT(errors[errors.size() / 2], 0.015);
}

// OSM-like nodes at 2 m: gentle curves whose nodes lie 1-3 sigma to one
// side of a design that skips them. Weighted by Tukey's biweight (a half at
// 2.5 sigma) they no longer paid for the curve's elements, and one long
// transition stood for a line, a transition and a curve (9.3 and 7.9 m
// off); weighted whole within the cut they do (issue 37's limit at 2 m: 5 m).
TEST(DesignFit, NodesToOneSideWithinTheCutKeepTheirWeight) {
    truth::TruthOptions t;
    t.sigma_m = 2.0;
    for (const int seed : {1290, 1165}) {
        const truth::TruthRoute r = truth::make_route(static_cast<std::uint64_t>(seed), t);
        const geometry::FitResult fit = geometry::fit_alignment(r.nodes, std::nullopt, std::nullopt, design_search());
        EXPECT_LT(truth::score(r, fit.alignment).deviation_max_m, 5.0) << "seed " << seed;
    }
}

// Each pass takes the last one's design as its frame. On this route
// (OSM-like nodes at 0.3 m, 1 % outliers) a pass's design missed a stretch
// and the passes in its frame drifted further (7.88 m off the true
// centreline); a pass that costs more on the map than the one before is not
// taken (0.6-1.2 m, as the compiler rounds: gcc and clang differ here).
TEST(DesignFit, APassWorseThanTheLastIsNotTaken) {
    truth::TruthOptions t;
    t.sigma_m = 0.3;
    t.outlier_fraction = 0.01;
    const truth::TruthRoute r = truth::make_route(1108, t);
    const geometry::FitResult fit = geometry::fit_alignment(r.nodes, std::nullopt, std::nullopt, design_search());
    EXPECT_LT(truth::score(r, fit.alignment).deviation_max_m, 2.0);
}

// A route of known design between two switches (both ends tied), sparse
// nodes at 0.3 m: the search in the first pass's frame, a beam, loses a
// stretch the first pass had (1.72 m off without the rival); the last pass's
// design is its rival, so it is kept (0.26 m).
TEST(DesignFit, TheSearchKeepsTheLastPassAsARival) {
    const truth::TruthRoute r = test::truth_route(1199, 0.3, 0.01, truth::Spacing::sparse);
    const geometry::FitResult fit = geometry::fit_alignment(r.nodes, test::pose_at(r.design, r.nodes.front()),
                                                            test::pose_at(r.design, r.nodes.back()), design_search());
    EXPECT_LT(truth::score(r, fit.alignment).deviation_max_m, 1.0);
}

// OSM-like nodes at 0.3 m: the first search of each pass keeps the 5 m
// grid's knots, and its design has 21 elements for the 17 of the truth
// (0.32 m off); searched again with those knots as candidates it takes the
// design's own count.
TEST(DesignFit, TheSearchRunsAgainFromItsOwnKnots) {
    const truth::TruthRoute r = test::truth_route(1034, 0.3, 0.01, truth::Spacing::osm);
    const geometry::FitResult fit = geometry::fit_alignment(r.nodes, std::nullopt, std::nullopt, design_search());
    const truth::TruthScore s = truth::score(r, fit.alignment);
    EXPECT_LE(s.fit_elements, s.design_elements);
    EXPECT_LT(s.deviation_max_m, 1.0); // 0.21 m built by gcc, 0.58 by clang
}

// The last search searches every run of five elements again, tied to the
// design around it (research_windows): OSM-like truth routes at 0.3 m.
// Without the windows seed 1008 has 25 elements for the design's 22 (and
// 1023 had 23 for 21 under the MAD noise estimate). One more than the
// design is allowed: with the noise as a capped root mean square, 1008
// keeps a compound R 150 / 173 m curve (23 elements, 0.53 m off).
TEST(DesignFit, TheLastSearchSearchesItsWindowsAgain) {
    for (const int seed : {1008, 1023}) {
        const truth::TruthRoute r = test::truth_route(seed, 0.3, 0.0, truth::Spacing::osm);
        const geometry::FitResult fit = geometry::fit_alignment(r.nodes, std::nullopt, std::nullopt, design_search());
        const truth::TruthScore s = truth::score(r, fit.alignment);
        EXPECT_LE(s.fit_elements, s.design_elements + 1) << "seed " << seed;
        EXPECT_LT(s.deviation_max_m, 1.0) << "seed " << seed;
    }
}

// A stray after two good nodes on OSM-like spacing at 0.3 m: the first
// pass's screen left the good ones out (6 and 8 m off the design, 7.6 m off
// the centreline); taken back in place of the stray, the design follows
// them. A stray the design would only bend to is not taken back: on dense
// nodes two strays side by side (4.9 and 9.4 m off) pulled it 4.7 m off;
// at 0.1 m a stray 9.1 m off taken back in place of a good node was
// followed by a bend through it and the next stray (9.1 m off).
TEST(DesignFit, ALeftOutNodeIsTakenBackWhereTheDesignThenFollowsIt) {
    const std::tuple<int, truth::Spacing, double> routes[] = {
        {1096, truth::Spacing::osm, 0.3}, {1086, truth::Spacing::dense, 0.3}, {1222, truth::Spacing::dense, 0.1}};
    for (const auto& [seed, spacing, sigma] : routes) {
        const truth::TruthRoute r = test::truth_route(seed, sigma, 0.01, spacing);
        const geometry::FitResult fit = geometry::fit_alignment(r.nodes, std::nullopt, std::nullopt, design_search());
        EXPECT_LT(truth::score(r, fit.alignment).deviation_max_m, 1.0) << "seed " << seed;
    }
}

// Two strays side by side (7.8 and 8.5 m off a curve of R 1,556 m, OSM-like
// nodes at 0.3 m) with a good node after them: the design bent to the pair,
// the good node looked off it and was the one the node trials left out
// (8.7 m off the centreline). The pair before the suspect is tried too.
TEST(DesignFit, TwoStraysSideBySideBeforeAGoodNodeAreLeftOut) {
    const truth::TruthRoute r = test::truth_route(1214, 0.3, 0.01, truth::Spacing::osm);
    const geometry::FitResult fit = geometry::fit_alignment(r.nodes, std::nullopt, std::nullopt, design_search());
    const truth::TruthScore s = truth::score(r, fit.alignment);
    EXPECT_LT(s.deviation_max_m, 1.0);
    EXPECT_LE(s.fit_elements, s.design_elements + 1);
}

// A stray the design follows smoothly through a curve on sparse nodes
// (0.3 m, a node 6 m off between nodes 50 m apart): it neither bends to it
// nor lies far, so only the left-out good node beside it was suspect, and
// its take-back trials did not leave the stray out in its place (7.1 m off,
// 8.2 m from the centreline). A neighbour off the trend of the kept nodes
// around it is now tried in its place (1.6 m).
TEST(DesignFit, AStrayFollowedSmoothlyIsLeftOutForTheGoodNodeBesideIt) {
    const truth::TruthRoute r = test::truth_route(1297, 0.3, 0.01, truth::Spacing::sparse);
    const geometry::FitResult fit = geometry::fit_alignment(r.nodes, std::nullopt, std::nullopt, design_search());
    EXPECT_LT(truth::score(r, fit.alignment).deviation_max_m, 2.0);
}

// A stray inside a tight curve on sparse nodes (0.3 m, a node 9 m off in an
// arc of 217 m, nodes 60 m apart): its turn does not show against the
// curve's, its distance from the cubic through its neighbours does (9.2 m
// off before, the design hooked to it).
TEST(DesignFit, AStrayInATightCurveOnSparseNodesIsLeftOut) {
    const truth::TruthRoute r = test::truth_route(1102, 0.3, 0.01, truth::Spacing::sparse);
    const geometry::FitResult fit = geometry::fit_alignment(r.nodes, std::nullopt, std::nullopt, design_search());
    EXPECT_LT(truth::score(r, fit.alignment).deviation_max_m, 1.0);
}

// A free start before sparse nodes at 0.1 m (a 343 m straight with two
// nodes on it, then a curve of 890 m): a transition at a chain end pays the
// length prior where it is longer than the rule, so the start does not
// swing on a 470 m S-shaped transition across the gap (5.0 m off before).
TEST(DesignFit, AFreeEndTransitionIsNoLongerThanTheRule) {
    const truth::TruthRoute r = test::truth_route(1124, 0.1, 0.0, truth::Spacing::sparse);
    const geometry::FitResult fit = geometry::fit_alignment(r.nodes, std::nullopt, std::nullopt, design_search());
    const truth::TruthScore s = truth::score(r, fit.alignment);
    EXPECT_LT(s.deviation_max_m, 1.0);
    EXPECT_EQ(s.spurious_sign_changes, 0);
}

// A Cologne branch whose switch node was mapped 2.65 m off the through
// track's design: its tie (the through track's pose there) is where the
// branch meets the switch, so the branch is fitted and judged from there,
// not from the mapped node (2.65 m off before: a corner chain). It leaves
// with the through track's curvature (R 125 m) and turns the other way;
// the transition between must end between the switch and the next node,
// 82 m on, where no knot is tried. The search priced as elements close
// finds a design through every node (before, it left the middle node out
// 5.0 m off): the furthest node is the mapped switch node, 2.65 m from the
// tie.
TEST(DesignFit, ATiedEndStartsWhereItsTieIs) {
    const std::vector<geometry::Point> nodes{{-2838.533, -2981.243}, {-2776.479, -2927.890}, {-2686.861, -2860.622}};
    const geometry::Pose start{-2837.031, -2983.427, 0.602600, 0.00798899};
    const geometry::FitResult fit = geometry::fit_alignment(nodes, start, std::nullopt, design_search());
    const geometry::Primitive& first = fit.alignment.primitives.front();
    EXPECT_NEAR(fit.alignment.start.x, start.x, 1e-9);
    EXPECT_NEAR(fit.alignment.start.y, start.y, 1e-9);
    EXPECT_EQ(first.curv_start, start.curvature);
    EXPECT_LT(fit.quality.followed_max_m, 0.1);
    EXPECT_NEAR(fit.quality.max_m, 2.65, 0.01); // the mapped switch node
    EXPECT_EQ(fit.quality.outliers, 0u);
}

// Two Cologne branches between two switches whose ties lie 5-9 degrees off
// the nodes' line: a spur of seven nodes along 800 m of straight track, the
// middle ones 360-370 m apart (way 575059128), and a link of five along
// 500 m. Each left out a node on the line of its neighbours as a stray, and
// the design swung 68 m and 27 m off it between the ties: a node left out
// costs its offset from the design in units of a stray's.
TEST(DesignFit, ALeftOutNodeDoesNotLetTheDesignSwingAway) {
    const std::vector<geometry::Point> spur{{8368.500, 9148.680}, {8370.050, 9179.477}, {8369.660, 9538.097},
                                            {8369.110, 9912.370}, {8368.766, 9925.719}, {8368.312, 9937.289},
                                            {8367.276, 9948.846}};
    const geometry::FitResult a = geometry::fit_alignment(spur, geometry::Pose{8368.301, 9148.711, 1.418013, -0.000409},
                                                          geometry::Pose{8367.277, 9948.846, 1.718143, 0.001975},
                                                          design_search());
    EXPECT_LT(a.quality.max_m, 1.0);
    const std::vector<geometry::Point> link{{-2462.108, -577.643}, {-2473.092, -561.218}, {-2616.579, -311.098},
                                            {-2686.119, -189.704}, {-2718.969, -144.632}};
    const geometry::FitResult b = geometry::fit_alignment(link, geometry::Pose{-2462.097, -577.634, 2.253539, -0.001900},
                                                          geometry::Pose{-2720.481, -145.511, 2.097512, 0.000005},
                                                          design_search());
    EXPECT_LT(b.quality.max_m, 2.0); // the end tie itself lies 1.75 m from the last node
}

// A branch leaving a straight through track at its switch on a turnout's
// curve (R 300 m from the switch, no transition): its tie holds position,
// heading and curvature (the link stays G2), and a short transition leads
// into the curve, within 0.15 m of every node.
TEST(DesignFit, ABranchLeavesItsSwitchThroughAShortTransition) {
    const geometry::FitResult fit = from_switch(turnout_nodes(300.0, 8.0, 12, 0.05));
    const auto& first = fit.alignment.primitives.front();
    EXPECT_EQ(first.curv_start, 0.0);
    EXPECT_LT(first.length, 20.0);
    EXPECT_NEAR(first.curv_end, 1.0 / 300.0, 0.2 / 300.0);
    EXPECT_LT(fit.quality.followed_max_m, 0.15);
}

// A few nodes on a hook tighter than any turnout's (R 40 m) still leave the
// switch at its curvature.
TEST(DesignFit, ATightHookStartsAtItsSwitchsCurvature) {
    const geometry::FitResult fit = from_switch(turnout_nodes(40.0, 4.0, 4, 0.0));
    EXPECT_EQ(fit.alignment.primitives.front().curv_start, 0.0);
}
