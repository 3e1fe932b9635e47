// Ground truth for the horizontal fit: designed alignments drawn as noisy,
// mapper-like nodes, fitted, and compared with the design.
#include "railodd/geometry/fit_alignment.hpp"
#include "railodd/geometry/indexed_alignment.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <iostream>
#include <numbers>

using namespace railodd::geometry;

namespace {

// Deterministic normal noise (Box-Muller on a 64-bit LCG), identical on every platform.
class Noise {
public:
    explicit Noise(std::uint64_t seed) : state_(seed) {}
    double uniform() {
        state_ = state_ * 6364136223846793005ULL + 1442695040888963407ULL;
        return (static_cast<double>(state_ >> 11) + 0.5) / 9007199254740992.0;
    }
    double normal(double sigma) {
        const double u1 = uniform(), u2 = uniform();
        return sigma * std::sqrt(-2 * std::log(u1)) * std::cos(2 * std::numbers::pi * u2);
    }

private:
    std::uint64_t state_;
};

// Nodes as a mapper draws them: every 60-250 m on lines, every 8-25 m where
// the track curves, and one where a line ends.
std::vector<Point> draw(const Alignment& truth, double sigma, std::uint64_t seed) {
    Noise noise(seed);
    const IndexedAlignment ia(truth);
    std::vector<Point> pts;
    double s = 0.0;
    while (true) {
        const Pose p = ia.evaluate(s);
        pts.push_back({p.x + noise.normal(sigma), p.y + noise.normal(sigma)});
        if (s >= ia.length()) {
            break;
        }
        double next = s + (std::abs(p.curvature) > 1e-12 ? 8 + 17 * noise.uniform() : 60 + 190 * noise.uniform());
        for (double q = s + 1.0; q < next; q += 1.0) {
            if (std::abs(ia.evaluate(q).curvature) > 1e-12 && std::abs(p.curvature) <= 1e-12) {
                next = q; // the curve begins: the mapper puts a node there
                break;
            }
        }
        s = std::min(ia.length(), next);
    }
    return pts;
}

Alignment curve(double radius, double transition, double arc, double turn_sign = 1.0) {
    Alignment a;
    a.start = {0, 0, 0.3, 0};
    const double k = turn_sign / radius;
    a.primitives = {make_line(600), make_spiral(transition, 0, k), make_arc(arc, k), make_spiral(transition, k, 0),
                    make_line(600)};
    return a;
}

// Largest lateral distance between the two alignments where both exist,
// sampled every metre both ways. The fitted line starts and ends at the feet
// of the noisy end nodes, so samples beyond the other line's ends are skipped.
double deviation(const Alignment& fitted, const Alignment& truth) {
    const IndexedAlignment f(fitted), t(truth);
    double worst = 0.0;
    auto one_way = [&worst](const IndexedAlignment& a, const IndexedAlignment& b) {
        for (double s = 0; s <= a.length(); s += 1.0) {
            const Pose p = a.evaluate(s);
            const Projection q = b.project(p.x, p.y);
            if (q.s > 0.0 && q.s < b.length()) {
                worst = std::max(worst, std::abs(q.offset));
            }
        }
    };
    one_way(f, t);
    one_way(t, f);
    return worst;
}

// Radius of the fitted arc at the middle of the true arc.
double radius_at(const Alignment& fitted, double x, double y) {
    const IndexedAlignment f(fitted);
    return 1.0 / std::abs(f.evaluate(f.project(x, y).s).curvature);
}

// The windowed fit (FitMethod::windowed), which these cases were first
// written for and whose element structure they pin; the design search, the
// default, is held to issue 37's radius and deviation targets on them
// (FitSimpleCurve.DefaultFitKeepsRadiusAndPosition).
FitOptions windowed() {
    FitOptions o;
    o.method = FitMethod::windowed;
    return o;
}

void expect_g2(const Alignment& a) {
    for (std::size_t i = 1; i < a.primitives.size(); ++i) {
        EXPECT_DOUBLE_EQ(a.primitives[i - 1].curv_end, a.primitives[i].curv_start) << "joint " << i;
    }
}

} // namespace

