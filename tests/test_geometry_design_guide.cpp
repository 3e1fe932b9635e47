// A parallel track's curvature as the design search's prior
// (geometry/src/fit/design_guide.cpp): concentric where the chain runs
// beside it either way, nothing where it only passes at a turnout's angle or
// where the chain's own design says otherwise.
#include "fit/design_guide.hpp"
#include "fit/reference_line.hpp"

#include "railodd/geometry/alignment.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <utility>
#include <vector>

using namespace railodd::geometry;
using namespace railodd::geometry::fit;

namespace {

constexpr double R = 1000.0, offset = 4.0, length = 600.0;

// A guide curving left at radius R from the origin heading east.
IndexedAlignment guide() {
    Alignment a;
    a.start = {0.0, 0.0, 0.0, 0.0};
    a.primitives = {make_arc(length, 1.0 / R)};
    return IndexedAlignment(a);
}

// A reference every metre along the guide's concentric circle `d` to its
// left (radius R - d), from `from` to `to` (radians round the centre),
// either way.
ReferenceLine concentric(double d, double from, double to) {
    std::vector<double> x, y;
    const double r = R - d, step = 1.0 / r;
    for (double a = from; from < to ? a <= to : a >= to; a += from < to ? step : -step) {
        x.push_back(r * std::sin(a));
        y.push_back(R - r * std::cos(a));
    }
    return ReferenceLine(x, y);
}

} // namespace

TEST(DesignGuide, BesideTheGuideItAsksForTheConcentricCurvature) {
    const ReferenceLine ref = concentric(offset, 0.05, 0.5);
    const GuideCurvature g(ref, 0.0, ref.length(), {guide()}, {}, 1.0);
    ASSERT_FALSE(g.empty());
    const GuideCurvature::Mean m = g.over(0.0, ref.length());
    EXPECT_NEAR(m.curvature, 1.0 / (R - offset), 1e-7);
    EXPECT_NEAR(m.weight, ref.length(), 2.5); // 1 per metre, every 2 m sample
    EXPECT_NEAR(m.at, 0.5 * ref.length(), 2.0);
}

TEST(DesignGuide, RunningTheOtherWayTheCurvatureTurnsSign) {
    const ReferenceLine ref = concentric(-offset, 0.5, 0.05);
    const GuideCurvature g(ref, 0.0, ref.length(), {guide()}, {}, 1.0);
    ASSERT_FALSE(g.empty());
    EXPECT_NEAR(g.over(0.0, ref.length()).curvature, -1.0 / (R + offset), 1e-7);
}

TEST(DesignGuide, ATrackLeavingAtATurnoutAngleIsNotGuided) {
    // From the guide's start, 1 in 9 away from it: within 6.5 m for 50 m.
    std::vector<double> x, y;
    for (double s = 0.0; s <= 300.0; s += 1.0) {
        x.push_back(s * std::cos(-1.0 / 9.0));
        y.push_back(s * std::sin(-1.0 / 9.0));
    }
    const GuideCurvature g(ReferenceLine(x, y), 0.0, 300.0, {guide()}, {}, 1.0);
    EXPECT_TRUE(g.empty());
}

TEST(DesignGuide, WhereTheChainsOwnDesignDisagreesItIsNotGuided) {
    const ReferenceLine ref = concentric(offset, 0.05, 0.5);
    // The chain's own design straight over its first half: a tenth of the
    // guide's curvature away, over the tolerance.
    const double half = 0.5 * ref.length();
    const std::vector<FrameElement> own{{ElementKind::line, 0.0, half, 0.0, 0.0},
                                        {ElementKind::arc, half, ref.length(), 1.0 / R, 1.0 / R}};
    const GuideCurvature g(ref, 0.0, ref.length(), {guide()}, own, 1.0);
    EXPECT_EQ(g.over(0.0, half - 2.0).weight, 0.0);
    EXPECT_GT(g.over(half + 2.0, ref.length()).weight, 0.0);
}

