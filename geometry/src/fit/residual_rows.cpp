// The residual rows of a CurvatureModel against its points (residual_rows.hpp).
#include "residual_rows.hpp"

#include "design_dp.hpp"

#include <algorithm>
#include <cmath>

namespace railodd::geometry::fit {

namespace {

// Huber-weighted residual: quadratic up to c, linear beyond, so a few real
// kinks (transition ends, a turnout) are not smoothed away with the noise.
double huber(double r, double c = 2.0) {
    const double a = std::abs(r);
    return a <= c ? r : std::copysign(std::sqrt(2 * c * a - c * c), r);
}


} // namespace

// How many rows fill_residuals fills.
std::size_t row_count(const CurvatureModel& m, const Problem& p) {
    std::size_t rows = p.pts.size() + (p.opt.pin_first ? 1 : 0) + (p.opt.pin_last ? 1 : 0);
    if (p.opt.kink_sigma > 0 && m.knot_var.size() > 2) {
        rows += m.knot_var.size() - 2;
    }
    if (p.opt.ridge_sigma > 0) {
        rows += m.knot_var.size();
    }
    if (!p.opt.transition_prior.empty()) {
        rows += m.segments();
    }
    if (!p.opt.guide_weight.empty()) {
        rows += m.segments();
    }
    if (!p.opt.knot_weight.empty()) {
        rows += m.segments() + 1;
    }
    return rows;
}

// The point rows: normal distance of every point, the along-track distance
// of the first and last point. Only points from `from` on are filled (those
// before it have not moved); the rows' count is returned.
std::size_t fill_point_rows(const std::vector<Foot>& feet, const std::vector<Point2>& curve, const Problem& p,
                            Eigen::VectorXd& r, std::size_t from) {
    const double w = 1.0 / p.opt.sigma_m;
    const std::vector<double>& scale = p.opt.point_scale;
    for (std::size_t i = from; i < feet.size(); ++i) {
        const double wi = scale.empty() ? w : w * scale[i];
        r[static_cast<long>(i)] = wi * ((p.pts[i].x - curve[i].x) * feet[i].nx + (p.pts[i].y - curve[i].y) * feet[i].ny);
    }
    std::size_t row = feet.size();
    auto along = [&](std::size_t i) {
        if (i >= from) {
            r[static_cast<long>(row)] =
                w * ((p.pts[i].x - curve[i].x) * feet[i].tx + (p.pts[i].y - curve[i].y) * feet[i].ty);
        }
        ++row;
    };
    if (p.opt.pin_first) {
        along(0);
    }
    if (p.opt.pin_last) {
        along(feet.size() - 1);
    }
    return row;
}

bool has_kink_rows(const CurvatureModel& m, const Problem& p) {
    return p.opt.kink_sigma > 0 && m.knot_var.size() > 2;
}

// Curvature kink at knot k (1 .. knots - 2).
double kink_row(const CurvatureModel& m, const Problem& p, std::size_t k) {
    const double a = m.knot_curvature(k - 1), b = m.knot_curvature(k), c = m.knot_curvature(k + 1);
    // Tight curves change curvature by more in absolute terms: the
    // allowed kink grows with the local curvature.
    const double scale = std::max(p.opt.kink_sigma, 0.25 * std::max({std::abs(a), std::abs(b), std::abs(c)}));
    return huber((a - 2 * b + c) / scale);
}

// Per unit length: long knot intervals are long because nodes are sparse
// there, which mappers do on straight track.
double ridge_row(const CurvatureModel& m, const Problem& p, std::size_t k) {
    const double left = k > 0 ? m.lengths[k - 1] : 0.0;
    const double right = k < m.segments() ? m.lengths[k] : 0.0;
    return huber(m.knot_curvature(k) * std::sqrt(0.5 * (left + right) / 20.0) / p.opt.ridge_sigma);
}

// A segment's length against the design rule's for its curvature change
// (zero where it has no prior or no change).
double transition_row(const CurvatureModel& m, const Problem& p, std::size_t j) {
    const double w = j < p.opt.transition_prior.size() ? p.opt.transition_prior[j] : 0.0;
    const double dk = std::abs(m.knot_curvature(j + 1) - m.knot_curvature(j));
    if (w <= 0.0 || dk < 1e-5) {
        return 0.0;
    }
    return std::sqrt(w) * std::log(m.lengths[j] / transition_length_for(dk));
}

// A segment's curvature against its guide's (zero where it has none).
double guide_row(const CurvatureModel& m, const Problem& p, std::size_t j) {
    const double w = j < p.opt.guide_weight.size() ? p.opt.guide_weight[j] : 0.0;
    if (w <= 0.0) {
        return 0.0;
    }
    const double f = p.opt.guide_at[j];
    return std::sqrt(w) * ((1.0 - f) * m.knot_curvature(j) + f * m.knot_curvature(j + 1) - p.opt.guide_curvature[j]);
}

// A knot's arc length against where it is held (zero where it is not).
double knot_row(const CurvatureModel& m, const Problem& p, std::size_t k) {
    const double w = k < p.opt.knot_weight.size() ? p.opt.knot_weight[k] : 0.0;
    if (w <= 0.0) {
        return 0.0;
    }
    double s = 0.0;
    for (std::size_t j = 0; j < k; ++j) {
        s += m.lengths[j];
    }
    return std::sqrt(w) * (s - p.opt.knot_at[k]);
}

// Residual rows: the point rows, then curvature kinks, the ridge, the
// transition priors, the guide, the held knots. The
// end pose is a constraint (end_constraint.hpp), or weighted rows appended
// where it cannot be one.
void fill_residuals(const CurvatureModel& m, const std::vector<Foot>& feet,
                    const std::vector<Point2>& curve, const Problem& p, Eigen::VectorXd& r) {
    std::size_t row = fill_point_rows(feet, curve, p, r);
    if (has_kink_rows(m, p)) {
        for (std::size_t k = 1; k + 1 < m.knot_var.size(); ++k) {
            r[row++] = kink_row(m, p, k);
        }
    }
    if (p.opt.ridge_sigma > 0) {
        for (std::size_t k = 0; k < m.knot_var.size(); ++k) {
            r[row++] = ridge_row(m, p, k);
        }
    }
    if (!p.opt.transition_prior.empty()) {
        for (std::size_t j = 0; j < m.segments(); ++j) {
            r[row++] = transition_row(m, p, j);
        }
    }
    if (!p.opt.guide_weight.empty()) {
        for (std::size_t j = 0; j < m.segments(); ++j) {
            r[row++] = guide_row(m, p, j);
        }
    }
    if (!p.opt.knot_weight.empty()) {
        for (std::size_t k = 0; k <= m.segments(); ++k) {
            r[row++] = knot_row(m, p, k);
        }
    }
}

} // namespace railodd::geometry::fit
