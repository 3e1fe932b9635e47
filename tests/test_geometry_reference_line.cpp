// The design search's frame (geometry/src/fit/reference_line.hpp): where a
// tied end's pose lands in it.
#include "fit/reference_line.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <vector>

using namespace railodd::geometry;

namespace {

// East from (0, 0), a half circle left, back west past the start, a half
// circle left, and east again to end 20 m behind the start, 0.5 m to its
// left: the end lies beside the first segment's backward extension.
fit::ReferenceLine loop_back() {
    std::vector<double> x, y;
    const auto line = [&](double x0, double x1, double yy) {
        for (int i = 0; i <= 10; ++i) {
            x.push_back(x0 + (x1 - x0) * i / 10.0);
            y.push_back(yy);
        }
    };
    const auto half_circle = [&](double cx, double cy, double from) {
        for (int i = 1; i < 60; ++i) {
            const double a = from + std::numbers::pi * i / 60.0;
            x.push_back(cx + 50.0 * std::cos(a));
            y.push_back(cy + 50.0 * std::sin(a));
        }
    };
    line(0.0, 100.0, 0.0);
    half_circle(100.0, 50.0, -std::numbers::pi / 2);
    line(100.0, -40.0, 100.0);
    half_circle(-40.0, 50.25, std::numbers::pi / 2);
    line(-40.0, -20.0, 0.5);
    return {x, y};
}

} // namespace

TEST(ReferenceLine, TiedEndOfALoopLandsAtTheEnd) {
    const fit::ReferenceLine r = loop_back();
    // The tie sits 0.3 m from the last segment and 0.2 m from the line
    // through the first: sought near the chain's end, it is the last's.
    const Pose end{-20.0, 0.2, 0.0, 0.0};
    double t = r.length();
    const fit::FrameState s = fit::frame_state(r, end, t);
    EXPECT_NEAR(t, r.length(), 0.5);
    EXPECT_NEAR(s.z - r.developed(t), -0.3, 1e-6);
    const Pose start{0.0, 0.0, 0.0, 0.0};
    double t0 = 0.0;
    fit::frame_state(r, start, t0);
    EXPECT_NEAR(t0, 0.0, 1e-9);
}