// Deviation from the design away from the two outer ends: there the line is
// held by the last one or two sparse, noisy nodes only, so its lateral error
// is that of an extrapolation (about 0.25 m standard deviation for four nodes
// with 0.3 m noise) rather than a property of the fit.
double interior_deviation(const Alignment& fitted, const Alignment& truth, double margin) {
    const IndexedAlignment f(fitted), t(truth);
    double worst = 0.0;
    for (double s = margin; s <= t.length() - margin; s += 1.0) {
        const Pose p = t.evaluate(s);
        worst = std::max(worst, std::abs(f.project(p.x, p.y).offset));
    }
    return worst;
}

struct CurveCase {
    double radius;
    std::uint64_t seed;
};

class FitSimpleCurve : public ::testing::TestWithParam<CurveCase> {};

TEST_P(FitSimpleCurve, RecoversRadiusPositionAndStructure) {
    const double r = GetParam().radius;
    const double transition = std::clamp(r / 8, 60.0, 200.0);
    const double arc = std::clamp(r / 2, 300.0, 1200.0);
    const Alignment truth = curve(r, transition, arc, r > 1000 ? -1 : 1);
    const FitResult fit = fit_alignment(draw(truth, 0.3, GetParam().seed), std::nullopt, std::nullopt, windowed());
    expect_g2(fit.alignment);
    const Pose mid = IndexedAlignment(truth).evaluate(600 + transition + arc / 2);
    EXPECT_NEAR(radius_at(fit.alignment, mid.x, mid.y), r, 0.02 * r);
    // 0.5 m is the target (checked over all cases below); single cases may
    // exceed it by a little where few sparse nodes hold a line.
    EXPECT_LT(interior_deviation(fit.alignment, truth, 100.0), 0.6);
    EXPECT_LT(deviation(fit.alignment, truth), 0.8);
    // line, transition, arc, transition, line
    ASSERT_EQ(fit.alignment.primitives.size(), 5u);
    EXPECT_EQ(fit.alignment.primitives[0].kind, PrimitiveKind::line);
    EXPECT_EQ(fit.alignment.primitives[1].kind, PrimitiveKind::spiral);
    EXPECT_EQ(fit.alignment.primitives[2].kind, PrimitiveKind::arc);
    EXPECT_EQ(fit.alignment.primitives[3].kind, PrimitiveKind::spiral);
    EXPECT_EQ(fit.alignment.primitives[4].kind, PrimitiveKind::line);
    EXPECT_EQ(fit.quality.fallback_windows, 0u);
}

// The design search on the same curves: the radius and, away from the
// free ends, within 1 m of the design (issue 37's limit at 0.3 m of noise).
// Its structure is not pinned: on 4 of the 18 it takes another (a free
// end's straight as an arc of R 44-110 km, R 600's arc split in two arcs
// 5 % apart), 3 of them because its local search stops short of a design
// it prices lower (docs/BENCHMARKS.md).
TEST_P(FitSimpleCurve, DefaultFitKeepsRadiusAndPosition) {
    const double r = GetParam().radius;
    const double transition = std::clamp(r / 8, 60.0, 200.0);
    const double arc = std::clamp(r / 2, 300.0, 1200.0);
    const Alignment truth = curve(r, transition, arc, r > 1000 ? -1 : 1);
    const FitResult fit = fit_alignment(draw(truth, 0.3, GetParam().seed), std::nullopt, std::nullopt, {});
    expect_g2(fit.alignment);
    const Pose mid = IndexedAlignment(truth).evaluate(600 + transition + arc / 2);
    EXPECT_NEAR(radius_at(fit.alignment, mid.x, mid.y), r, 0.02 * r);
    EXPECT_LT(interior_deviation(fit.alignment, truth, 100.0), 1.0);
    EXPECT_LE(fit.alignment.primitives.size(), 7u); // the design's 5 and one arc split in two
}

std::vector<CurveCase> curve_cases() {
    std::vector<CurveCase> cases;
    for (double r : {150.0, 300.0, 600.0, 1200.0, 2500.0, 5000.0}) {
        for (std::uint64_t seed : {1u, 2u, 3u}) {
            cases.push_back({r, static_cast<std::uint64_t>(r) * 7 + seed});
        }
    }
    return cases;
}

INSTANTIATE_TEST_SUITE_P(Radii, FitSimpleCurve, ::testing::ValuesIn(curve_cases()),
                         [](const auto& info) {
                             std::string name = "R";
                             name += std::to_string(static_cast<int>(info.param.radius));
                             name += "_seed";
                             name += std::to_string(info.param.seed);
                             return name;
                         });

