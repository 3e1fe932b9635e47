// The design search's frame (geometry/src/fit/reference_line.hpp): where a
// tied end's pose lands in it, and a design in it taken back to the map.
#include "fit/reference_line.hpp"

#include "railodd/geometry/indexed_alignment.hpp"

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

// A design that runs beside its reference at a constant offset, through a
// curve of R 200 m that turns 86 degrees: on the map it is the parallel
// curve. Its arcs are shorter and tighter than their chainage says; taken
// at the frame's lengths, its exit turned by the offset times one less the
// cosine of the angle (0.46 m here) and kept that heading error.
TEST(ReferenceLine, ADesignBesideItsReferenceIsTheParallelCurveOnTheMap) {
    const double k = 1.0 / 200.0;
    Alignment ref;
    ref.primitives = {make_line(100.0), make_spiral(50.0, 0.0, k), make_arc(250.0, k), make_spiral(50.0, k, 0.0),
                      make_line(800.0)};
    const fit::ReferenceLine r = fit::alignment_reference(ref, 2.0);
    const fit::ElementKind kinds[] = {fit::ElementKind::line, fit::ElementKind::transition, fit::ElementKind::arc,
                                      fit::ElementKind::transition, fit::ElementKind::line};
    const std::vector<Pose> starts = primitive_starts(ref);
    for (const double offset : {0.5, -0.5, 2.0}) {
        fit::FrameDesign d;
        d.start = {offset, 0.0, 0.0};
        double s = 0.0;
        for (std::size_t i = 0; i < ref.primitives.size(); ++i) {
            const Primitive& p = ref.primitives[i];
            d.elements.push_back({kinds[i], s, s + p.length, p.curv_start, p.curv_end});
            s += p.length;
        }
        const IndexedAlignment map(fit::to_alignment(r, d));
        double worst = 0.0, exit = 0.0;
        for (std::size_t i = 0; i < ref.primitives.size(); ++i) {
            for (double u = 0.0; u < ref.primitives[i].length; u += 10.0) {
                const Pose q = evaluate(starts[i], ref.primitives[i], u);
                const double d_m = map.project(q.x - offset * std::sin(q.hdg), q.y + offset * std::cos(q.hdg)).distance;
                worst = std::max(worst, d_m);
                exit = i == 4 ? std::max(exit, d_m) : exit;
            }
        }
        // Second order in the offset: 0.06 m at 0.5 m, 0.25 m at 2 m.
        EXPECT_LT(worst, 0.1 * offset * offset + 0.05) << "offset " << offset;
        EXPECT_LT(exit, 0.1 * offset * offset + 0.05) << "offset " << offset;
    }
}
