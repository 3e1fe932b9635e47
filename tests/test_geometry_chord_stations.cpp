// chord_stations: a polyline through the stations stays within the sagitta
// of the alignment on random line / transition / arc sequences (measured
// densely, not from the formula), keeps every joint inside the range and
// puts no station inside a line.
#include "railodd/geometry/alignment.hpp"
#include "railodd/geometry/indexed_alignment.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <stdexcept>

using namespace railodd::geometry;

namespace {

Alignment random_alignment(std::mt19937& rng) {
    std::uniform_real_distribution<double> u(0.0, 1.0);
    Alignment a;
    a.start = {100.0 * u(rng), -50.0 * u(rng), 6.0 * u(rng), 0.0};
    double k = 0.0;
    const int n = 1 + static_cast<int>(rng() % 12);
    for (int i = 0; i < n; ++i) {
        const double length = 0.5 + 400.0 * u(rng) * u(rng);
        const double radius = 40.0 + 5000.0 * u(rng) * u(rng);
        const double next = (u(rng) < 0.5 ? -1.0 : 1.0) / radius;
        switch (rng() % 3) {
        case 0: a.primitives.push_back(make_line(length)); k = 0.0; break;
        case 1: a.primitives.push_back(make_spiral(length, k, next)); k = next; break;
        default: a.primitives.push_back(make_arc(length, next)); k = next; break;
        }
    }
    return a;
}

double point_segment(const Pose& p, const Pose& a, const Pose& b) {
    const double dx = b.x - a.x, dy = b.y - a.y, len2 = dx * dx + dy * dy;
    const double t = len2 > 0.0 ? std::clamp(((p.x - a.x) * dx + (p.y - a.y) * dy) / len2, 0.0, 1.0) : 0.0;
    return std::hypot(p.x - a.x - t * dx, p.y - a.y - t * dy);
}

} // namespace

TEST(GeometryChordStations, PolylineStaysWithinTheSagittaOfRandomAlignments) {
    std::mt19937 rng(7);
    std::uniform_real_distribution<double> u(0.0, 1.0);
    for (int round = 0; round < 300; ++round) {
        const Alignment a = random_alignment(rng);
        const double total = length(a);
        const double s0 = u(rng) < 0.3 ? 0.0 : total * u(rng) * 0.5;
        const double s1 = u(rng) < 0.3 ? total : s0 + (total - s0) * u(rng);
        const double sagitta = u(rng) < 0.5 ? 0.05 : 0.005;
        const std::vector<double> st = chord_stations(a, s0, s1, sagitta);
        EXPECT_EQ(IndexedAlignment(a).chord_stations(s0, s1, sagitta), st) << "round " << round;
        ASSERT_GE(st.size(), s1 > s0 ? 2u : 1u);
        EXPECT_EQ(st.front(), s0);
        EXPECT_EQ(st.back(), s1);
        ASSERT_TRUE(std::is_sorted(st.begin(), st.end()));
        EXPECT_EQ(std::adjacent_find(st.begin(), st.end()), st.end()) << "a station given twice";
        double worst = 0.0;
        for (std::size_t i = 1; i < st.size(); ++i) {
            const Pose p = evaluate(a, st[i - 1]), q = evaluate(a, st[i]);
            for (int j = 1; j < 50; ++j) {
                worst = std::max(worst, point_segment(evaluate(a, st[i - 1] + (st[i] - st[i - 1]) * j / 50.0), p, q));
            }
        }
        EXPECT_LE(worst, sagitta * 1.0001 + 1e-9) << "round " << round;
        // Every joint strictly inside the range is a station.
        double at = 0.0;
        for (const Primitive& p : a.primitives) {
            at += p.length;
            if (at > s0 && at < s1) {
                EXPECT_NE(std::find(st.begin(), st.end(), at), st.end()) << "joint at " << at;
            }
        }
    }
}

TEST(GeometryChordStations, LinesNeedOnlyTheirEndsAndArcsTheirCurvature) {
    Alignment a;
    a.primitives = {make_line(1000.0), make_arc(100.0, 1.0 / 300.0), make_line(500.0)};
    EXPECT_EQ(chord_stations(a, 10.0, 900.0, 0.05), (std::vector<double>{10.0, 900.0}));
    EXPECT_EQ(chord_stations(a, 10.0, 1200.0, 0.05).size(), 2u + 2u + 9u); // ends, joints, 10 chords of 10 m
    EXPECT_EQ(chord_stations(a, 500.0, 500.0, 0.05), (std::vector<double>{500.0}));
    EXPECT_THROW(chord_stations(a, 5.0, 1.0, 0.05), std::invalid_argument);
    EXPECT_THROW(chord_stations(a, 0.0, 1.0, 0.0), std::invalid_argument);
}
