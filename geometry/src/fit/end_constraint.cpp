#include "end_constraint.hpp"

#include <algorithm>
#include <cmath>

namespace railodd::geometry::fit {

std::size_t end_rows(const CurvatureModel& m) { return m.knot_var.back() >= 0 ? 4 : 3; }

Eigen::VectorXd end_gap(const CurvatureModel& m, const Pose& end, const Pose& target) {
    Eigen::VectorXd c(static_cast<long>(end_rows(m)));
    c[0] = end.x - target.x;
    c[1] = end.y - target.y;
    // Headings a turn apart are one heading (a chain's integrated heading
    // runs past pi; a tie's is normalised).
    c[2] = end_heading_scale * std::remainder(end.hdg - target.hdg, 2.0 * std::acos(-1.0));
    if (c.size() == 4) {
        c[3] = end_curvature_scale * (end.curvature - target.curvature);
    }
    return c;
}

namespace {

// A^-1 C^T and the Schur complement C A^-1 C^T, factored.
struct Schur {
    Eigen::MatrixXd W;
    Eigen::LDLT<Eigen::MatrixXd> S;
    bool ok = false;
};

Schur schur(const NormalMatrix& A, const Eigen::MatrixXd& C) {
    Schur s;
    s.W = A.solve(C.transpose());
    const Eigen::MatrixXd S = C * s.W;
    s.S.compute(S);
    // A constraint no parameter can move leaves a (near) zero pivot: the
    // model cannot reach the end exactly and the caller falls back to
    // weighted rows.
    const Eigen::VectorXd d = s.S.vectorD();
    const double largest = d.cwiseAbs().maxCoeff();
    s.ok = s.S.info() == Eigen::Success && std::isfinite(largest) && largest > 0.0 &&
           d.minCoeff() > 1e-12 * largest && s.W.allFinite();
    return s;
}

} // namespace

std::optional<Eigen::VectorXd> constrained_step(const NormalMatrix& A, const Eigen::VectorXd& g,
                                                const Eigen::MatrixXd& C, const Eigen::VectorXd& c) {
    const Schur s = schur(A, C);
    if (!s.ok) {
        return std::nullopt;
    }
    const Eigen::VectorXd free_step = A.solve(-g);
    const Eigen::VectorXd lambda = s.S.solve(c + C * free_step);
    Eigen::VectorXd d = free_step - s.W * lambda;
    if (!d.allFinite()) {
        return std::nullopt;
    }
    return d;
}

double project_onto_end(Eigen::VectorXd& values, const NormalMatrix& A, const Eigen::MatrixXd& C,
                        const std::function<Eigen::VectorXd(const Eigen::VectorXd&)>& apply) {
    Eigen::VectorXd gap = apply(values);
    double best = gap.cwiseAbs().maxCoeff();
    const Schur s = schur(A, C);
    if (!s.ok || !std::isfinite(best)) {
        return best;
    }
    for (int it = 0; it < 8 && best >= end_tolerance; ++it) {
        const Eigen::VectorXd next = values - s.W * s.S.solve(gap);
        const Eigen::VectorXd next_gap = apply(next);
        const double now = next_gap.cwiseAbs().maxCoeff();
        if (!std::isfinite(now) || now > 0.5 * best) {
            break; // not contracting: too far from the linearisation
        }
        values = next;
        gap = next_gap;
        best = now;
    }
    apply(values); // the model holds the values returned
    return best;
}

bool meet_end(CurvatureModel& m, const Pose& target) {
    // Enough segments for a line's, a transition's and an arc's worth of
    // freedom whatever the last few are.
    constexpr std::size_t reach = 8;
    const ParameterMap map(m);
    const std::size_t first = m.segments() > reach ? m.segments() - reach : 0;
    std::vector<std::size_t> moved;
    for (std::size_t i = 0; i < map.size(); ++i) {
        if (!map.is_start(i) && map.influence(i).second >= first) {
            moved.push_back(i);
        }
    }
    const auto gap = [&](const CurvatureModel& x) { return end_gap(x, x.knot_poses().back(), target); };
    const Eigen::VectorXd c = gap(m);
    const std::vector<double> base = map.get(m);
    Eigen::MatrixXd C(c.size(), static_cast<long>(moved.size()));
    Eigen::VectorXd metric(static_cast<long>(moved.size()));
    CurvatureModel nudged = m;
    for (std::size_t j = 0; j < moved.size(); ++j) {
        const std::size_t i = moved[j];
        const double h = map.difference_step(i);
        map.set_one(nudged, i, base[i] + h);
        C.col(static_cast<long>(j)) = (gap(nudged) - c) / h;
        map.set_one(nudged, i, base[i]);
        metric[static_cast<long>(j)] = map.is_curvature(i) ? end_curvature_scale * end_curvature_scale : 1.0;
    }
    const DenseNormal A(Eigen::MatrixXd(metric.asDiagonal()));
    Eigen::VectorXd v(static_cast<long>(moved.size()));
    for (std::size_t j = 0; j < moved.size(); ++j) {
        v[static_cast<long>(j)] = base[moved[j]];
    }
    CurvatureModel trial = m;
    const double left = project_onto_end(v, A, C, [&](const Eigen::VectorXd& values) {
        for (std::size_t j = 0; j < moved.size(); ++j) {
            map.set_one(trial, moved[j], values[static_cast<long>(j)]);
        }
        const bool shrunk = std::any_of(trial.lengths.begin(), trial.lengths.end(), [](double l) { return !(l > 0.0); });
        return shrunk ? Eigen::VectorXd::Constant(c.size(), HUGE_VAL) : gap(trial);
    });
    if (!(left < end_tolerance)) {
        return false;
    }
    m = std::move(trial);
    return true;
}

} // namespace railodd::geometry::fit