TEST(FitAlignment, NineOutOfTenCurvesStayWithinHalfAMetre) {
    std::size_t within = 0, total = 0;
    for (double r : {150.0, 300.0, 600.0, 1200.0, 2500.0, 5000.0}) {
        for (std::uint64_t seed = 100; seed < 105; ++seed) {
            const double transition = std::clamp(r / 8, 60.0, 200.0);
            const Alignment truth = curve(r, transition, std::clamp(r / 2, 300.0, 1200.0), seed % 2 ? 1 : -1);
            const FitResult fit = fit_alignment(draw(truth, 0.3, seed * 31 + static_cast<std::uint64_t>(r)),
                                                std::nullopt, std::nullopt, {});
            within += interior_deviation(fit.alignment, truth, 100.0) < 0.5 ? 1 : 0;
            ++total;
        }
    }
    std::cout << within << " of " << total << " fits within 0.5 m of the design\n";
    EXPECT_GE(static_cast<double>(within), 0.9 * static_cast<double>(total));
}

TEST(FitAlignment, ReverseAndCompoundCurves) {
    Alignment truth;
    truth.start = {100, -50, -0.7, 0};
    const double k1 = 1 / 400.0, k2 = 1 / 900.0, k3 = -1 / 500.0;
    truth.primitives = {make_line(400),         make_spiral(80, 0, k1), make_arc(350, k1), make_spiral(60, k1, k2),
                        make_arc(400, k2),      make_spiral(120, k2, k3), make_arc(300, k3), make_spiral(90, k3, 0),
                        make_line(500)};
    const FitResult fit = fit_alignment(draw(truth, 0.3, 99), std::nullopt, std::nullopt, {});
    expect_g2(fit.alignment);
    EXPECT_LT(interior_deviation(fit.alignment, truth, 100.0), 0.5);
    const IndexedAlignment t(truth);
    for (const auto& [s, r] : std::vector<std::pair<double, double>>{{655, 400}, {1145, 900}, {1700, 500}}) {
        const Pose p = t.evaluate(s);
        EXPECT_NEAR(radius_at(fit.alignment, p.x, p.y), r, 0.03 * r) << "at s " << s;
    }
}

TEST(FitAlignment, MeetsGivenStartAndEndPosesExactly) {
    const Alignment truth = curve(800, 100, 400);
    const IndexedAlignment t(truth);
    const Pose start = t.evaluate(0), end = t.evaluate(t.length());
    const FitResult fit = fit_alignment(draw(truth, 0.3, 5), start, end, {});
    expect_g2(fit.alignment);
    const IndexedAlignment f(fit.alignment);
    const Pose a = f.evaluate(0), b = f.evaluate(f.length());
    EXPECT_NEAR(a.x, start.x, 1e-9);
    EXPECT_NEAR(a.y, start.y, 1e-9);
    EXPECT_NEAR(a.hdg, start.hdg, 1e-12);
    EXPECT_NEAR(a.curvature, start.curvature, 1e-12);
    // The end pose is a constraint of the solve, not a weighted target.
    EXPECT_NEAR(b.x, end.x, 1e-7);
    EXPECT_NEAR(b.y, end.y, 1e-7);
    EXPECT_NEAR(b.hdg, end.hdg, 1e-9);
    EXPECT_NEAR(b.curvature, end.curvature, 1e-12);
}

TEST(FitAlignment, ReachesAnEndPoseOffTheMappedLineExactly) {
    // A track whose tied end (a switch on another track) is 0.5 m to the
    // side of where its nodes lead and turned by 3 mrad, after 4 km: the
    // fit (the windowed one's last window) must bend to it and still follow
    // the nodes.
    Alignment truth;
    truth.start = {0, 0, 0.3, 0};
    truth.primitives = {make_line(800), make_spiral(80, 0, 1.0 / 900), make_arc(500, 1.0 / 900),
                        make_spiral(80, 1.0 / 900, 0), make_line(2700)};
    const IndexedAlignment t(truth);
    Pose end = t.evaluate(t.length());
    end.x += 0.5 * -std::sin(end.hdg);
    end.y += 0.5 * std::cos(end.hdg);
    end.hdg += 0.003;
    for (const FitOptions& o : {FitOptions{}, windowed()}) {
        const FitResult fit = fit_alignment(draw(truth, 0.3, 11), t.evaluate(0), end, o);
        if (o.method == FitMethod::windowed) {
            EXPECT_GE(fit.quality.windows, 2u);
        }
        expect_g2(fit.alignment);
        const IndexedAlignment f(fit.alignment);
        const Pose b = f.evaluate(f.length());
        EXPECT_NEAR(b.x, end.x, 1e-7);
        EXPECT_NEAR(b.y, end.y, 1e-7);
        EXPECT_NEAR(b.hdg, end.hdg, 1e-9);
        EXPECT_NEAR(b.curvature, end.curvature, 1e-12);
        EXPECT_LT(fit.quality.max_m, 1.0);
        EXPECT_LT(interior_deviation(fit.alignment, truth, 400.0), 0.5);
    }
}

