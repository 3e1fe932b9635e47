// The design search as a chain's fit (FitMethod::design_search,
// geometry/src/fit/design_fit.cpp) on routes of known design
// (data/alignment_truth): near the true centreline, about the design's
// element count, the noise read from the nodes, tied ends met.
#include "railodd/geometry/fit_alignment.hpp"
#include "railodd/truth/alignment_truth.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <vector>

using namespace railodd;

namespace {

geometry::FitOptions design_search() {
    geometry::FitOptions o;
    o.method = geometry::FitMethod::design_search;
    return o;
}

} // namespace

TEST(DesignFit, OsmLikeNodesGiveTheDesign) {
    std::vector<double> max_dev;
    for (int seed = 1000; seed < 1010; ++seed) {
        truth::TruthOptions t;
        t.sigma_m = 0.3;
        const truth::TruthRoute r = truth::make_route(static_cast<std::uint64_t>(seed), t);
        const geometry::FitResult fit = geometry::fit_alignment(r.nodes, std::nullopt, std::nullopt, design_search());
        geometry::validate(fit.alignment);
        const truth::TruthScore s = truth::score(r, fit.alignment);
        max_dev.push_back(s.deviation_max_m);
        EXPECT_LT(s.deviation_p95_m, 0.8) << "seed " << seed;
        EXPECT_LE(s.fit_elements, s.design_elements * 3 / 2) << "seed " << seed;
        EXPECT_GT(fit.quality.noise_sigma_m, 0.7 * 0.3) << "seed " << seed;
        EXPECT_LT(fit.quality.noise_sigma_m, 1.6 * 0.3) << "seed " << seed;
        EXPECT_LE(s.spurious_sign_changes, 1) << "seed " << seed;
    }
    std::sort(max_dev.begin(), max_dev.end());
    EXPECT_LT(max_dev[max_dev.size() / 2], 1.0);
}

TEST(DesignFit, SparseNodesKeepTheElementCountAndTheNoise) {
    for (int seed = 1000; seed < 1010; ++seed) {
        truth::TruthOptions t;
        t.sigma_m = 1.0;
        t.spacing = truth::Spacing::sparse;
        const truth::TruthRoute r = truth::make_route(static_cast<std::uint64_t>(seed), t);
        const geometry::FitResult fit = geometry::fit_alignment(r.nodes, std::nullopt, std::nullopt, design_search());
        const truth::TruthScore s = truth::score(r, fit.alignment);
        EXPECT_LE(s.fit_elements, s.design_elements * 3 / 2) << "seed " << seed;
        EXPECT_GT(fit.quality.noise_sigma_m, 0.7) << "seed " << seed;
        EXPECT_LT(fit.quality.noise_sigma_m, 1.6) << "seed " << seed;
    }
}

TEST(DesignFit, TiedEndsAreMet) {
    truth::TruthOptions t;
    t.sigma_m = 0.3;
    t.outlier_fraction = 0.0;
    t.length_m = 3000.0;
    for (int seed = 1000; seed < 1005; ++seed) {
        const truth::TruthRoute r = truth::make_route(static_cast<std::uint64_t>(seed), t);
        const geometry::Pose start = geometry::evaluate(r.design, 0.0);
        const geometry::Pose end = geometry::evaluate(r.design, geometry::length(r.design));
        std::vector<geometry::Point> nodes = r.nodes;
        nodes.front() = {start.x, start.y};
        nodes.back() = {end.x, end.y};
        const geometry::FitResult fit = geometry::fit_alignment(nodes, start, end, design_search());
        const geometry::Pose a = geometry::evaluate(fit.alignment, 0.0);
        const geometry::Pose b = geometry::evaluate(fit.alignment, geometry::length(fit.alignment));
        EXPECT_NEAR(a.x, start.x, 1e-6) << "seed " << seed;
        EXPECT_NEAR(a.y, start.y, 1e-6) << "seed " << seed;
        EXPECT_NEAR(a.hdg, start.hdg, 1e-8) << "seed " << seed;
        EXPECT_LT(std::hypot(b.x - end.x, b.y - end.y), 1e-3) << "seed " << seed;
        EXPECT_NEAR(std::remainder(b.hdg - end.hdg, 2 * M_PI), 0.0, 1e-4) << "seed " << seed;
        EXPECT_LT(truth::score(r, fit.alignment).deviation_max_m, 1.5) << "seed " << seed;
    }
}
