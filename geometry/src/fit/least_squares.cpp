#include "least_squares.hpp"

#include "end_constraint.hpp"
#include "residuals.hpp"

#include "../loop_bounds.hpp"
#include "railodd/geometry/indexed_alignment.hpp"

#include <Eigen/Dense>

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>

namespace railodd::geometry::fit {

std::vector<double> point_distances(const CurvatureModel& model, const std::vector<Point2>& points) {
    return foot_distances(model, points);
}

namespace {

// Is a fit still this far above the cost it must reach, and converging this
// slowly, beyond hope? Levenberg-Marquardt's gains shrink as it converges: at
// the current rate, with twice the slack, the remaining iterations cannot get
// there. Structure candidates that cannot match the fine spline stop here
// after a few iterations instead of forty.
bool hopeless(double cost, double gain, int remaining, double target) {
    if (!std::isfinite(target) || cost <= 2.0 * target) {
        return false;
    }
    return cost * std::pow(1.0 - std::min(1.0, 2.0 * gain), remaining) > target;
}

// J^T J and J^T r of one linearisation, damped and factored on demand:
// dense, or a chain's (chain_system.hpp).
class Normal {
public:
    explicit Normal(const Linearisation& lin) : lin_(lin) {
        if (lin.chain) {
            chain_.emplace(*lin.chain);
            diagonal_ = chain_->diagonal();
            gradient_ = chain_->transpose_times(lin.r);
            return;
        }
        dense_equations();
        diagonal_ = JtJ_.diagonal();
    }
    const Eigen::VectorXd& gradient() const noexcept { return gradient_; }
    // J's columns' squared norms: J^T J's diagonal (for a dense J summed
    // apart from it, as the geodesic acceleration always took them).
    Eigen::VectorXd column_norms() const {
        return chain_ ? diagonal_ : Eigen::VectorXd(lin_.J.colwise().squaredNorm().transpose());
    }
    Eigen::VectorXd times(const Eigen::VectorXd& v) const {
        return chain_ ? chain_->times(v) : Eigen::VectorXd(lin_.J * v);
    }
    Eigen::VectorXd transpose_times(const Eigen::VectorXd& y) const {
        return chain_ ? chain_->transpose_times(y) : Eigen::VectorXd(lin_.J.transpose() * y);
    }
    // J^T J + mu diag(J^T J), factored.
    const NormalMatrix& damped(double mu) {
        const Eigen::VectorXd d = mu * (diagonal_.array() + 1e-12).matrix();
        if (chain_) {
            chain_->factor(d);
            return *chain_;
        }
        Eigen::MatrixXd A = JtJ_;
        A.diagonal() += d;
        dense_.emplace(A);
        return *dense_;
    }

private:
    // J^T J (lower triangle: LDLT reads no more) and J^T r. The dense point
    // rows by one product; the sparse rows below them one at a time, by their
    // non-zero entries: the fine spline has two smoothness rows per knot and
    // about a knot per point, so a dense product over them was most of its
    // cost.
    void dense_equations() {
        const Linearisation& lin = lin_;
        const long cols = lin.J.cols(), top = std::min(lin.dense_rows, lin.J.rows());
        JtJ_ = Eigen::MatrixXd::Zero(cols, cols);
        JtJ_.selfadjointView<Eigen::Lower>().rankUpdate(lin.J.topRows(top).transpose());
        gradient_ = lin.J.topRows(top).transpose() * lin.r.head(top);
        std::vector<long> nz;
        for (long row = top; row < lin.J.rows(); ++row) {
            nz.clear();
            for (long c = 0; c < cols; ++c) {
                if (lin.J(row, c) != 0.0) {
                    nz.push_back(c);
                }
            }
            for (std::size_t a = 0; a < nz.size(); ++a) {
                const double ja = lin.J(row, nz[a]);
                gradient_[nz[a]] += ja * lin.r[row];
                for (std::size_t b = 0; b <= a; ++b) {
                    JtJ_(nz[a], nz[b]) += ja * lin.J(row, nz[b]);
                }
            }
        }
    }

