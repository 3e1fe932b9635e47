// The design fitted in the trend filter's frame (geometry/src/fit/frame_fit.cpp):
// on nodes drawn exactly from a known design, a structure started with its
// knots and curvatures off recovers them.
#include "fit/frame_fit.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

using namespace railodd::geometry;
using namespace railodd::geometry::fit;

namespace {

// A straight reference along x (headings 0 on a 4 m grid) over `length` m.
Frame straight_frame(double length) {
    Frame f;
    f.h = 4.0;
    for (double s = 0.0; s <= length + 1e-9; s += f.h) {
        f.x.push_back(s);
        f.y.push_back(0.0);
        f.hdg.push_back(0.0);
    }
    return f;
}

// line 200 m, transition 80 m, arc 300 m at curvature k, transition 80 m, line to the end.
CurvatureModel curve(double k, double line1, double t1, double arc, double t2, double total) {
    CurvatureModel m;
    m.start = Pose{0.0, 0.0, 0.0, 0.0};
    m.start_free = false;
    m.knot_var = {-1};
    m.knot_fixed = {0.0};
    m.curv = {k};
    m.push_segment(line1, true, -1, 0.0);
    m.push_segment(t1, true, 0);
    m.push_segment(arc, true, 0);
    m.push_segment(t2, true, -1, 0.0);
    m.push_segment(total - line1 - t1 - arc - t2, true, -1, 0.0);
    return m;
}

// Offset of the design from the x axis at s, by small-angle integration (1 mm steps).
std::vector<double> offsets(const CurvatureModel& m, const std::vector<double>& at) {
    std::vector<double> out;
    double s = 0.0, y = 0.0, hdg = 0.0, knot = 0.0;
    std::size_t j = 0, i = 0;
    constexpr double ds = 1e-3;
    while (i < at.size()) {
        while (j < m.segments() && s >= knot + m.lengths[j]) {
            knot += m.lengths[j++];
        }
        if (s >= at[i] - 1e-9) {
            out.push_back(y);
            ++i;
            continue;
        }
        const double t = (s + ds / 2 - knot) / (j < m.segments() ? m.lengths[j] : 1.0);
        const double k = j < m.segments() ? m.knot_curvature(j) * (1 - t) + m.knot_curvature(j + 1) * t
                                          : m.knot_curvature(j);
        y += ds * (hdg + k * ds / 2);
        hdg += k * ds;
        s += ds;
    }
    return out;
}

} // namespace

TEST(FrameFit, RecoversKnotsAndCurvatureOfAKnownDesign) {
    constexpr double total = 1200.0, k = 1.0 / 4000.0; // turns 0.095 rad: within the small-angle model
    const CurvatureModel truth = curve(k, 200.0, 80.0, 300.0, 80.0, total);
    Frame f = straight_frame(total);
    for (double s = 0.0; s <= total + 1e-9; s += 10.0) {
        f.s.push_back(s);
    }
    f.e = offsets(truth, f.s);
    ASSERT_EQ(f.e.size(), f.s.size());

    CurvatureModel m = curve(0.8 * k, 230.0, 50.0, 330.0, 60.0, total); // knots 30 m off, curvature 20 % low
    const FrameFit fit = fit_in_frame(m, f, std::nullopt, 0.01);
    ASSERT_TRUE(fit.ok);
    double knot = 0.0, true_knot = 0.0;
    for (std::size_t j = 0; j + 1 < m.segments(); ++j) {
        knot += m.lengths[j];
        true_knot += truth.lengths[j];
        EXPECT_NEAR(knot, true_knot, 0.5) << "knot " << j + 1;
    }
    EXPECT_NEAR(m.curv[0] / k, 1.0, 0.002);
    for (const double d : fit.distances_m) {
        EXPECT_LT(d, 0.005);
    }
}

TEST(FrameFit, MeetsAnEndPoseAndRefusesLargeAngles) {
    constexpr double total = 1200.0, k = 1.0 / 4000.0; // turns 0.095 rad: within the small-angle model
    const CurvatureModel truth = curve(k, 200.0, 80.0, 300.0, 80.0, total);
    Frame f = straight_frame(total);
    for (double s = 0.0; s <= total + 1e-9; s += 25.0) {
        f.s.push_back(s);
    }
    f.e = offsets(truth, f.s);
    // The end pose: where the design ends, its offset and turn.
    const double turn = k * (80.0 / 2 + 300.0 + 80.0 / 2);
    const Pose end{total, f.e.back(), turn, 0.0};
    CurvatureModel m = curve(1.2 * k, 180.0, 100.0, 280.0, 100.0, total);
    const FrameFit fit = fit_in_frame(m, f, end, 0.01);
    ASSERT_TRUE(fit.ok);
    EXPECT_NEAR(m.curv[0] / k, 1.0, 0.005);

    // Nodes leaving the reference at 0.3 rad: the small-angle model no
    // longer stands for the curve, and the fit says so.
    CurvatureModel line;
    line.start = Pose{0.0, 0.0, 0.0, 0.0};
    line.knot_var = {-1};
    line.knot_fixed = {0.0};
    line.push_segment(total, true, -1, 0.0);
    Frame sparse = straight_frame(total);
    for (double s = 0.0; s <= total; s += 100.0) {
        sparse.s.push_back(s);
        sparse.e.push_back(std::tan(0.3) * s);
    }
    EXPECT_FALSE(fit_in_frame(line, sparse, std::nullopt, 0.3).ok);
}
