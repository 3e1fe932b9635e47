// Closed-form evaluation of planView primitives against independent references.
#include "railodd/geometry/alignment.hpp"
#include "railodd/geometry/indexed_alignment.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <optional>
#include <random>
#include <stdexcept>

using namespace railodd::geometry;

namespace {

constexpr double pi = std::numbers::pi;

struct Point {
    double x;
    double y;
};

// Composite Simpson in long double over the quadratic heading: an integration
// path independent of the power series under test.
Point reference_spiral(const Pose& start, double k0, double k1, double length) {
    const int n = 400000;
    const long double h = static_cast<long double>(length) / n;
    const long double rate = (static_cast<long double>(k1) - k0) / length;
    long double sx = 0.0L;
    long double sy = 0.0L;
    for (int i = 0; i <= n; ++i) {
        const long double t = h * i;
        const long double th = start.hdg + t * (k0 + 0.5L * rate * t);
        const long double w = (i == 0 || i == n) ? 1.0L : (i % 2 == 1 ? 4.0L : 2.0L);
        sx += w * std::cos(th);
        sy += w * std::sin(th);
    }
    return {static_cast<double>(start.x + sx * h / 3.0L),
            static_cast<double>(start.y + sy * h / 3.0L)};
}

Alignment mixed_alignment() {
    Alignment a;
    a.start = {120.0, -40.0, 0.3, 0.0};
    a.primitives = {make_line(250.0),        make_spiral(100.0, 0.0, 1.0 / 300.0),
                    make_arc(180.0, 1.0 / 300.0), make_spiral(100.0, 1.0 / 300.0, 0.0),
                    make_line(90.0),         make_spiral(80.0, 0.0, -1.0 / 600.0),
                    make_arc(400.0, -1.0 / 600.0), make_spiral(80.0, -1.0 / 600.0, 0.0),
                    make_line(300.0)};
    return a;
}

} // namespace

TEST(Primitive, LineEndsAlongHeading) {
    const Pose start{10.0, 20.0, 0.7, 0.0};
    const Pose end = evaluate(start, make_line(123.4), 123.4);
    EXPECT_NEAR(end.x, 10.0 + 123.4 * std::cos(0.7), 1e-12);
    EXPECT_NEAR(end.y, 20.0 + 123.4 * std::sin(0.7), 1e-12);
    EXPECT_DOUBLE_EQ(end.hdg, 0.7);
    EXPECT_EQ(end.curvature, 0.0);
}

TEST(Primitive, ArcEndpointsLieOnTheCircle) {
    for (const double radius : {300.0, -600.0, 1200.0, -2500.0}) {
        const Pose start{-5.0, 7.0, 1.1, 0.0};
        const double k = 1.0 / radius;
        // Centre lies on the left normal for a left curve (positive k).
        const double cx = start.x - radius * std::sin(start.hdg);
        const double cy = start.y + radius * std::cos(start.hdg);
        for (const double ds : {0.0, 1.0, 77.7, 500.0, 900.0}) {
            const Pose p = evaluate(start, make_arc(900.0, k), ds);
            const double th = start.hdg + k * ds;
            EXPECT_NEAR(p.x, cx + radius * std::sin(th), 1e-9) << "R " << radius << " ds " << ds;
            EXPECT_NEAR(p.y, cy - radius * std::cos(th), 1e-9) << "R " << radius << " ds " << ds;
            EXPECT_NEAR(p.hdg, th, 1e-15);
            EXPECT_EQ(p.curvature, k);
        }
    }
}

TEST(Primitive, FullCircleCloses) {
    const double radius = 250.0;
    const Pose start{3.0, 4.0, -0.4, 0.0};
    const Pose end = evaluate(start, make_arc(2.0 * pi * radius, 1.0 / radius), 2.0 * pi * radius);
    EXPECT_NEAR(end.x, start.x, 1e-9);
    EXPECT_NEAR(end.y, start.y, 1e-9);
    EXPECT_NEAR(end.hdg, start.hdg + 2.0 * pi, 1e-12);
}

TEST(Primitive, VanishingCurvatureArcHasNoCancellation) {
    // The textbook (sin(h + k s) - sin h) / k loses all digits as k -> 0; the
    // lateral deviation from the tangent must still be k L^2 / 2.
    const double k = 1e-13;
    const double len = 1000.0;
    const Pose start{0.0, 0.0, 0.2, 0.0};
    const Pose arc = evaluate(start, make_arc(len, k), len);
    const double along = arc.x * std::cos(0.2) + arc.y * std::sin(0.2);
    const double lateral = -arc.x * std::sin(0.2) + arc.y * std::cos(0.2);
    EXPECT_NEAR(along, len, 1e-12);
    EXPECT_NEAR(lateral, 0.5 * k * len * len, 1e-12);
}