    const Linearisation& lin_;
    Eigen::MatrixXd JtJ_;
    Eigen::VectorXd gradient_, diagonal_;
    std::optional<ChainSystem> chain_;
    std::optional<DenseNormal> dense_;
};

// How the end pose is held: not at all, as exact constraints, or (where the
// model cannot meet it exactly) as heavily weighted residual rows.
enum class EndMode { none, exact, weighted };

// One Levenberg-Marquardt solve's state: the model, the feet of the points,
// the damping.
class LevenbergMarquardt {
public:
    LevenbergMarquardt(CurvatureModel& model, const std::vector<Point2>& points, const SolveOptions& options)
        : model_(model), map_(model), p_{points, options},
          feet_(feet_of(model, model.knot_poses(), points, options)),
          mode_(!options.end                          ? EndMode::none
                : map_.size() >= end_rows(model) ? EndMode::exact
                                                      : EndMode::weighted),
          on_end_(!options.end) {
        if (options.abandon_loops) {
            loop_bounds_.emplace(points);
        }
        // No segment, nor the whole curve, needs to be longer than twice the
        // polyline through the data.
        for (std::size_t i = 1; i < points.size(); ++i) {
            max_length_ += 2.0 * std::hypot(points[i].x - points[i - 1].x, points[i].y - points[i - 1].y);
        }
    }

    SolveReport run() {
        SolveReport report;
        const double give_up_cost = p_.opt.give_up_rss / (p_.opt.sigma_m * p_.opt.sigma_m);
        for (int it = 0; it < p_.opt.max_iterations && map_.size() > 0; ++it) {
            report.iterations = it + 1;
            const Outcome o = iterate();
            if (o == Outcome::fell_back) {
                continue;
            }
            if (o == Outcome::stuck) {
                break;
            }
            if (total_length(model_) > max_length_ || (loop_bounds_ && loops())) {
                // Diverged: the curve has grown far longer than the data
                // (spiralling at the curvature bound), or loops where the
                // caller will reject it. Nothing to keep.
                report.gave_up = true;
                break;
            }
            if (o == Outcome::reached_end || o == Outcome::approaching_end) {
                continue; // the gain of a step towards the end says nothing
            }
            if (gain_ < 1e-4 || drop_ < 0.01) {
                // Converged for every use made of the cost: a step gained
                // less than a hundredth of a noise variance over the whole
                // window (the rows are distances over sigma), against the
                // F-test's 1.6 per parameter, or a ten-thousandth of the
                // cost. Small, nearly unidentifiable windows (ten
                // parameters, a dozen nodes) crept down their flat valleys
                // by a few thousandths per step until the relative test
                // alone stopped them.
                break;
            }
            if (hopeless(cost_, gain_, p_.opt.max_iterations - it - 1, give_up_cost)) {
                report.gave_up = true;
                break;
            }
        }
        return report;
    }

private:
    bool loops() const {
        double turning = 0.0;
        for (std::size_t j = 0; j < model_.segments(); ++j) {
            turning += piece_turning(model_.knot_curvature(j), model_.knot_curvature(j + 1), model_.lengths[j]);
        }
        return loop_bounds_->exceeded(total_length(model_), turning);
    }

    enum class Outcome { improved, approaching_end, reached_end, stuck, fell_back };

    // A trial model and the largest row of its end gap (0 without an end).
    struct Trial {
        CurvatureModel model;
        double gap = 0.0;
    };

