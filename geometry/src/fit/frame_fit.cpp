#include "frame_fit.hpp"

#include "frame_integrals.hpp"

#include <Eigen/Dense>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <numbers>

namespace railodd::geometry::fit {

namespace {

constexpr double pi = std::numbers::pi;

double wrap(double a) { return a - 2 * pi * std::round(a / (2 * pi)); }

struct FrameEnd {
    double s = 0.0;   // the curve's length: where the end pose (else the last node) lies on the reference
    bool pose = false; // an end pose to meet
    double y = 0.0, phi = 0.0;
};

// The end pose's place on the reference (nearest grid cell).
FrameEnd frame_end(const Frame& f, const std::optional<Pose>& end) {
    FrameEnd out;
    out.s = f.s.back();
    if (!end) {
        return out;
    }
    double best = std::numeric_limits<double>::infinity();
    for (std::size_t j = 0; j + 1 < f.x.size(); ++j) {
        const double dx = f.x[j + 1] - f.x[j], dy = f.y[j + 1] - f.y[j];
        const double len2 = dx * dx + dy * dy;
        const double qx = end->x - f.x[j], qy = end->y - f.y[j];
        const double u = std::clamp((qx * dx + qy * dy) / len2, 0.0, j + 2 == f.x.size() ? 1.5 : 1.0);
        const double d2 = (qx - u * dx) * (qx - u * dx) + (qy - u * dy) * (qy - u * dy);
        if (d2 < best) {
            best = d2;
            out.s = f.h * (static_cast<double>(j) + u);
            out.y = (dx * qy - dy * qx) / std::sqrt(len2);
        }
    }
    out.pose = true;
    out.phi = wrap(end->hdg - ReferenceHeading(f).at(out.s).hdg);
    return out;
}

// The least-squares problem in the frame, separated (variable projection):
// for given segment lengths the design's offsets are linear in the start's
// offset and heading from the reference (where free) and the curvature
// variables, which are solved for exactly; only the free lengths are
// iterated on. Residuals: the nodes' scaled offsets from the design, then
// heavily weighted end rows.
class FrameProblem {
public:
    FrameProblem(CurvatureModel& m, const Frame& f, const std::optional<Pose>& end, double sigma, double prior_sigma)
        : m_(m), f_(f), ref_(f), end_(frame_end(f, end)), sigma_(sigma), prior_sigma_(prior_sigma),
          scale_(f.s.size(), 1.0) {
        const double n0 = -std::sin(f.hdg[0]), n1 = std::cos(f.hdg[0]);
        y0_ = (m.start.x - f.x[0]) * n0 + (m.start.y - f.y[0]) * n1;
        phi0_ = wrap(m.start.hdg - f.hdg[0]);
        prior_ = m.curv;
        for (std::size_t i = 0; i < f.s.size(); ++i) {
            reference_.push_back(ref_.at(f.s[i]).integral);
        }
    }

    std::size_t rows() const { return f_.s.size() + (end_.pose ? 2 : 0); }

    // The iterated parameters: the interior knots' chainages (the last
    // knot lies at the end target, so the curve's length is met exactly).
    std::size_t knots() const { return m_.segments() - 1; }

    Eigen::VectorXd get() const {
        Eigen::VectorXd v(static_cast<Eigen::Index>(knots()));
        double s = 0.0;
        for (std::size_t j = 0; j < knots(); ++j) {
            s += m_.lengths[j];
            v[static_cast<Eigen::Index>(j)] = s;
        }
        return v;
    }

    // Knot chainages at least min_length apart, within (0, end).
    Eigen::VectorXd feasible(Eigen::VectorXd v, double min_length) const {
        const auto n = v.size();
        for (Eigen::Index j = n - 1; j >= 0; --j) {
            const double above = j + 1 < n ? v[j + 1] : end_.s;
            v[j] = std::min(v[j], above - min_length);
        }
        for (Eigen::Index j = 0; j < n; ++j) {
            v[j] = std::max(v[j], (j > 0 ? v[j - 1] : 0.0) + min_length);
        }
        return v;
    }