TEST(Primitive, ClothoidMatchesPublishedFresnelValues) {
    // Curvature s / A^2 with A^2 = L^2 / pi gives x(L) = L C(1), y(L) = L S(1)
    // for the normalised Fresnel integrals C(1), S(1).
    const double len = 100.0;
    const double radius = len / pi; // curvature at the end: L / A^2 = pi / L
    const Pose end = evaluate(Pose{}, make_spiral(len, 0.0, 1.0 / radius), len);
    EXPECT_NEAR(end.x, len * 0.7798934003768228, 1e-9);
    EXPECT_NEAR(end.y, len * 0.4382591473903548, 1e-9);
    EXPECT_NEAR(end.hdg, len / (2.0 * radius), 1e-14);
    EXPECT_NEAR(end.curvature, 1.0 / radius, 1e-15);
}

TEST(Primitive, LongClothoidsMatchFineReferenceWithinMicrometre) {
    struct Case {
        double k0;
        double k1;
        double len;
    };
    const Case cases[] = {{0.0, 1.0 / 300.0, 1000.0},      {1.0 / 600.0, 1.0 / 300.0, 1000.0},
                          {1.0 / 300.0, 0.0, 150.0},       {0.0, -1.0 / 1200.0, 1000.0},
                          {-1.0 / 250.0, 1.0 / 250.0, 800.0}, {0.0, 0.5, 60.0}};
    const Pose start{1000.0, -2000.0, 2.5, 0.0};
    for (const Case& c : cases) {
        const Pose end = evaluate(start, make_spiral(c.len, c.k0, c.k1), c.len);
        const Point ref = reference_spiral(start, c.k0, c.k1, c.len);
        EXPECT_LT(std::hypot(end.x - ref.x, end.y - ref.y), 1e-6)
            << "k " << c.k0 << " -> " << c.k1 << " over " << c.len;
        EXPECT_NEAR(end.hdg, start.hdg + 0.5 * (c.k0 + c.k1) * c.len, 1e-13);
        EXPECT_NEAR(end.curvature, c.k1, 1e-15);
    }
}

// The pieces the fit evaluates millions of times: a few metres to a few tens,
// any curvature sign, and sub-intervals whose phase is at the series' limit.
TEST(Primitive, ShortClothoidsMatchFineReferenceWithinNanometre) {
    struct Case {
        double k0;
        double k1;
        double len;
    };
    const Case cases[] = {{1.0 / 300.0, 1.0 / 250.0, 12.0}, {-1.0 / 5000.0, 1.0 / 4000.0, 25.0},
                          {0.0, 1e-7, 40.0},                {1.0 / 190.0, -1.0 / 190.0, 60.0},
                          {0.2, 0.25, 1.2},                 {0.0, 0.1, 6.0},
                          {0.04, 0.0, 7.5},                 {-0.1, -0.05, 9.0}};
    const Pose start{-350.0, 80.0, -1.2, 0.0};
    for (const Case& c : cases) {
        const Primitive p = make_spiral(c.len, c.k0, c.k1);
        for (double f : {0.3, 1.0}) {
            const Pose end = evaluate(start, p, f * c.len);
            const double rate = (c.k1 - c.k0) / c.len;
            const Point ref = reference_spiral(start, c.k0, c.k0 + rate * f * c.len, f * c.len);
            EXPECT_LT(std::hypot(end.x - ref.x, end.y - ref.y), 1e-9)
                << "k " << c.k0 << " -> " << c.k1 << " over " << c.len << " at " << f;
        }
    }
}

TEST(Primitive, SpiralMidpointHeadingIsQuadratic) {
    const Primitive p = make_spiral(120.0, 0.0, 1.0 / 600.0);
    const Pose mid = evaluate(Pose{}, p, 60.0);
    EXPECT_NEAR(mid.hdg, 60.0 * 60.0 / (2.0 * 600.0 * 120.0), 1e-15);
    EXPECT_NEAR(mid.curvature, 0.5 / 600.0, 1e-15);
}

TEST(Primitive, DistanceIsClamped) {
    const Pose start{1.0, 2.0, 0.0, 0.0};
    const Primitive p = make_arc(50.0, 0.01);
    const Pose before = evaluate(start, p, -10.0);
    const Pose after = evaluate(start, p, 80.0);
    const Pose end = evaluate(start, p, 50.0);
    EXPECT_DOUBLE_EQ(before.x, 1.0);
    EXPECT_DOUBLE_EQ(before.y, 2.0);
    EXPECT_DOUBLE_EQ(after.x, end.x);
    EXPECT_DOUBLE_EQ(after.y, end.y);
}