    // One linearisation and up to ten damped steps from it.
    Outcome iterate() {
        Linearisation lin = linearise(model_, map_, p_, feet_, known_ ? &*known_ : nullptr);
        known_.reset();
        if (mode_ == EndMode::weighted) {
            append_end_rows(lin);
        }
        const double cost = lin.r.squaredNorm();
        const double gap = mode_ == EndMode::exact ? lin.c.cwiseAbs().maxCoeff() : 0.0;
        Normal normal(lin);
        for (int tries = 0; tries < 10; ++tries) {
            const NormalMatrix& A = normal.damped(mu_);
            // Away from the end pose, steps aim at a shrinking share of the
            // gap until one closes part of it.
            const double share = on_end_ ? 1.0 : std::pow(0.5, tries);
            std::optional<Trial> t =
                mode_ == EndMode::exact ? exact_trial(A, normal, lin, share) : free_trial(A, normal, lin);
            if (!t) {
                mode_ = EndMode::weighted; // this model cannot meet the end exactly
                return Outcome::fell_back;
            }
            if (!on_end_ && (t->gap < end_tolerance || t->gap < (1.0 - 0.25 * share) * gap)) {
                // Nearer the end: the data cost does not count yet.
                on_end_ = t->gap < end_tolerance;
                Evaluated e;
                const double c = cost_at_feet(t->model, p_, feet_, false, e);
                accept(std::move(t->model), cost, c, std::move(e));
                return on_end_ ? Outcome::reached_end : Outcome::approaching_end;
            }
            Evaluated e;
            const double c = cost_at_feet(t->model, p_, feet_, mode_ == EndMode::weighted, e);
            if (on_end_ && t->gap < end_tolerance && std::isfinite(c) && c < cost) {
                accept(std::move(t->model), cost, c, std::move(e));
                return Outcome::improved;
            }
            mu_ *= 4;
        }
        if (!on_end_) {
            mode_ = EndMode::weighted;
            return Outcome::fell_back;
        }
        return Outcome::stuck;
    }

    void accept(CurvatureModel&& m, double before, double after, Evaluated&& e) {
        known_ = std::move(e);
        gain_ = (before - after) / std::max(before, 1e-30);
        drop_ = before - after;
        cost_ = after;
        model_ = std::move(m);
        mu_ = std::max(mu_ / 3, 1e-9);
    }

    std::optional<Trial> free_trial(const NormalMatrix& A, const Normal& normal, const Linearisation& lin) const {
        const Eigen::VectorXd x = to_eigen(map_.get(model_));
        const Eigen::VectorXd v = A.solve(-normal.gradient());
        Trial t{model_, 0.0};
        apply(t.model, x + v + 0.5 * acceleration(A, normal, lin, x, v));
        return t;
    }

    // Geodesic acceleration (Transtrum and Sethna): the second directional
    // derivative of the residuals along the step bends it along the curved
    // valleys that otherwise hold LM to small steps. Zero where it would
    // dominate the step.
    Eigen::VectorXd acceleration(const NormalMatrix& A, const Normal& normal, const Linearisation& lin,
                                 const Eigen::VectorXd& x, const Eigen::VectorXd& v) const {
        if (!p_.opt.geodesic_acceleration) {
            return Eigen::VectorXd::Zero(v.size());
        }
        const double h = 0.1;
        CurvatureModel probe = model_;
        apply(probe, x + h * v);
        const Eigen::VectorXd r2 = residuals_at_feet(probe, p_, feet_, mode_ == EndMode::weighted);
        if (r2.size() != lin.r.size()) {
            return Eigen::VectorXd::Zero(v.size());
        }
        const Eigen::VectorXd rvv = (2.0 / h) * ((r2 - lin.r) / h - normal.times(v));
        const Eigen::VectorXd a = -A.solve(normal.transpose_times(rvv));
        const Eigen::VectorXd scale = (normal.column_norms().array() + 1e-12).sqrt().matrix();
        const double ratio = a.cwiseProduct(scale).norm() / std::max(v.cwiseProduct(scale).norm(), 1e-300);
        return 2.0 * ratio <= 0.75 ? a : Eigen::VectorXd::Zero(v.size());
    }

    // The constrained step (closing `share` of the end gap), then on towards
    // the end pose.
    std::optional<Trial> exact_trial(const NormalMatrix& A, const Normal& normal, const Linearisation& lin,
                                     double share) const {
        const std::optional<Eigen::VectorXd> d = constrained_step(A, normal.gradient(), lin.C, share * lin.c);
        if (!d) {
            return std::nullopt;
        }
        Trial t{model_, 0.0};
        Eigen::VectorXd v = to_eigen(map_.get(model_)) + *d;
        t.gap = project_onto_end(v, A, lin.C, [&](const Eigen::VectorXd& values) {
            apply(t.model, values);
            return end_gap(t.model, t.model.knot_poses().back(), *p_.opt.end);
        });
        return t;
    }

