// Cant from railway:cant and from equilibrium estimation, and its sign.
#include "railodd/geometry/cant.hpp"

#include <gtest/gtest.h>

#include <cmath>

using namespace railodd::geometry;

namespace {

// line 0..500, spiral 500..620, arc 620..980, spiral 980..1100, line to 1400.
Alignment curve(double radius) {
    const double k = 1.0 / radius;
    Alignment a;
    a.primitives = {make_line(500.0), make_spiral(120.0, 0.0, k), make_arc(360.0, k), make_spiral(120.0, k, 0.0),
                    make_line(300.0)};
    return a;
}

CantTagSpan span(double a, double b, std::optional<double> cant_mm, std::optional<double> kmh) {
    return {a, b, cant_mm, kmh};
}

} // namespace

TEST(Cant, TaggedOnTheArcRampedOverTheSpirals) {
    const auto a = curve(-600.0); // right curve
    const auto c = compute_cant(a, {span(0, 450, {}, 120.0), span(450, 1150, 100.0, 120.0), span(1150, 1400, {}, 120.0)},
                                {});
    ASSERT_EQ(c.size(), 3u);
    EXPECT_DOUBLE_EQ(c[0].s_start, 500.0);
    EXPECT_DOUBLE_EQ(c[0].s_end, 620.0);
    EXPECT_DOUBLE_EQ(c[0].cant_start_m, 0.0);
    EXPECT_DOUBLE_EQ(c[0].cant_end_m, 0.1);
    EXPECT_DOUBLE_EQ(c[1].s_start, 620.0);
    EXPECT_DOUBLE_EQ(c[1].s_end, 980.0);
    EXPECT_DOUBLE_EQ(c[1].cant_start_m, 0.1);
    EXPECT_DOUBLE_EQ(c[1].cant_end_m, 0.1);
    EXPECT_DOUBLE_EQ(c[2].cant_start_m, 0.1);
    EXPECT_DOUBLE_EQ(c[2].cant_end_m, 0.0);
    EXPECT_DOUBLE_EQ(c[2].s_end, 1100.0);
    for (const auto& s : c) {
        EXPECT_FALSE(s.estimated);
        EXPECT_FALSE(s.left_curve);
    }
    EXPECT_DOUBLE_EQ(cant_at(c, 560.0), 0.05);
    EXPECT_DOUBLE_EQ(cant_at(c, 800.0), 0.1);
    EXPECT_DOUBLE_EQ(cant_at(c, 300.0), 0.0);
    EXPECT_DOUBLE_EQ(cant_at(c, 1200.0), 0.0);
    // A right curve raises the left rail: OpenDRIVE's positive roll.
    EXPECT_NEAR(superelevation_at(c, 800.0, 1.5), std::asin(0.1 / 1.5), 1e-15);
    EXPECT_GT(superelevation_at(c, 800.0, 1.5), 0.0);
}

TEST(Cant, LeftCurveRollsNegative) {
    const auto c = compute_cant(curve(600.0), {span(0, 1400, 80.0, {})}, {});
    ASSERT_EQ(c.size(), 3u);
    EXPECT_TRUE(c[1].left_curve);
    EXPECT_DOUBLE_EQ(c[1].cant_start_m, 0.08);
    EXPECT_LT(superelevation_at(c, 800.0, 1.5), 0.0);
}

TEST(Cant, EstimatedFromSpeedAndCapped) {
    // 160 km/h on R 1200: 1.5 * (160 / 3.6)^2 / (9.81 * 1200) = 0.2517 m, i.e.
    // the textbook 11.8 V^2 / R = 252 mm, above the 160 mm cap.
    const auto c = compute_cant(curve(1200.0), {span(0, 1400, {}, 160.0)}, {.estimate = true});
    ASSERT_EQ(c.size(), 3u);
    EXPECT_DOUBLE_EQ(c[1].cant_start_m, 0.160);
    EXPECT_DOUBLE_EQ(c[1].cant_end_m, 0.160);
    for (const auto& s : c) {
        EXPECT_TRUE(s.estimated);
    }
    // Below the cap the equilibrium value stands: 80 km/h on R 1200 -> 62.9 mm.
    const auto slow = compute_cant(curve(1200.0), {span(0, 1400, {}, 80.0)}, {.estimate = true});
    ASSERT_EQ(slow.size(), 3u);
    EXPECT_NEAR(slow[1].cant_start_m, 1.5 * std::pow(80.0 / 3.6, 2) / (9.81 * 1200.0), 1e-12);
    EXPECT_NEAR(slow[1].cant_start_m, 0.0629, 1e-4);
}

TEST(Cant, TagBeatsEstimateAndZeroMeansNone) {
    const auto tagged = compute_cant(curve(1200.0), {span(0, 1400, 45.0, 160.0)}, {.estimate = true});
    ASSERT_EQ(tagged.size(), 3u);
    EXPECT_DOUBLE_EQ(tagged[1].cant_start_m, 0.045);
    EXPECT_FALSE(tagged[1].estimated);
    EXPECT_TRUE(compute_cant(curve(1200.0), {span(0, 1400, 0.0, 160.0)}, {.estimate = true}).empty());
}

TEST(Cant, UntaggedWithoutEstimateHasNone) {
    EXPECT_TRUE(compute_cant(curve(1200.0), {span(0, 1400, {}, 160.0)}, {}).empty());
    EXPECT_TRUE(compute_cant(curve(1200.0), {}, {.estimate = true}).empty()); // no speed to estimate from
}

TEST(Cant, ArcMostlyOutsideTheTaggedWayIsUntagged) {
    // The tagged way covers only 100 m of the 360 m arc.
    EXPECT_TRUE(compute_cant(curve(600.0), {span(0, 720, 100.0, {}), span(720, 1400, {}, {})}, {}).empty());
}

TEST(Cant, ReverseCurveRampChangesSide) {
    Alignment a;
    a.primitives = {make_arc(200.0, 1.0 / 500.0), make_spiral(100.0, 1.0 / 500.0, -1.0 / 500.0),
                    make_arc(200.0, -1.0 / 500.0)};
    const auto c = compute_cant(a, {span(0, 500, 90.0, {})}, {});
    ASSERT_EQ(c.size(), 4u);
    EXPECT_TRUE(c[0].left_curve);
    EXPECT_TRUE(c[1].left_curve);
    EXPECT_DOUBLE_EQ(c[1].s_end, 250.0);
    EXPECT_DOUBLE_EQ(c[1].cant_end_m, 0.0);
    EXPECT_FALSE(c[2].left_curve);
    EXPECT_DOUBLE_EQ(c[2].cant_end_m, 0.09);
    EXPECT_FALSE(c[3].left_curve);
    EXPECT_NEAR(cant_at(c, 225.0), 0.045, 1e-12);
}

TEST(Cant, SuperelevationAngle) {
    EXPECT_DOUBLE_EQ(superelevation_rad(0.0, 1.5), 0.0);
    EXPECT_NEAR(superelevation_rad(0.150, 1.5), std::asin(0.1), 1e-15);
    EXPECT_NEAR(superelevation_rad(0.160, 1.5), 0.10687, 1e-5); // 6.12 degrees
}
