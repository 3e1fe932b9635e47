// The design search's exact polish (geometry/src/fit/design_polish.cpp):
// what it leaves of elements the nodes cannot tell from nothing.
#include "design_fit_support.hpp"
#include "railodd/geometry/alignment.hpp"
#include "railodd/geometry/fit_alignment.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <optional>
#include <vector>

using namespace railodd;
using test::design_search;

namespace {

// Nodes every `step` metres along a design, moved off it by a fixed
// pattern of up to `wobble` metres (the same on every compiler).
std::vector<geometry::Point> nodes_along(const geometry::Alignment& a, double step, double wobble) {
    std::vector<geometry::Point> p;
    const double total = geometry::length(a);
    for (int i = 0; step * i <= total + 1e-9; ++i) {
        const geometry::Pose q = geometry::evaluate(a, step * i);
        const double off = wobble * static_cast<double>((i * 7) % 5 - 2) / 2.0;
        p.push_back({q.x - off * std::sin(q.hdg), q.y + off * std::cos(q.hdg)});
    }
    return p;
}

std::size_t under_a_metre(const geometry::Alignment& a) {
    std::size_t n = 0;
    for (const geometry::Primitive& e : a.primitives) {
        n += e.length < 1.0 ? 1 : 0;
    }
    return n;
}

// A turnout's curve (R 190 m) straight from its switch, no transition:
// n + 1 nodes every `step` metres, leaving the origin heading east.
std::vector<geometry::Point> turnout(double step, int n) {
    geometry::Alignment a;
    a.start = {0.0, 0.0, 0.0, 1.0 / 190.0};
    a.primitives = {geometry::make_arc(step * n, 1.0 / 190.0)};
    return nodes_along(a, step, 0.03);
}

} // namespace

// The curvature jump at a switch is drawn as a transition (every link G2),
// whose length the nodes cannot tell: the polish drove it to its 0.5 m floor
// (VDE 8.2: 288 of its 360 elements under a metre). It is held at
// switch_transition_m, 2 m, which lies 1 mm inside a curve of R 150 m. The
// branch drawn from its switch (a tied start) and towards it (a tied end).
TEST(DesignPolish, ATurnoutsCurveMeetsItsSwitchThroughTwoMetresAtLeast) {
    for (const bool towards : {false, true}) {
        std::vector<geometry::Point> p = turnout(6.0, 12);
        std::optional<geometry::Pose> start = geometry::Pose{0.0, 0.0, 0.0, 0.0}, end;
        if (towards) {
            std::reverse(p.begin(), p.end());
            end = geometry::Pose{0.0, 0.0, M_PI, 0.0};
            start.reset();
        }
        const geometry::FitResult fit = geometry::fit_alignment(p, start, end, design_search());
        const auto& el = fit.alignment.primitives;
        const geometry::Primitive& at_switch = towards ? el.back() : el.front();
        EXPECT_EQ(towards ? at_switch.curv_end : at_switch.curv_start, 0.0) << towards;
        EXPECT_GE(at_switch.length, 2.0 - 1e-9) << towards;
        EXPECT_LT(at_switch.length, 20.0) << towards;
        EXPECT_EQ(under_a_metre(fit.alignment), 0u) << towards;
        EXPECT_LT(fit.quality.followed_max_m, 0.15) << towards;
    }
}

// A curve of two transitions meeting at its apex (no arc between), shorter
// than the transition-length rule would have them: the search draws no arc
// under 10 m, and the polish shrank the one it drew to its 0.5 m floor
// (0.5-0.6 m here). The arc is taken out where the nodes' cost rises by
// less than its length parameter's penalty.
TEST(DesignPolish, TransitionsMeetingAtTheApexKeepNoArcBetweenThem) {
    for (const double r : {600.0, 1200.0, 2400.0}) {
        geometry::Alignment truth;
        truth.start = {0.0, 0.0, 0.3, 0.0};
        truth.primitives = {geometry::make_line(150.0), geometry::make_spiral(40.0, 0.0, 1.0 / r),
                            geometry::make_spiral(40.0, 1.0 / r, 0.0), geometry::make_line(150.0)};
        const geometry::FitResult fit =
            geometry::fit_alignment(nodes_along(truth, 8.0, 0.03), std::nullopt, std::nullopt, design_search());
        EXPECT_EQ(under_a_metre(fit.alignment), 0u) << "R " << r;
        EXPECT_LE(fit.alignment.primitives.size(), 4u) << "R " << r;
        EXPECT_LT(fit.quality.max_m, 0.1) << "R " << r;
    }
}

// Several such curves along one chain, on nodes 8-20 m apart: the polish
// shrank each arc to its floor, and taking them all out at once, or one of
// them, can leave the solve shrinking another (Cologne: 76 arcs at the
// 0.5 m floor mid-chain, 30 after). Each is taken out, in rounds, where the
// nodes allow.
TEST(DesignPolish, EveryApexAlongAChainLosesItsArc) {
    geometry::Alignment truth;
    truth.start = {0.0, 0.0, 0.1, 0.0};
    truth.primitives.push_back(geometry::make_line(150.0));
    for (const auto& [r, l] : {std::pair{700.0, 40.0}, {-1500.0, 60.0}, {900.0, 35.0}, {-2600.0, 80.0}, {1800.0, 55.0}}) {
        truth.primitives.push_back(geometry::make_spiral(l, 0.0, 1.0 / r));
        truth.primitives.push_back(geometry::make_spiral(l, 1.0 / r, 0.0));
        truth.primitives.push_back(geometry::make_line(160.0));
    }
    for (const double step : {8.0, 12.0, 16.0, 20.0}) {
        const geometry::FitResult fit =
            geometry::fit_alignment(nodes_along(truth, step, 0.05), std::nullopt, std::nullopt, design_search());
        EXPECT_EQ(under_a_metre(fit.alignment), 0u) << "nodes every " << step << " m";
        EXPECT_LT(fit.quality.max_m, 0.15) << "nodes every " << step << " m";
    }
}
