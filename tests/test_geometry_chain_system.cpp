// A chain's normal equations by the Riccati recursion
// (geometry/src/fit/chain_system.hpp) against the dense ones they replace:
// the same gradient, diagonal, products and damped steps on chains with
// free and tied starts, shared and fixed knot curvatures, priors, held
// knots, a tied end; and the same fit from solve().
#include "fit/chain_linearise.hpp"
#include "fit/least_squares.hpp"
#include "fit/residuals.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <optional>
#include <vector>

using namespace railodd::geometry;
using namespace railodd::geometry::fit;

namespace {

double noise(std::uint64_t& s) {
    s = s * 6364136223846793005ULL + 1442695040888963407ULL;
    return static_cast<double>(s >> 11) / 9007199254740992.0 - 0.5;
}

// Line, transition, arc, transition, reverse transition, arc, transition,
// line, with the arcs' two knots one variable and the lines' fixed at zero;
// a free first knot where the start is tied (a branch at its switch).
CurvatureModel s_curve(bool start_free) {
    CurvatureModel m;
    m.start = {120.0, -40.0, 0.3, 0.0};
    m.start_free = start_free;
    if (start_free) {
        m.knot_var = {-1};
        m.knot_fixed = {0.0};
    } else {
        m.curv.push_back(1e-4);
        m.knot_var = {0};
        m.knot_fixed = {0.0};
    }
    const auto var = [&](double k) {
        m.curv.push_back(k);
        return static_cast<int>(m.curv.size()) - 1;
    };
    m.push_segment(150.0, true, -1, 0.0);
    const int a = var(1.0 / 500.0);
    m.push_segment(70.0, true, a);
    m.push_segment(120.0, true, a);
    m.push_segment(60.0, true, -1, 0.0);
    const int b = var(-1.0 / 800.0);
    m.push_segment(50.0, true, b);
    m.push_segment(90.0, true, b);
    m.push_segment(50.0, true, var(-1e-4));
    m.push_segment(140.0, false, -1, 0.0);
    return m;
}

std::vector<Point2> nodes_on(const CurvatureModel& m, double spacing, std::uint64_t seed) {
    const Alignment a = m.to_alignment();
    double total = 0.0;
    for (const Primitive& p : a.primitives) {
        total += p.length;
    }
    std::vector<Point2> pts;
    std::uint64_t s = seed;
    for (double at = 0.0; at <= total; at += spacing) {
        const Pose c = evaluate(a, at);
        pts.push_back({c.x + 0.6 * noise(s), c.y + 0.6 * noise(s)});
    }
    return pts;
}

// The model a little off the one the nodes were drawn from.
CurvatureModel nudged(CurvatureModel m) {
    for (double& l : m.lengths) {
        l *= 1.03;
    }
    for (double& k : m.curv) {
        k *= 0.9;
    }
    m.start.hdg += 0.002;
    return m;
}

SolveOptions options(bool priors, bool end) {
    SolveOptions so;
    so.sigma_m = 0.3;
    so.geodesic_acceleration = true;
    if (priors) {
        so.transition_prior = {0, 2.0, 0, 2.0, 2.0, 0, 2.0, 0};
        so.guide_weight = {0, 0, 50.0, 0, 0, 30.0, 0, 0};
        so.guide_curvature = {0, 0, 1.0 / 520.0, 0, 0, -1.0 / 790.0, 0, 0};
        so.guide_at = {0.5, 0.5, 0.4, 0.5, 0.5, 0.6, 0.5, 0.5};
        so.knot_at.assign(9, 0.0);
        so.knot_weight.assign(9, 0.0);
        so.knot_at[4] = 400.0;
        so.knot_weight[4] = 1.0;
    }
    if (end) {
        CurvatureModel truth = s_curve(false);
        so.end = truth.knot_poses().back();
        so.pin_first = false;
    }
    return so;
}

struct Case {
    bool start_free, priors, end;
};

class ChainSystemMatchesDense : public ::testing::TestWithParam<Case> {};

TEST_P(ChainSystemMatchesDense, GradientDiagonalProductsAndDampedSteps) {
    const Case c = GetParam();
    const CurvatureModel truth = s_curve(c.start_free);
    const std::vector<Point2> pts = nodes_on(truth, 9.0, 17);
    const CurvatureModel m = nudged(truth);
    SolveOptions dense_opt = options(c.priors, c.end);
    SolveOptions chain_opt = dense_opt;
    chain_opt.chain_solve = true;
    const ParameterMap map(m);
    std::vector<Foot> feet_d = feet_of(m, m.knot_poses(), pts, dense_opt);
    std::vector<Foot> feet_c = feet_d;
    const Linearisation d = linearise(m, map, Problem{pts, dense_opt}, feet_d, nullptr);
    const Linearisation ch = linearise(m, map, Problem{pts, chain_opt}, feet_c, nullptr);
    ASSERT_FALSE(d.chain.has_value());
    ASSERT_TRUE(ch.chain.has_value());
    ASSERT_EQ(d.r.size(), ch.r.size());
    ASSERT_EQ(static_cast<long>(ch.chain->rows.size()), d.J.rows());

    ChainSystem sys(*ch.chain);
    const Eigen::MatrixXd JtJ = d.J.transpose() * d.J;
    const Eigen::VectorXd g = d.J.transpose() * d.r;
    const double gscale = g.cwiseAbs().maxCoeff();
    EXPECT_LT((sys.transpose_times(ch.r) - g).cwiseAbs().maxCoeff(), 1e-6 * gscale);
    EXPECT_LT((sys.diagonal() - JtJ.diagonal()).cwiseAbs().maxCoeff(), 1e-6 * JtJ.diagonal().maxCoeff());
    Eigen::VectorXd v(static_cast<long>(map.size()));
    std::uint64_t s = 5;
    for (long i = 0; i < v.size(); ++i) {
        v[i] = noise(s);
    }
    const Eigen::VectorXd Jv = d.J * v;
    EXPECT_LT((sys.times(v) - Jv).cwiseAbs().maxCoeff(), 1e-6 * Jv.cwiseAbs().maxCoeff());
    if (c.end) {
        ASSERT_EQ(d.C.rows(), ch.C.rows());
        EXPECT_LT((d.C - ch.C).cwiseAbs().maxCoeff(), 1e-5 * d.C.cwiseAbs().maxCoeff());
        // The end gap as rows of the end state (where the end is held by
        // weighted rows instead of constraints) moves as C says.
        ChainJacobian with_end = *ch.chain;
        for (long g = 0; g < ch.end_state.rows(); ++g) {
            ChainRow row;
            row.stage = with_end.segments();
            row.c.head<chain_states>() = ch.end_state.row(g).transpose();
            with_end.rows.push_back(row);
        }
        const Eigen::VectorXd Cv = d.C * v;
        const Eigen::VectorXd tail = ChainSystem(with_end).times(v).tail(Cv.size());
        EXPECT_LT((tail - Cv).cwiseAbs().maxCoeff(), 1e-5 * Cv.cwiseAbs().maxCoeff());
    }
    for (const double mu : {1e-6, 1e-3, 1.0}) {
        const Eigen::VectorXd damping = mu * (JtJ.diagonal().array() + 1e-12).matrix();
        Eigen::MatrixXd A = JtJ;
        A.diagonal() += damping;
        const Eigen::VectorXd dense_step = A.ldlt().solve(-g);
        sys.factor(mu * (sys.diagonal().array() + 1e-12).matrix());
        const Eigen::VectorXd chain_step = sys.solve(-g);
        // The system is ill-conditioned (lengths against curvatures, lever
        // arms of a kilometre): the steps differ along directions that
        // hardly change the quadratic model. Measured in A's own norm, and
        // by the equations' residual.
        const Eigen::VectorXd diff = chain_step - dense_step;
        const double model = 0.5 * dense_step.dot(A * dense_step) + g.dot(dense_step);
        EXPECT_LT(diff.dot(A * diff), 1e-9 * std::abs(model)) << "mu " << mu;
        EXPECT_LT((A * chain_step + g).norm(), 1e-7 * g.norm()) << "mu " << mu;
    }
}

INSTANTIATE_TEST_SUITE_P(Chains, ChainSystemMatchesDense,
                         ::testing::Values(Case{true, false, false}, Case{true, true, false}, Case{false, true, false},
                                           Case{false, true, true}, Case{false, false, true}));

// The whole Levenberg-Marquardt solve takes the same path either way.
TEST(ChainSystem, SolveReachesTheDenseSolvesFit) {
    for (const Case c : {Case{true, true, false}, Case{false, true, true}}) {
        const CurvatureModel truth = s_curve(c.start_free);
        const std::vector<Point2> pts = nodes_on(truth, 7.0, 29);
        CurvatureModel dense = nudged(truth);
        CurvatureModel chain = dense;
        SolveOptions so = options(c.priors, c.end);
        const SolveReport rd = solve(dense, pts, so);
        so.chain_solve = true;
        const SolveReport rc = solve(chain, pts, so);
        EXPECT_TRUE(rc.end_met);
        EXPECT_NEAR(rc.rms_m, rd.rms_m, 1e-6);
        EXPECT_NEAR(rc.max_m, rd.max_m, 1e-5);
        for (std::size_t j = 0; j < dense.segments(); ++j) {
            EXPECT_NEAR(chain.lengths[j], dense.lengths[j], 1e-4) << "segment " << j;
        }
        for (std::size_t v = 0; v < dense.curv.size(); ++v) {
            EXPECT_NEAR(chain.curv[v], dense.curv[v], 1e-9) << "variable " << v;
        }
    }
}

} // namespace