    // Sets the knots, solves for the linear parameters, and gives the
    // residuals and, where asked, their Jacobian in the knots (Kaufman's:
    // the derivative at fixed linear parameters, projected off their span).
    void residuals(const Eigen::VectorXd& v, Eigen::VectorXd& r, Eigen::MatrixXd* jacobian = nullptr) {
        double previous = 0.0;
        for (std::size_t j = 0; j < m_.segments(); ++j) {
            const double s = j < knots() ? v[static_cast<Eigen::Index>(j)] : end_.s;
            m_.lengths[j] = s - previous;
            previous = s;
        }
        length_ = end_.s;
        at_end_ = ref_.at(length_);
        const HatIntegrals hats = hat_integrals(m_.lengths, f_.s), end_hats = hat_integrals(m_.lengths, {length_});
        Eigen::MatrixXd columns;
        Eigen::VectorXd fixed;
        linear_system(hats, end_hats, columns, fixed);
        Eigen::LDLT<Eigen::MatrixXd> normal;
        if (columns.cols() > 0) {
            // A weak prior holds each curvature near the diagram's value
            // where the nodes hardly tell it (a segment of a metre between
            // two knots run together), so no spike of curvature buys a
            // wiggle the exact solve would keep.
            Eigen::MatrixXd nm = columns.transpose() * columns;
            Eigen::VectorXd rhs = columns.transpose() * fixed;
            nm.diagonal().array() += 1e-12;
            const std::size_t start = m_.start_free ? 2 : 0;
            for (std::size_t v = 0; v < prior_.size(); ++v) {
                const auto i = static_cast<Eigen::Index>(start + v);
                nm(i, i) += 1.0 / (prior_sigma_ * prior_sigma_);
                rhs[i] += prior_[v] / (prior_sigma_ * prior_sigma_);
            }
            normal.compute(nm);
            set_linear(normal.solve(rhs));
            r = fixed - columns * linear();
        } else {
            r = fixed;
        }
        if (jacobian) {
            *jacobian = knot_derivatives(hats, end_hats);
            if (columns.cols() > 0) {
                *jacobian -= columns * normal.solve(columns.transpose() * *jacobian);
            }
        }
    }

    std::vector<double> distances() const {
        const Eigen::MatrixXd h = hat_integrals(m_.lengths, f_.s).total();
        Eigen::VectorXd k(static_cast<Eigen::Index>(m_.knot_var.size()));
        for (std::size_t j = 0; j < m_.knot_var.size(); ++j) {
            k[static_cast<Eigen::Index>(j)] = m_.knot_curvature(j);
        }
        const Eigen::VectorXd design = h * k;
        std::vector<double> d;
        for (std::size_t i = 0; i < f_.s.size(); ++i) {
            const double y = y0_ + phi0_ * f_.s[i] + design[static_cast<Eigen::Index>(i)] - reference_[i];
            d.push_back(std::abs(f_.e[i] - y));
        }
        return d;
    }

    std::vector<double>& scale() { return scale_; }

    // The largest angle between the design and the reference, at the knots
    // and the nodes: beyond a tenth of a radian or so the small-angle model
    // no longer stands for the curve (a free start swung round, with a
    // sharp curve to come back, can pass sparse nodes in the frame).
    double max_angle() const {
        std::vector<double> at(f_.s);
        double s = 0.0;
        for (const double l : m_.lengths) {
            s += l;
            at.push_back(s);
        }
        std::sort(at.begin(), at.end());
        double turn = 0.0, knot = 0.0, most = std::abs(phi0_);
        std::size_t j = 0;
        for (const double q : at) {
            while (j < m_.segments() && knot + m_.lengths[j] <= q) {
                turn += 0.5 * (m_.knot_curvature(j) + m_.knot_curvature(j + 1)) * m_.lengths[j];
                knot += m_.lengths[j++];
            }
            const double t = q - knot, a = m_.knot_curvature(j);
            const double b = j < m_.segments() ? m_.knot_curvature(j + 1) : a;
            const double l = j < m_.segments() ? m_.lengths[j] : 1.0;
            const double here = turn + a * t + (b - a) * t * t / (2 * l);
            most = std::max(most, std::abs(f_.hdg[0] + phi0_ + here - ref_.at(q).hdg));
        }
        return most;
    }

    double start_angle() const { return phi0_; }

    // The model's start pose where it is free: the frame's start offset and heading.
    void write_start() {
        if (m_.start_free) {
            const double h0 = f_.hdg[0];
            m_.start.x = f_.x[0] - y0_ * std::sin(h0);
            m_.start.y = f_.y[0] + y0_ * std::cos(h0);
            m_.start.hdg = h0 + phi0_;
        }
    }

private:
    static constexpr double tie = 100.0, lever_m = 50.0;

