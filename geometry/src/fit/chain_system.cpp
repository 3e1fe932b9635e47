// The Riccati recursion for a chain's damped normal equations (chain_system.hpp).
#include "chain_system.hpp"

namespace railodd::geometry::fit {

namespace {

constexpr int kappa = 3;      // state slot: curvature variable at the first knot
constexpr int arc_length = 4; // state slot: arc length to it

using State = Eigen::Matrix<double, chain_states, 1>;
using Control = Eigen::Matrix<double, chain_controls, 1>;

// The state a parameter leaves behind once its segments are passed: its
// twist, the end knot's curvature where it is that variable, a length's
// share of the arc length.
State after(const Eigen::Vector3d& w, double kappa_share, double length_share) {
    State y;
    y << w, kappa_share, length_share;
    return y;
}

} // namespace

ChainSystem::ChainSystem(const ChainJacobian& j)
    : j_(j), gram_(j.segments() + 1, Slots::Zero()), steps_(j.segments()) {
    for (const ChainRow& r : j.rows) {
        gram_[r.stage].selfadjointView<Eigen::Lower>().rankUpdate(r.c);
    }
    for (Slots& g : gram_) {
        g = g.selfadjointView<Eigen::Lower>();
    }
    if (j.start_free()) {
        start_inverse_ = j.start_twist.inverse();
    }
    transitions();
    diagonal_of_normal();
}

// x' = A x + B u: the twist gains the rigid motions of the parameters whose
// segments end here, the curvature passes on or is replaced, the arc
// length grows by the segment's length.
void ChainSystem::transitions() {
    for (std::size_t s = 0; s < j_.segments(); ++s) {
        const ChainStage& st = j_.stages[s];
        Step& step = steps_[s];
        step.A.setIdentity();
        step.A(kappa, kappa) = st.carried_on ? 1.0 : 0.0;
        if (st.carried_ends) {
            step.A.block<3, 1>(0, kappa) = st.w_carried;
        }
        step.B.setZero();
        if (st.length >= 0) {
            step.B.block<3, 1>(0, 0) = st.w_length;
            step.B(arc_length, 0) = 1.0;
        }
        if (st.fresh >= 0) {
            step.B(kappa, 1) = 1.0;
            if (st.fresh_ends) {
                step.B.block<3, 1>(0, 1) = st.w_fresh;
            }
        }
    }
}

// A parameter's column of J: its own slot in the rows of its segments, and
// beyond them the state it leaves behind, which later rows read through
// the sums of their state Gram matrices.
void ChainSystem::diagonal_of_normal() {
    const std::size_t n = j_.segments();
    std::vector<StateMatrix> beyond(n + 1);
    beyond[n] = gram_[n].topLeftCorner<chain_states, chain_states>();
    for (std::size_t s = n; s-- > 0;) {
        beyond[s] = beyond[s + 1] + gram_[s].topLeftCorner<chain_states, chain_states>();
    }
    diagonal_ = Eigen::VectorXd::Zero(static_cast<long>(j_.parameters));
    const auto add = [&](long p, double v) {
        if (p >= 0) {
            diagonal_[p] += v;
        }
    };
    for (std::size_t s = 0; s < n; ++s) {
        const ChainStage& st = j_.stages[s];
        const Slots& g = gram_[s];
        add(st.carried, g(kappa, kappa));
        add(st.length, g(5, 5));
        add(st.fresh, g(6, 6));
        if (st.length >= 0) {
            const State y = after(st.w_length, 0.0, 1.0);
            add(st.length, y.dot(beyond[s + 1] * y));
        }
        if (st.carried >= 0 && st.carried_ends) {
            const State y = after(st.w_carried, st.carried_on ? 1.0 : 0.0, 0.0);
            add(st.carried, y.dot(beyond[s + 1] * y));
        }
        if (st.fresh >= 0 && st.fresh_ends) {
            const State y = after(st.w_fresh, 1.0, 0.0);
            add(st.fresh, y.dot(beyond[s + 1] * y));
        }
    }
    for (int c = 0; c < 3 && j_.start_free(); ++c) {
        const State y = after(j_.start_twist.col(c), 0.0, 0.0);
        add(j_.start[static_cast<std::size_t>(c)], y.dot(beyond[0] * y));
    }
}

double ChainSystem::damping_at(long parameter) const { return parameter >= 0 ? damping_[parameter] : 1.0; }

void ChainSystem::factor(const Eigen::VectorXd& damping) {
    damping_ = damping;
    const std::size_t n = j_.segments();
    StateMatrix P = gram_[n].topLeftCorner<chain_states, chain_states>();
    for (std::size_t s = n; s-- > 0;) {
        Step& step = steps_[s];
        const Slots& g = gram_[s];
        const ChainStage& st = j_.stages[s];
        const StateMatrix Qxx = g.topLeftCorner<chain_states, chain_states>() + step.A.transpose() * P * step.A;
        step.Qux = g.bottomLeftCorner<chain_controls, chain_states>() + step.B.transpose() * P * step.A;
        Eigen::Matrix<double, chain_controls, chain_controls> Quu =
            g.bottomRightCorner<chain_controls, chain_controls>() + step.B.transpose() * P * step.B;
        Quu(0, 0) += damping_at(st.length);
        Quu(1, 1) += damping_at(st.fresh);
        step.Quu.compute(Quu);
        step.K = -step.Quu.solve(step.Qux);
        P = Qxx + step.Qux.transpose() * step.K;
        P = (0.5 * (P + P.transpose())).eval();
    }
    // The first state: its twist is the start pose's parameters' (damped
    // in their own units), its curvature the first knot's variable; a
    // fixed part stays zero.
    StateMatrix H = P;
    if (j_.start_free()) {
        Eigen::Vector3d d;
        for (int c = 0; c < 3; ++c) {
            d[c] = damping_[j_.start[static_cast<std::size_t>(c)]];
        }
        H.topLeftCorner<3, 3>() += start_inverse_.transpose() * d.asDiagonal() * start_inverse_;
    } else {
        H.topRows<3>().setZero();
        H.leftCols<3>().setZero();
        H.topLeftCorner<3, 3>().setIdentity();
    }
    if (j_.first_curvature >= 0) {
        H(kappa, kappa) += damping_[j_.first_curvature];
    } else {
        H.row(kappa).setZero();
        H.col(kappa).setZero();
        H(kappa, kappa) = 1.0;
    }
    H.row(arc_length).setZero();
    H.col(arc_length).setZero();
    H(arc_length, arc_length) = 1.0;
    initial_.compute(H);
}

Eigen::VectorXd ChainSystem::solve_one(const Eigen::VectorXd& b) const {
    const std::size_t n = j_.segments();
    const auto at = [&](long p) { return p >= 0 ? b[p] : 0.0; };
    std::vector<Control> k(n);
    State q = State::Zero();
    for (std::size_t s = n; s-- > 0;) {
        const Step& step = steps_[s];
        const ChainStage& st = j_.stages[s];
        const Control qu = step.B.transpose() * q - Control(at(st.length), at(st.fresh));
        k[s] = -step.Quu.solve(qu);
        q = step.A.transpose() * q + step.Qux.transpose() * k[s];
    }
    State g = q;
    if (j_.start_free()) {
        const Eigen::Vector3d bs(b[j_.start[0]], b[j_.start[1]], b[j_.start[2]]);
        g.head<3>() -= start_inverse_.transpose() * bs;
    } else {
        g.head<3>().setZero();
    }
    g[kappa] = j_.first_curvature >= 0 ? g[kappa] - b[j_.first_curvature] : 0.0;
    g[arc_length] = 0.0;
    State x = -initial_.solve(g);
    Eigen::VectorXd out = Eigen::VectorXd::Zero(b.size());
    if (j_.start_free()) {
        const Eigen::Vector3d ds = start_inverse_ * x.head<3>();
        for (int c = 0; c < 3; ++c) {
            out[j_.start[static_cast<std::size_t>(c)]] = ds[c];
        }
    }
    if (j_.first_curvature >= 0) {
        out[j_.first_curvature] = x[kappa];
    }
    for (std::size_t s = 0; s < n; ++s) {
        const Step& step = steps_[s];
        const ChainStage& st = j_.stages[s];
        const Control u = step.K * x + k[s];
        if (st.length >= 0) {
            out[st.length] = u[0];
        }
        if (st.fresh >= 0) {
            out[st.fresh] = u[1];
        }
        x = step.A * x + step.B * u;
    }
    return out;
}

Eigen::MatrixXd ChainSystem::solve(const Eigen::MatrixXd& B) const {
    Eigen::MatrixXd X(B.rows(), B.cols());
    for (long c = 0; c < B.cols(); ++c) {
        X.col(c) = solve_one(B.col(c));
    }
    return X;
}

Eigen::VectorXd ChainSystem::times(const Eigen::VectorXd& v) const {
    const std::size_t n = j_.segments();
    const auto at = [&](long p) { return p >= 0 ? v[p] : 0.0; };
    std::vector<ChainRowCoefficients> z(n + 1, ChainRowCoefficients::Zero());
    State x = State::Zero();
    if (j_.start_free()) {
        x.head<3>() = j_.start_twist * Eigen::Vector3d(v[j_.start[0]], v[j_.start[1]], v[j_.start[2]]);
    }
    x[kappa] = at(j_.first_curvature);
    for (std::size_t s = 0; s < n; ++s) {
        const Control u(at(j_.stages[s].length), at(j_.stages[s].fresh));
        z[s] << x, u;
        x = steps_[s].A * x + steps_[s].B * u;
    }
    z[n] << x, Control::Zero();
    Eigen::VectorXd out(static_cast<long>(j_.rows.size()));
    for (std::size_t r = 0; r < j_.rows.size(); ++r) {
        out[static_cast<long>(r)] = j_.rows[r].c.dot(z[j_.rows[r].stage]);
    }
    return out;
}

Eigen::VectorXd ChainSystem::transpose_times(const Eigen::VectorXd& y) const {
    const std::size_t n = j_.segments();
    std::vector<ChainRowCoefficients> gz(n + 1, ChainRowCoefficients::Zero());
    for (std::size_t r = 0; r < j_.rows.size(); ++r) {
        gz[j_.rows[r].stage] += y[static_cast<long>(r)] * j_.rows[r].c;
    }
    Eigen::VectorXd out = Eigen::VectorXd::Zero(static_cast<long>(j_.parameters));
    State lambda = gz[n].head<chain_states>();
    for (std::size_t s = n; s-- > 0;) {
        const Control gu = gz[s].tail<chain_controls>() + steps_[s].B.transpose() * lambda;
        if (j_.stages[s].length >= 0) {
            out[j_.stages[s].length] += gu[0];
        }
        if (j_.stages[s].fresh >= 0) {
            out[j_.stages[s].fresh] += gu[1];
        }
        lambda = gz[s].head<chain_states>() + steps_[s].A.transpose() * lambda;
    }
    if (j_.start_free()) {
        const Eigen::Vector3d gs = j_.start_twist.transpose() * lambda.head<3>();
        for (int c = 0; c < 3; ++c) {
            out[j_.start[static_cast<std::size_t>(c)]] += gs[c];
        }
    }
    if (j_.first_curvature >= 0) {
        out[j_.first_curvature] += lambda[kappa];
    }
    return out;
}

} // namespace railodd::geometry::fit