    void apply(CurvatureModel& m, const Eigen::VectorXd& values) const {
        map_.set(m, std::vector<double>(values.data(), values.data() + values.size()));
        clamp_model(m, p_.opt.min_length_m, p_.opt.min_length_at, max_length_, p_.opt.max_curvature);
    }

    static Eigen::VectorXd to_eigen(const std::vector<double>& v) {
        return Eigen::Map<const Eigen::VectorXd>(v.data(), static_cast<long>(v.size()));
    }

    void append_end_rows(Linearisation& lin) const {
        if (lin.chain) {
            const long n = lin.r.size(), k = lin.end_state.rows();
            for (long g = 0; g < k; ++g) {
                ChainRow row;
                row.stage = lin.chain->segments();
                row.c.head<chain_states>() = end_weight * lin.end_state.row(g).transpose();
                lin.chain->rows.push_back(row);
            }
            lin.r.conservativeResize(n + k);
            lin.r.tail(k) = end_weight * lin.c;
            return;
        }
        const long n = lin.J.rows(), k = lin.C.rows();
        lin.J.conservativeResize(n + k, Eigen::NoChange);
        lin.J.bottomRows(k) = end_weight * lin.C;
        lin.r.conservativeResize(n + k);
        lin.r.tail(k) = end_weight * lin.c;
    }

    CurvatureModel& model_;
    const ParameterMap map_;
    const Problem p_;
    std::vector<Foot> feet_;
    EndMode mode_;
    bool on_end_;
    double max_length_ = 50.0;
    double mu_ = 1e-3;
    std::optional<LoopBounds> loop_bounds_;
    std::optional<Evaluated> known_; // model_ evaluated by the cost of the step that made it
    double cost_ = 0.0;
    double gain_ = 0.0;
    double drop_ = 0.0;
};

SolveReport solve_once(CurvatureModel& model, const std::vector<Point2>& points, const SolveOptions& options) {
    return LevenbergMarquardt(model, points, options).run();
}

} // namespace

SolveReport solve(CurvatureModel& model, const std::vector<Point2>& points, const SolveOptions& options) {
    SolveReport report;
    if (options.end) {
        // Reaching a far end pose from a rough start makes a stiff problem:
        // fit the data first, then pull the end into place.
        SolveOptions free_end = options;
        free_end.end.reset();
        const SolveReport first = solve_once(model, points, free_end);
        report.iterations = first.iterations;
        report.gave_up = first.gave_up;
    }
    if (!report.gave_up) {
        // The end rows weigh in the cost here: only the free fit may give up.
        SolveOptions with_end = options;
        if (options.end) {
            with_end.give_up_rss = std::numeric_limits<double>::infinity();
        }
        const SolveReport second = solve_once(model, points, with_end);
        report.iterations += second.iterations;
        report.gave_up = second.gave_up;
    }
    if (report.gave_up) {
        report.rms_m = report.max_m = std::numeric_limits<double>::infinity();
        return report;
    }
    if (options.end) {
        report.end_met = end_gap(model, model.knot_poses().back(), *options.end).cwiseAbs().maxCoeff() < end_tolerance;
    }
    report.distances_m = point_distances(model, points);
    double sum = 0.0;
    for (double x : report.distances_m) {
        sum += x * x;
        report.max_m = std::max(report.max_m, x);
    }
    report.rms_m = report.distances_m.empty() ? 0.0 : std::sqrt(sum / static_cast<double>(report.distances_m.size()));
    return report;
}

bool far_point_scale(const std::vector<double>& distances, double cap, std::vector<std::size_t>& previous,
                     std::vector<double>& scale) {
    std::vector<std::size_t> far;
    std::vector<double> out(distances.size(), 1.0);
    for (std::size_t i = 0; i < distances.size(); ++i) {
        if (distances[i] > cap) {
            out[i] = cap / distances[i];
            far.push_back(i);
        }
    }
    if (far.empty() || far.size() > 2 + distances.size() / 50 || far == previous) {
        return false;
    }
    previous = std::move(far);
    scale = std::move(out);
    return true;
}

} // namespace railodd::geometry::fit