TEST(Alignment, ValidateRejectsContradictions) {
    Alignment a;
    a.primitives = {make_line(10.0), Primitive{PrimitiveKind::line, 5.0, 0.01, 0.0}};
    EXPECT_THROW(validate(a), std::invalid_argument);
    a.primitives = {Primitive{PrimitiveKind::arc, 5.0, 0.01, 0.02}};
    EXPECT_THROW(validate(a), std::invalid_argument);
    a.primitives = {make_line(-1.0)};
    EXPECT_THROW(validate(a), std::invalid_argument);
    a.primitives = {make_line(10.0), make_spiral(5.0, 0.0, 0.01)};
    EXPECT_NO_THROW(validate(a));
}

TEST(Alignment, ChainedEvaluationIsG2Continuous) {
    const Alignment a = mixed_alignment();
    const auto starts = primitive_starts(a);
    const auto s0 = primitive_s(a);
    ASSERT_EQ(starts.size(), a.primitives.size());
    const double eps = 1e-6;
    for (std::size_t i = 1; i < starts.size(); ++i) {
        const Pose before = evaluate(a, s0[i] - eps);
        const Pose at = evaluate(a, s0[i]);
        const Pose after = evaluate(a, s0[i] + eps);
        EXPECT_NEAR(at.x, starts[i].x, 1e-9);
        EXPECT_NEAR(at.y, starts[i].y, 1e-9);
        EXPECT_NEAR(at.hdg, starts[i].hdg, 1e-12);
        EXPECT_LT(std::hypot(after.x - before.x, after.y - before.y), 2.0 * eps + 1e-9);
        EXPECT_NEAR(after.hdg, before.hdg, 1e-8);
        EXPECT_NEAR(after.curvature, before.curvature, 1e-9) << "curvature jump at joint " << i;
    }
}

TEST(Alignment, EvaluateClampsAndReportsLength) {
    const Alignment a = mixed_alignment();
    EXPECT_DOUBLE_EQ(length(a), 1580.0);
    const Pose begin = evaluate(a, -5.0);
    EXPECT_DOUBLE_EQ(begin.x, a.start.x);
    EXPECT_DOUBLE_EQ(begin.y, a.start.y);
    const Pose end = evaluate(a, 1e9);
    const Pose last = evaluate(primitive_starts(a).back(), a.primitives.back(), 300.0);
    EXPECT_NEAR(end.x, last.x, 1e-12);
    EXPECT_NEAR(end.y, last.y, 1e-12);
    const double turn = (50.0 + 180.0 + 50.0) / 300.0 - (40.0 + 400.0 + 40.0) / 600.0;
    EXPECT_NEAR(end.hdg, a.start.hdg + turn, 1e-12);
}

TEST(Alignment, IndexedEvaluationMatchesPlainEvaluation) {
    const Alignment a = mixed_alignment();
    const IndexedAlignment idx(a);
    for (double s = 0.0; s <= 1580.0; s += 37.3) {
        const Pose p = evaluate(a, s);
        const Pose q = idx.evaluate(s);
        EXPECT_NEAR(p.x, q.x, 1e-9);
        EXPECT_NEAR(p.y, q.y, 1e-9);
        EXPECT_NEAR(p.curvature, q.curvature, 1e-15);
    }
}

TEST(Projection, RecoversStationAndOffset) {
    const Alignment a = mixed_alignment();
    const IndexedAlignment idx(a);
    for (double s = 3.0; s < 1578.0; s += 41.7) {
        for (const double off : {-10.0, -3.2, 0.0, 0.4, 4.5, 25.0}) {
            const Pose p = evaluate(a, s);
            const double x = p.x - off * std::sin(p.hdg);
            const double y = p.y + off * std::cos(p.hdg);
            const Projection r = idx.project(x, y);
            EXPECT_NEAR(r.s, s, 1e-7) << "s " << s << " offset " << off;
            EXPECT_NEAR(r.offset, off, 1e-8) << "s " << s << " offset " << off;
            EXPECT_NEAR(r.distance, std::abs(off), 1e-8);
        }
    }
}