TEST(FitAlignment, LongTrackIsFittedInWindowsWithoutJoints) {
    Alignment truth;
    truth.start = {0, 0, 0, 0};
    for (int i = 0; i < 4; ++i) {
        const double k = (i % 2 ? -1 : 1) / (700.0 + 300 * i);
        truth.primitives.push_back(make_line(900));
        truth.primitives.push_back(make_spiral(90, 0, k));
        truth.primitives.push_back(make_arc(450, k));
        truth.primitives.push_back(make_spiral(90, k, 0));
    }
    truth.primitives.push_back(make_line(900));
    const FitResult fit = fit_alignment(draw(truth, 0.3, 7), std::nullopt, std::nullopt, windowed());
    EXPECT_GE(fit.quality.windows, 2u);
    expect_g2(fit.alignment);
    EXPECT_LT(interior_deviation(fit.alignment, truth, 150.0), 0.5);
    EXPECT_LT(fit.quality.rms_m, 0.4);
}

TEST(FitAlignment, ShortNoisyChordBesideALongOneDoesNotThrowTheStartOff) {
    // Curve nodes every 15 m, the curve's last node 0.8 m to the side, then
    // 250 m chords down a straight to a second curve; the start is tied, as
    // every window's after the first. A curvature guess from the short
    // chord alone, carried across the long interval beside it, once put the
    // first estimate hundreds of metres off the second curve (seen on the
    // sample route); the solve then settled on a wrong shape.
    Alignment truth;
    truth.start = {0, 0, 0.2, 0};
    truth.primitives = {make_spiral(60, 0, 1.0 / 600), make_arc(400, 1.0 / 600), make_spiral(60, 1.0 / 600, 0),
                        make_line(750), make_spiral(60, 0, -1.0 / 500), make_arc(500, -1.0 / 500),
                        make_spiral(60, -1.0 / 500, 0), make_line(400)};
    const IndexedAlignment t(truth);
    std::vector<Point> pts;
    auto node = [&](double s, double side) {
        const Pose p = t.evaluate(s);
        pts.push_back({p.x - side * std::sin(p.hdg), p.y + side * std::cos(p.hdg)});
    };
    for (double s = 0.0; s < 520.0; s += 15.0) {
        node(s, 0.0);
    }
    node(520.0, -0.8);
    node(770.0, 0.0);
    node(1020.0, 0.0);
    for (double s = 1270.0; s < 1900.0; s += 15.0) {
        node(s, 0.0);
    }
    node(t.length(), 0.0);
    const FitResult fit = fit_alignment(pts, t.evaluate(0), std::nullopt, {});
    expect_g2(fit.alignment);
    EXPECT_EQ(fit.quality.fallback_windows, 0u);
    EXPECT_LT(fit.quality.max_m, 1.0); // the side-stepped node is 0.8 m off the truth
    EXPECT_LT(interior_deviation(fit.alignment, truth, 50.0), 0.3);
}

TEST(FitAlignment, TwoPointsGiveALine) {
    const FitResult fit = fit_alignment({{0, 0}, {30, 40}}, std::nullopt, std::nullopt, {});
    ASSERT_EQ(fit.alignment.primitives.size(), 1u);
    EXPECT_EQ(fit.alignment.primitives[0].kind, PrimitiveKind::line);
    EXPECT_NEAR(fit.alignment.primitives[0].length, 50.0, 1e-6);
    EXPECT_NEAR(fit.quality.max_m, 0.0, 1e-6);
}