    // The design matrix of the linear parameters (start offset and heading
    // where free, curvature variables) and what they must fit (the nodes'
    // offsets and the end targets less the fixed parts of the design),
    // rows scaled as the residuals.
    void linear_system(const HatIntegrals& hats, const HatIntegrals& end_hats, Eigen::MatrixXd& a,
                       Eigen::VectorXd& target) const {
        const std::size_t n = f_.s.size(), start = m_.start_free ? 2 : 0;
        const Eigen::MatrixXd h = hats.total();
        const Eigen::MatrixXd at_end = end_hats.total();
        a = Eigen::MatrixXd::Zero(static_cast<Eigen::Index>(rows()), static_cast<Eigen::Index>(start + m_.curv.size()));
        target = Eigen::VectorXd::Zero(a.rows());
        const Eigen::VectorXd w = row_weights();
        const auto e0 = static_cast<Eigen::Index>(n);
        // Per knot: offsets at the nodes, offset and turn at the end.
        auto knot_column = [&](std::size_t k) {
            Eigen::VectorXd c(a.rows());
            c.head(e0) = h.col(static_cast<Eigen::Index>(k));
            if (end_.pose) {
                const double left = k > 0 ? m_.lengths[k - 1] : 0.0, right = k < m_.segments() ? m_.lengths[k] : 0.0;
                c[e0] = at_end(0, static_cast<Eigen::Index>(k));
                c[e0 + 1] = (left + right) / 2;
            }
            return c;
        };
        Eigen::VectorXd offset = Eigen::VectorXd::Zero(a.rows()), slope = Eigen::VectorXd::Zero(a.rows());
        for (std::size_t i = 0; i < n; ++i) {
            offset[static_cast<Eigen::Index>(i)] = 1.0;
            slope[static_cast<Eigen::Index>(i)] = f_.s[i];
            target[static_cast<Eigen::Index>(i)] = f_.e[i] + reference_[i];
        }
        if (end_.pose) {
            offset[e0] = 1.0;
            slope[e0] = length_;
            slope[e0 + 1] = 1.0;
            target[e0] = end_.y + at_end_.integral;
            target[e0 + 1] = end_.phi + at_end_.hdg - f_.hdg[0];
        }
        if (m_.start_free) {
            a.col(0) = offset;
            a.col(1) = slope;
        } else {
            target -= y0_ * offset + phi0_ * slope;
        }
        for (std::size_t k = 0; k < m_.knot_var.size(); ++k) {
            const int v = m_.knot_var[k];
            if (v >= 0) {
                a.col(static_cast<Eigen::Index>(start) + v) += knot_column(k);
            } else if (m_.knot_fixed[k] != 0.0) {
                target -= m_.knot_fixed[k] * knot_column(k);
            }
        }
        a = w.asDiagonal() * a;
        target = w.asDiagonal() * target;
    }

    Eigen::VectorXd row_weights() const {
        Eigen::VectorXd w(static_cast<Eigen::Index>(rows()));
        for (std::size_t i = 0; i < f_.s.size(); ++i) {
            w[static_cast<Eigen::Index>(i)] = scale_[i] / sigma_;
        }
        if (end_.pose) {
            const auto e0 = static_cast<Eigen::Index>(f_.s.size());
            w[e0] = tie / sigma_;
            w[e0 + 1] = tie * lever_m / sigma_;
        }
        return w;
    }

    // Derivatives of the residuals in the interior knots' chainages at fixed
    // knot curvatures: moving knot q by one changes the curvature under its
    // hat by minus the slope there, so the offsets by minus the slopes times
    // the hat's half integrals.
    Eigen::MatrixXd knot_derivatives(const HatIntegrals& hats, const HatIntegrals& end_hats) const {
        const auto n = static_cast<Eigen::Index>(f_.s.size());
        Eigen::MatrixXd d = Eigen::MatrixXd::Zero(static_cast<Eigen::Index>(rows()), static_cast<Eigen::Index>(knots()));
        for (std::size_t q = 1; q <= knots(); ++q) {
            const double before = (m_.knot_curvature(q) - m_.knot_curvature(q - 1)) / m_.lengths[q - 1];
            const double after = (m_.knot_curvature(q + 1) - m_.knot_curvature(q)) / m_.lengths[q];
            const auto c = static_cast<Eigen::Index>(q);
            Eigen::VectorXd col(d.rows());
            col.head(n) = before * hats.left.col(c) + after * hats.right.col(c);
            if (end_.pose) {
                col[n] = before * end_hats.left(0, c) + after * end_hats.right(0, c);
                col[n + 1] = before * m_.lengths[q - 1] / 2 + after * m_.lengths[q] / 2;
            }
            d.col(c - 1) = col; // residual = target - design: the design's change, negated twice
        }
        return row_weights().asDiagonal() * d;
    }