namespace {

// A long random track of lines and arcs (R 150-3000 m) that winds back across
// itself, so that the search tree's boxes overlap.
Alignment winding_alignment(unsigned seed, int pieces) {
    std::mt19937 rng(seed);
    std::uniform_real_distribution<double> len(5.0, 200.0), radius(150.0, 3000.0), coin(0.0, 1.0);
    Alignment a;
    a.start = {1000.0 * coin(rng), -500.0 * coin(rng), 6.0 * coin(rng), 0.0};
    for (int i = 0; i < pieces; ++i) {
        a.primitives.push_back(coin(rng) < 0.3 ? make_line(len(rng))
                                               : make_arc(len(rng), (coin(rng) < 0.8 ? 1.0 : -1.0) / radius(rng)));
    }
    return a;
}

// Nearest distance by brute force: every 5 cm of [s0, s1] (the indexed
// evaluation is checked against the plain one above).
double dense_nearest(const IndexedAlignment& a, double x, double y, double s0, double s1) {
    double best = std::numeric_limits<double>::infinity();
    for (double s = s0; s <= s1; s += 0.05) {
        const Pose p = a.evaluate(s);
        best = std::min(best, std::hypot(p.x - x, p.y - y));
    }
    return best;
}

} // namespace

// The nearest-sample search prunes subtrees of boxes: on long tracks that
// cross themselves it must still find the nearest point a scan of the whole
// track finds, over the whole track and over a stretch of it.
TEST(Projection, TreeSearchFindsTheNearestPointOnLongWindingTracks) {
    for (const unsigned seed : {1u, 2u, 3u}) {
        const Alignment a = winding_alignment(seed, 300);
        const IndexedAlignment idx(a);
        std::mt19937 rng(seed + 100);
        std::uniform_real_distribution<double> along(0.0, idx.length()), off(-40.0, 40.0);
        for (int q = 0; q < 30; ++q) {
            const Pose p = evaluate(a, along(rng));
            const double o = off(rng);
            const double x = p.x - o * std::sin(p.hdg), y = p.y + o * std::cos(p.hdg);
            const Projection r = idx.project(x, y);
            EXPECT_LE(r.distance, dense_nearest(idx, x, y, 0.0, idx.length()) + 1e-6) << "seed " << seed << " query " << q;
            const double s0 = along(rng), s1 = std::min(idx.length(), s0 + 300.0);
            const Projection w = idx.project_within(x, y, s0, s1);
            // The stretch is widened to the samples around it (2 m apart at most)
            // and the search brackets the nearest one by its neighbours.
            EXPECT_GE(w.s, s0 - 4.0);
            EXPECT_LE(w.s, s1 + 4.0);
            EXPECT_LE(w.distance, dense_nearest(idx, x, y, s0, s1) + 1e-6) << "seed " << seed << " query " << q;
        }
    }
}

// project_near is project() where the curve passes within the radius, and
// nothing where it passes nowhere within it (the design search's guides ask
// it of every 2 m of a chain).
TEST(Projection, NearIsProjectWithinTheRadiusAndNothingBeyond) {
    for (const unsigned seed : {1u, 2u}) {
        const Alignment a = winding_alignment(seed, 300);
        const IndexedAlignment idx(a);
        std::mt19937 rng(seed + 200);
        std::uniform_real_distribution<double> along(0.0, idx.length()), off(-20.0, 20.0);
        for (int q = 0; q < 200; ++q) {
            const Pose p = evaluate(a, along(rng));
            const double o = off(rng);
            const double x = p.x - o * std::sin(p.hdg), y = p.y + o * std::cos(p.hdg);
            const Projection r = idx.project(x, y);
            const std::optional<Projection> n = idx.project_near(x, y, 6.5);
            if (r.distance <= 6.5) {
                ASSERT_TRUE(n.has_value()) << "seed " << seed << " query " << q;
            }
            if (n) {
                EXPECT_EQ(n->s, r.s);
                EXPECT_EQ(n->distance, r.distance);
            } else {
                EXPECT_GT(r.distance, 6.5);
            }
        }
    }
}

TEST(Projection, FreeFunctionAndEnds) {
    const Alignment a = mixed_alignment();
    const Projection mid = project_point(a, evaluate(a, 700.0).x, evaluate(a, 700.0).y);
    EXPECT_NEAR(mid.s, 700.0, 1e-7);
    EXPECT_NEAR(mid.distance, 0.0, 1e-8);
    // A point behind the start projects onto s = 0 with its full distance.
    const double x = a.start.x - 30.0 * std::cos(a.start.hdg);
    const double y = a.start.y - 30.0 * std::sin(a.start.hdg);
    const Projection before = project_point(a, x, y);
    EXPECT_DOUBLE_EQ(before.s, 0.0);
    EXPECT_NEAR(before.distance, 30.0, 1e-9);
    EXPECT_NEAR(before.offset, 0.0, 1e-9);
}
