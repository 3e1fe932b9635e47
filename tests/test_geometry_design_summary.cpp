// The design figures of a fitted network (report.json geometry.summary.design):
// shares, elements and sign changes on known alignments, and the curvature
// agreement of parallel tracks on concentric and on disagreeing curves.
#include "railodd/geometry/design_summary.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

using namespace railodd::geometry;

namespace {

// An arc of radius r (left turn), `length` long, starting at (x, y) heading east.
Alignment arc(double x, double y, double r, double length) {
    Alignment a;
    a.start = {x, y, 0.0, 0.0};
    a.primitives = {make_arc(length, 1.0 / r)};
    return a;
}

} // namespace

TEST(DesignSummary, SharesElementsAndSignChangesOfAKnownAlignment) {
    Alignment a;
    a.primitives = {make_line(400), make_spiral(100, 0, 1.0 / 800), make_arc(300, 1.0 / 800),
                    make_spiral(100, 1.0 / 800, -1.0 / 800), make_arc(100, -1.0 / 800), make_spiral(100, -1.0 / 800, 0),
                    make_line(900)};
    const DesignSummary d = summarise_design({a});
    EXPECT_NEAR(d.length_km, 2.0, 1e-9);
    EXPECT_NEAR(d.spiral_share, 0.15, 1e-9);
    EXPECT_NEAR(d.arc_share, 0.2, 1e-9);
    EXPECT_NEAR(d.elements_per_km, 3.5, 1e-9);
    EXPECT_NEAR(d.joints_per_km, 3.0, 1e-9);
    EXPECT_EQ(d.short_element_share, 0.0);
    EXPECT_NEAR(d.sign_changes_per_km, 0.5, 1e-9); // the reverse curve's one
    EXPECT_EQ(d.parallel_pairs, 0u);
    // Cut into two roads where its line ends, the line's joint is a road's
    // end; cut inside its first arc, the arc is two elements and the joint
    // between them a road's end.
    const std::vector<Alignment> at_knot = split_alignment(a, {400.0});
    EXPECT_NEAR(summarise_design(at_knot).joints_per_km, 2.5, 1e-9);
    const std::vector<Alignment> in_arc = split_alignment(a, {650.0});
    EXPECT_NEAR(summarise_design(in_arc).elements_per_km, 4.0, 1e-9);
    EXPECT_NEAR(summarise_design(in_arc).joints_per_km, 3.0, 1e-9);
}

TEST(DesignSummary, ConcentricDoubleTrackAgreesEitherWay) {
    // Two tracks 4.5 m apart around one centre: curvatures 1/500 and
    // 1/495.5 are one design.
    const Alignment outer = arc(0, 0, 500, 600), inner = arc(0, 4.5, 495.5, 600);
    for (const bool flip : {false, true}) {
        const DesignSummary d = summarise_design({outer, flip ? reversed(inner) : inner});
        EXPECT_GT(d.parallel_pairs, 100u) << flip;
        EXPECT_LT(d.parallel_difference_p95, 1e-3) << flip;
        EXPECT_EQ(d.parallel_share_over_10pct, 0.0) << flip;
    }
}

TEST(DesignSummary, DisagreeingParallelCurvesAreCounted) {
    // The inner track runs 40 m of its arc 30 % tighter and 40 m 30 %
    // wider, then on at the common radius: still 3-6 m beside the outer
    // one, but not one design there.
    Alignment inner;
    inner.start = {0, 4.5, 0, 0};
    inner.primitives = {make_arc(250, 1 / 495.5), make_arc(40, 1.3 / 495.5), make_arc(40, 0.7 / 495.5),
                        make_arc(270, 1 / 495.5)};
    const DesignSummary d = summarise_design({arc(0, 0, 500, 600), inner});
    EXPECT_GT(d.parallel_pairs, 100u);
    EXPECT_GT(d.parallel_share_over_10pct, 0.05);
    EXPECT_LT(d.parallel_share_over_10pct, 0.3);
    EXPECT_LT(d.parallel_difference_p50, 0.02);
}

TEST(DesignSummary, TracksTooFarApartOrStraightAreNotPairs) {
    Alignment a, b;
    a.primitives = {make_line(500)};
    b.start = {0, 4.5, 0, 0};
    b.primitives = {make_line(500)};
    EXPECT_EQ(summarise_design({a, b}).parallel_pairs, 0u); // straight: nothing to compare
    EXPECT_EQ(summarise_design({arc(0, 0, 500, 600), arc(0, 12, 488, 600)}).parallel_pairs, 0u);
}

TEST(DesignSummary, ATrackLeavingItsNeighbourIsNoPair) {
    // A turnout's curve of R 300 m leaving 3 m beside a curved track, under
    // 0.05 rad off its direction for its first 15 m: beside it, but parting
    // (its offset 0.7 m more 20 m on), not a parallel track.
    const Alignment through = arc(0, 0, 2000, 600);
    const Pose at = evaluate(through, 200.0);
    Alignment leg;
    leg.start = {at.x - 3.0 * std::sin(at.hdg), at.y + 3.0 * std::cos(at.hdg), at.hdg, 0.0};
    leg.primitives = {make_arc(60.0, 1.0 / 300.0)};
    EXPECT_EQ(summarise_design({through, leg}).parallel_pairs, 0u);
}

TEST(DesignSummary, ElementsUnderAMetreAreCounted) {
    // A curve entered through a half-metre transition, as a turnout's at its
    // switch: one element in four under 1 m.
    Alignment a;
    a.primitives = {make_line(100), make_spiral(0.5, 0, 1.0 / 300), make_arc(50, 1.0 / 300), make_spiral(30, 1.0 / 300, 0)};
    EXPECT_NEAR(summarise_design({a}).short_element_share, 0.25, 1e-12);
}