    Eigen::VectorXd linear() const {
        Eigen::VectorXd theta(static_cast<Eigen::Index>((m_.start_free ? 2 : 0) + m_.curv.size()));
        Eigen::Index i = 0;
        if (m_.start_free) {
            theta[i++] = y0_;
            theta[i++] = phi0_;
        }
        for (const double c : m_.curv) {
            theta[i++] = c;
        }
        return theta;
    }

    void set_linear(const Eigen::VectorXd& theta) {
        Eigen::Index i = 0;
        if (m_.start_free) {
            y0_ = theta[i++];
            phi0_ = theta[i++];
        }
        for (double& c : m_.curv) {
            c = theta[i++];
        }
    }

    CurvatureModel& m_;
    const Frame& f_;
    ReferenceHeading ref_;
    FrameEnd end_;
    double sigma_;
    double prior_sigma_;
    std::vector<double> scale_;
    std::vector<double> reference_; // the reference's integral at each node
    std::vector<double> prior_;     // the curvature variables' first values
    double y0_ = 0.0, phi0_ = 0.0, length_ = 0.0;
    ReferenceHeading::At at_end_;
};

// Levenberg-Marquardt over the knots' chainages.
bool levenberg_marquardt(FrameProblem& fp, double min_length) {
    Eigen::VectorXd x = fp.get(), r, r1;
    fp.residuals(x, r);
    double cost = r.squaredNorm(), mu = 1e-4;
    const auto n = static_cast<Eigen::Index>(fp.knots());
    Eigen::MatrixXd J(r.size(), n);
    for (int it = 0; it < 30 && n > 0 && std::isfinite(cost); ++it) {
        fp.residuals(x, r, &J);
        const Eigen::MatrixXd A = J.transpose() * J;
        const Eigen::VectorXd g = J.transpose() * r;
        bool accepted = false;
        double gain = 0.0;
        for (int tries = 0; tries < 8 && !accepted; ++tries) {
            Eigen::MatrixXd D = A;
            D.diagonal() += mu * A.diagonal() + Eigen::VectorXd::Constant(n, 1e-12);
            const Eigen::VectorXd xt = fp.feasible(x - D.ldlt().solve(g), min_length);
            fp.residuals(xt, r1);
            const double c1 = r1.squaredNorm();
            if (std::isfinite(c1) && c1 < cost) {
                gain = cost - c1;
                x = xt;
                r = r1;
                cost = c1;
                mu = std::max(1e-9, mu * 0.3);
                accepted = true;
            } else {
                mu *= 10;
            }
        }
        if (!accepted || gain < 0.01) {
            break;
        }
    }
    fp.residuals(x, r);
    return std::isfinite(cost);
}

} // namespace

FrameFit fit_in_frame(CurvatureModel& m, const Frame& f, const std::optional<Pose>& end, double sigma,
                      double prior_sigma) {
    constexpr double min_length = 0.5, cap_sigmas = 5.0;
    FrameFit out;
    if (f.s.size() < 2 || f.hdg.size() < 2) {
        return out;
    }
    if (m.segments() == 0 || std::find(m.length_free.begin(), m.length_free.end(), 0) != m.length_free.end()) {
        return out; // structures have every length free
    }
    FrameProblem fp(m, f, end, sigma, prior_sigma);
    bool ok = levenberg_marquardt(fp, min_length);
    out.distances_m = fp.distances();
    // Nodes beyond the criterion's cap weighted down while few are so far,
    // as in the exact solve (design_selection.cpp).
    std::vector<std::size_t> previous;
    for (int round = 0; round < 3 && ok && far_point_scale(out.distances_m, cap_sigmas * sigma, previous, fp.scale());
         ++round) {
        ok = levenberg_marquardt(fp, min_length);
        out.distances_m = fp.distances();
    }
    // A fixed start may leave the reference at an angle (a branch drawn
    // leaving its switch kinked): the design may turn as far.
    const double allowed = std::max(0.15, m.start_free ? 0.0 : 2.0 * std::abs(fp.start_angle()));
    ok = ok && fp.max_angle() <= allowed;
    fp.write_start();
    out.ok = ok && std::all_of(out.distances_m.begin(), out.distances_m.end(), [](double d) { return std::isfinite(d); });
    return out;
}

} // namespace railodd::geometry::fit