TEST(DesignGuide, AnArcsCostIsLeastAtTheGuidesCurvature) {
    const ReferenceLine ref = concentric(offset, 0.05, 0.5);
    const GuideCurvature g(ref, 0.0, ref.length(), {guide()}, {}, 1.0);
    design::Quad f;
    f.free = 4u; // an arc: its curvature alone
    g.add(f, 100.0, 100.0, 400.0);
    const double k = f.q(2) / f.P(2, 2) / (design::S * design::S);
    EXPECT_NEAR(k, 1.0 / (R - offset), 1e-9);
    // The cost there is the samples' spread about it: none on a circle.
    EXPECT_NEAR(f.c - f.q(2) * f.q(2) / f.P(2, 2), 0.0, 1e-12);
}

namespace {

// A guide of one curve between straights: line, transition, arc,
// transition, line.
IndexedAlignment curve_guide() {
    Alignment a;
    a.start = {0.0, 0.0, 0.0, 0.0};
    a.primitives = {make_line(200.0), make_spiral(100.0, 0.0, 1.0 / R), make_arc(300.0, 1.0 / R),
                    make_spiral(100.0, 1.0 / R, 0.0), make_line(200.0)};
    return IndexedAlignment(a);
}

// A reference every metre along the guide, `d` to its left, either way;
// with the chainages across from the guide's joints.
std::pair<ReferenceLine, std::vector<double>> offset_reference(const IndexedAlignment& g, double d, bool reversed) {
    std::vector<double> x, y, along{0.0};
    for (double s = 0.0; s <= g.length() + 1e-9; s += 1.0) {
        const Pose p = g.evaluate(reversed ? g.length() - s : s);
        x.push_back(p.x - d * std::sin(p.hdg));
        y.push_back(p.y + d * std::cos(p.hdg));
        if (x.size() > 1) {
            along.push_back(along.back() + std::hypot(x.back() - x[x.size() - 2], y.back() - y[y.size() - 2]));
        }
    }
    std::vector<double> joints;
    for (const double s : {200.0, 300.0, 600.0, 700.0}) {
        joints.push_back(along[static_cast<std::size_t>(reversed ? g.length() - s : s)]);
    }
    std::sort(joints.begin(), joints.end());
    return {ReferenceLine(x, y), joints};
}

} // namespace

TEST(DesignGuide, ItsJointsLieAcrossFromTheGuidesWithTheKindsEitherSide) {
    const IndexedAlignment g = curve_guide();
    for (const bool reversed : {false, true}) {
        SCOPED_TRACE(reversed ? "the other way" : "the same way");
        const auto [ref, expected] = offset_reference(g, reversed ? -offset : offset, reversed);
        const GuideCurvature gc(ref, 0.0, ref.length(), {g}, {}, 1.0);
        const auto& j = gc.joints();
        ASSERT_EQ(j.size(), 4u);
        const ElementKind line = ElementKind::line, tr = ElementKind::transition, arc = ElementKind::arc;
        const std::vector<std::pair<ElementKind, ElementKind>> kinds{{line, tr}, {tr, arc}, {arc, tr}, {tr, line}};
        for (std::size_t i = 0; i < 4; ++i) {
            // The reference is a polyline of 1 m chords: its chainage differs
            // from the offset curve's by millimetres.
            EXPECT_NEAR(j[i].t, expected[i], 0.05) << i;
            EXPECT_EQ(j[i].before, kinds[i].first) << i;
            EXPECT_EQ(j[i].after, kinds[i].second) << i;
            EXPECT_EQ(j[i].run, j[0].run);
        }
    }
}

TEST(DesignGuide, WhereTheChainsOwnDesignDisagreesTheJointsStay) {
    // The prior is left out where the chain's own design is straight along
    // the guide's curve; its joints are not: the structure is judged by
    // the nodes (design_guided.cpp).
    const IndexedAlignment g = curve_guide();
    const auto [ref, expected] = offset_reference(g, offset, false);
    const std::vector<FrameElement> own{{ElementKind::line, 0.0, ref.length(), 0.0, 0.0}};
    const GuideCurvature gc(ref, 0.0, ref.length(), {g}, own, 1.0);
    EXPECT_EQ(gc.joints().size(), 4u);
    EXPECT_EQ(gc.over(350.0, 550.0).weight, 0.0);
}
