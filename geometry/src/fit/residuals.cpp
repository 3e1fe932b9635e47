// Feet, residual rows and their Jacobian (residuals.hpp).
#include "residuals.hpp"

#include "chain_linearise.hpp"
#include "residual_rows.hpp"

#include "design_dp.hpp"
#include "end_constraint.hpp"

#include "railodd/geometry/indexed_alignment.hpp"

#include <algorithm>
#include <cmath>
#include <optional>

namespace railodd::geometry::fit {

namespace {

std::size_t segment_at(const std::vector<double>& s0, double s) {
    const auto it = std::upper_bound(s0.begin(), s0.end() - 1, s);
    return std::min<std::size_t>(s0.size() - 2, static_cast<std::size_t>(std::max<long>(0, it - s0.begin() - 1)));
}

struct Near {
    double s;
    double distance;
};

// Newton steps along the curve from chainage s to the foot of (x, y), as in
// refine_feet. None where they do not settle: the caller searches samples.
std::optional<Near> walk_to_foot(const CurvatureModel& m, const std::vector<Pose>& poses,
                                 const std::vector<double>& s0, double s, const Point2& q) {
    const double total = s0.back();
    for (int it = 0; it < 12; ++it) {
        s = std::clamp(s, 0.0, total);
        const std::size_t j = segment_at(s0, s);
        const Pose c = evaluate(poses[j], m.segment(j), s - s0[j]);
        const double dx = q.x - c.x, dy = q.y - c.y;
        const double ch = std::cos(c.hdg), sh = std::sin(c.hdg);
        const double step = (dx * ch + dy * sh) / std::max(0.2, 1.0 - c.curvature * (-dx * sh + dy * ch));
        if (std::abs(step) < 1e-3 || (s <= 0.0 && step < 0.0) || (s >= total && step > 0.0)) {
            return Near{s, std::hypot(dx, dy)};
        }
        s += step;
    }
    return std::nullopt;
}

// Moves every foot to the nearest curve point by Newton steps along the curve
// from where it was: after one least-squares step the feet move little, and
// this costs a few evaluations per point instead of a global search.
// `at_feet`, where given, is the curve at every foot as it stands (the cost
// of the accepted step evaluated it): the first Newton step starts there.
void refine_feet(const CurvatureModel& m, const std::vector<Pose>& poses, const std::vector<Point2>& pts,
                 std::vector<Foot>& feet, const std::vector<Pose>* at_feet) {
    const std::size_t last = m.segments() - 1;
    for (std::size_t i = 0; i < feet.size(); ++i) {
        Foot& f = feet[i];
        f.segment = std::min(f.segment, last);
        f.u = std::clamp(f.u, 0.0, m.lengths[f.segment]);
        Pose c{};
        for (int it = 0; it < 8; ++it) {
            c = it == 0 && at_feet ? (*at_feet)[i]
                                   : evaluate(poses[f.segment], m.segment(f.segment), f.at_end ? m.lengths[f.segment] : f.u);
            if (f.at_end || f.at_start) {
                break;
            }
            const double dx = pts[i].x - c.x, dy = pts[i].y - c.y;
            const double ch = std::cos(c.hdg), sh = std::sin(c.hdg);
            const double along = dx * ch + dy * sh;
            const double offset = -dx * sh + dy * ch;
            const double step = along / std::max(0.2, 1.0 - c.curvature * offset);
            if (std::abs(step) < 1e-6) {
                break;
            }
            if (std::abs(step) < 1e-3 && f.u + step >= 0.0 && f.u + step <= m.lengths[f.segment]) {
                // The last millimetre along the curve as an arc of the local
                // curvature: the error (curvature rate times step cubed) is
                // far below rounding, and it saves an evaluation per point.
                const double mid = c.hdg + 0.5 * c.curvature * step;
                c = {c.x + step * std::cos(mid), c.y + step * std::sin(mid), c.hdg + c.curvature * step, c.curvature};
                f.u += step;
                break;
            }
            double u = f.u + step;
            while (u < 0.0 && f.segment > 0) {
                --f.segment;
                u += m.lengths[f.segment];
            }
            while (u > m.lengths[f.segment] && f.segment < last) {
                u -= m.lengths[f.segment];
                ++f.segment;
            }
            f.u = std::clamp(u, 0.0, m.lengths[f.segment]);
        }
        f.place(c);
    }
}

// The Jacobian column of parameter i (influencing segments [a, b]) in the
// smoothness rows: only the rows of knots a - 1 .. b + 2 can change, the
// rest stay exactly zero (the start pose changes none).
void smoothness_column(const CurvatureModel& m2, const ParameterMap& map, std::size_t i, const Problem& p,
                       const Eigen::VectorXd& r, double h, std::size_t first_row, Eigen::MatrixXd& J) {
    if (map.is_start(i)) {
        return;
    }
    const auto [a, b] = map.influence(i);
    const std::size_t knots = m2.knot_var.size();
    const long col = static_cast<long>(i);
    std::size_t row = first_row;
    if (has_kink_rows(m2, p)) {
        for (std::size_t k = std::max<std::size_t>(1, a == 0 ? 1 : a - 1); k + 1 < knots && k <= b + 2; ++k) {
            const long at = static_cast<long>(row + k - 1);
            J(at, col) = (kink_row(m2, p, k) - r[at]) / h;
        }
        row += knots - 2;
    }
    if (p.opt.ridge_sigma > 0) {
        for (std::size_t k = a; k < knots && k <= b + 1; ++k) {
            const long at = static_cast<long>(row + k);
            J(at, col) = (ridge_row(m2, p, k) - r[at]) / h;
        }
        row += knots;
    }
    if (!p.opt.transition_prior.empty()) {
        for (std::size_t j = a == 0 ? 0 : a - 1; j < m2.segments() && j <= b + 1; ++j) {
            const long at = static_cast<long>(row + j);
            J(at, col) = (transition_row(m2, p, j) - r[at]) / h;
        }
        row += m2.segments();
    }
    if (!p.opt.guide_weight.empty()) {
        for (std::size_t j = a == 0 ? 0 : a - 1; j < m2.segments() && j <= b + 1; ++j) {
            const long at = static_cast<long>(row + j);
            J(at, col) = (guide_row(m2, p, j) - r[at]) / h;
        }
        row += m2.segments();
    }
    // A length moves every knot after its segment.
    if (!p.opt.knot_weight.empty() && map.is_length(i)) {
        for (std::size_t k = a + 1; k <= m2.segments(); ++k) {
            const long at = static_cast<long>(row + k);
            J(at, col) = (knot_row(m2, p, k) - r[at]) / h;
        }
    }
}

// The rigid motion taking pose `from` to pose `to`, applied to points: one
// sincos per motion, not per point (a Jacobian column moves every point
// downstream of its segment).
class Rigid {
public:
    Rigid(const Pose& from, const Pose& to)
        : from_(from), to_(to), c_(std::cos(to.hdg - from.hdg)), s_(std::sin(to.hdg - from.hdg)) {}
    Point2 operator()(const Point2& p) const {
        const double dx = p.x - from_.x, dy = p.y - from_.y;
        return {to_.x + dx * c_ - dy * s_, to_.y + dx * s_ + dy * c_};
    }

private:
    Pose from_, to_;
    double c_, s_;
};

// The curve points and end pose of a model that differs from the current one
// only in segments [a, b]: recomputed there, moved rigidly downstream.
// `p2` is scratch space for the perturbed knot poses: one allocation per
// linearisation, not per column.
// Points before `first_moved` sit upstream of segment a and are left as they are.
void perturbed_curve(const CurvatureModel& m2, std::size_t a, std::size_t b, bool from_start,
                     const std::vector<Pose>& poses, const std::vector<Foot>& feet, const std::vector<Point2>& curve,
                     std::size_t first_moved, std::vector<Pose>& p2, std::vector<Point2>& out, Pose& end_out) {
    if (from_start) {
        // The start pose moves the whole curve rigidly: no evaluation needed.
        const Pose& from = poses.front();
        const Pose to{m2.start.x, m2.start.y, m2.start.hdg, from.curvature};
        const Rigid move(from, to);
        for (std::size_t i = first_moved; i < feet.size(); ++i) {
            out[i] = move(curve[i]);
        }
        const Pose& e = poses.back();
        const Point2 q = move({e.x, e.y});
        end_out = {q.x, q.y, e.hdg + (to.hdg - from.hdg), e.curvature};
        return;
    }
    // Only p2[a .. b + 1] is read below.
    p2[a] = poses[a];
    for (std::size_t j = a; j <= b; ++j) {
        p2[j + 1] = evaluate(p2[j], m2.segment(j), m2.lengths[j]);
    }
    const Rigid downstream(poses[b + 1], p2[b + 1]);
    for (std::size_t i = first_moved; i < feet.size(); ++i) {
        const Foot& f = feet[i];
        if (f.segment < a) {
            out[i] = curve[i];
        } else if (f.segment <= b) {
            const Pose c = evaluate(p2[f.segment], m2.segment(f.segment), f.at_end ? m2.lengths[f.segment] : f.u);
            out[i] = {c.x, c.y};
        } else {
            out[i] = downstream(curve[i]);
        }
    }
    const Pose& e = poses.back();
    if (b + 1 == poses.size() - 1) {
        end_out = p2[b + 1];
    } else {
        const Point2 q = downstream({e.x, e.y});
        end_out = {q.x, q.y, e.hdg + (p2[b + 1].hdg - poses[b + 1].hdg), e.curvature};
    }
}

} // namespace

std::vector<Foot> feet_of(const CurvatureModel& m, const std::vector<Pose>& poses, const std::vector<Point2>& pts,
                          const SolveOptions& opt) {
    std::vector<double> s0(m.segments() + 1, 0.0);
    for (std::size_t j = 0; j < m.segments(); ++j) {
        s0[j + 1] = s0[j] + m.lengths[j];
    }
    // Sampled search only where walking along the curve does not settle
    // nearby: building the index evaluates the curve every 4 m.
    std::optional<IndexedAlignment> ia;
    auto index = [&]() -> const IndexedAlignment& {
        if (!ia) {
            ia.emplace(m.to_alignment(), 4.0);
        }
        return *ia;
    };
    std::vector<Foot> feet;
    feet.reserve(pts.size());
    for (std::size_t i = 0; i < pts.size(); ++i) {
        const bool last = opt.pin_last && i + 1 == pts.size();
        const bool first = opt.pin_first && i == 0;
        // Points are in track order: search near the previous point's foot,
        // as far on as the chord between the two points reaches.
        double s = 0.0;
        if (last) {
            s = s0.back();
        } else if (!first) {
            const double prev = feet.empty() ? 0.0 : s0[feet.back().segment] + feet.back().u;
            const double reach = i == 0 ? s0.back() : std::hypot(pts[i].x - pts[i - 1].x, pts[i].y - pts[i - 1].y);
            const double lo = prev - 50.0, hi = prev + 1.5 * reach + 50.0;
            const std::optional<Near> walked = walk_to_foot(m, poses, s0, i == 0 ? 0.0 : prev + reach, pts[i]);
            if (walked && walked->distance < 25.0 && walked->s >= lo && walked->s <= hi) {
                s = walked->s;
            } else {
                const Projection near = index().project_within(pts[i].x, pts[i].y, lo, hi);
                s = near.distance < 25.0 ? near.s : index().project(pts[i].x, pts[i].y).s;
            }
        }
        Foot f;
        f.segment = segment_at(s0, s);
        f.u = std::clamp(s - s0[f.segment], 0.0, m.lengths[f.segment]);
        f.at_end = last;
        f.at_start = first;
        const Pose c = evaluate(poses[f.segment], m.segment(f.segment), f.at_end ? m.lengths[f.segment] : f.u);
        f.place(c);
        feet.push_back(f);
    }
    return feet;
}

std::vector<std::size_t> first_feet_on(const std::vector<Foot>& feet, std::size_t segments) {
    std::vector<std::size_t> first_on(segments + 1, feet.size());
    for (std::size_t i = feet.size(); i-- > 0;) {
        first_on[feet[i].segment] = i;
    }
    for (std::size_t j = segments; j-- > 0;) {
        first_on[j] = std::min(first_on[j], first_on[j + 1]);
    }
    return first_on;
}

Linearisation linearise(const CurvatureModel& m, const ParameterMap& map, const Problem& p, std::vector<Foot>& feet,
                        const Evaluated* known) {
    const std::vector<Pose> poses = known ? known->knots : m.knot_poses();
    refine_feet(m, poses, p.pts, feet, known ? &known->at_feet : nullptr);
    std::vector<Point2> curve(feet.size());
    for (std::size_t i = 0; i < feet.size(); ++i) {
        curve[i] = {feet[i].cx, feet[i].cy};
    }
    const std::size_t rows = row_count(m, p);
    Linearisation lin;
    lin.r = Eigen::VectorXd::Zero(static_cast<long>(rows));
    lin.dense_rows = static_cast<long>(p.pts.size() + (p.opt.pin_first ? 1 : 0) + (p.opt.pin_last ? 1 : 0));
    fill_residuals(m, feet, curve, p, lin.r);
    if (p.opt.end) {
        lin.c = end_gap(m, poses.back(), *p.opt.end);
    }
    if (chain_form(m, p)) {
        chain_linearise(m, map, p, feet, poses, lin);
        return lin;
    }
    lin.J = Eigen::MatrixXd::Zero(static_cast<long>(rows), static_cast<long>(map.size()));
    if (p.opt.end) {
        lin.C = Eigen::MatrixXd::Zero(lin.c.size(), static_cast<long>(map.size()));
    }
    const std::vector<double> base = map.get(m);
    // A parameter of segments [a, b] leaves every point before first_on[a] where it is.
    const std::vector<std::size_t> first_on = first_feet_on(feet, m.segments());
    std::vector<Point2> moved(feet.size());
    std::vector<Pose> p2(poses.size());
    Eigen::VectorXd r2(static_cast<long>(rows));
    // One working copy, each parameter nudged and put back exactly: no model
    // copy per column.
    CurvatureModel m2 = m;
    for (std::size_t i = 0; i < map.size(); ++i) {
        const double h = map.difference_step(i);
        map.set_one(m2, i, base[i] + h);
        const auto [a, b] = map.influence(i);
        Pose end2;
        const std::size_t from = map.is_start(i) ? 0 : first_on[a];
        perturbed_curve(m2, a, b, map.is_start(i), poses, feet, curve, from, p2, moved, end2);
        const std::size_t point_rows = fill_point_rows(feet, moved, p, r2, from);
        const long n0 = static_cast<long>(from), n = static_cast<long>(feet.size());
        lin.J.col(static_cast<long>(i)).segment(n0, n - n0) = (r2.segment(n0, n - n0) - lin.r.segment(n0, n - n0)) / h;
        for (long row = n; row < static_cast<long>(point_rows); ++row) {
            // The pinned ends' rows: unfilled (not moved) rows keep r2 from
            // an earlier column, so only a moved end counts.
            const std::size_t end_point = row == n && p.opt.pin_first ? 0 : feet.size() - 1;
            if (end_point >= from) {
                lin.J(row, static_cast<long>(i)) = (r2[row] - lin.r[row]) / h;
            }
        }
        smoothness_column(m2, map, i, p, lin.r, h, point_rows, lin.J);
        if (p.opt.end) {
            lin.C.col(static_cast<long>(i)) = (end_gap(m2, end2, *p.opt.end) - lin.c) / h;
        }
        map.set_one(m2, i, base[i]);
    }
    return lin;
}

namespace {

// The data rows (and, with end rows, the end gap) of a model evaluated at
// fixed feet; the evaluation is kept in `e`.
Eigen::VectorXd rows_at_feet(const CurvatureModel& m, const Problem& p, const std::vector<Foot>& feet,
                             bool with_end_rows, Evaluated& e, Eigen::VectorXd& gap) {
    e.knots = m.knot_poses();
    const std::vector<Pose>& poses = e.knots;
    e.at_feet.resize(feet.size());
    std::vector<Point2> curve(feet.size());
    for (std::size_t i = 0; i < feet.size(); ++i) {
        const Foot& f = feet[i];
        const double u = f.at_end ? m.lengths[f.segment] : std::min(f.u, m.lengths[f.segment]);
        e.at_feet[i] = evaluate(poses[f.segment], m.segment(f.segment), u);
        curve[i] = {e.at_feet[i].x, e.at_feet[i].y};
    }
    Eigen::VectorXd r(static_cast<long>(row_count(m, p)));
    fill_residuals(m, feet, curve, p, r);
    if (with_end_rows) {
        gap = end_gap(m, poses.back(), *p.opt.end);
    }
    return r;
}

} // namespace

double cost_at_feet(const CurvatureModel& m, const Problem& p, const std::vector<Foot>& feet, bool with_end_rows,
                    Evaluated& e) {
    Eigen::VectorXd gap;
    const Eigen::VectorXd r = rows_at_feet(m, p, feet, with_end_rows, e, gap);
    return r.squaredNorm() + (with_end_rows ? end_weight * end_weight * gap.squaredNorm() : 0.0);
}

Eigen::VectorXd residuals_at_feet(const CurvatureModel& m, const Problem& p, const std::vector<Foot>& feet,
                                  bool with_end_rows) {
    Evaluated e;
    Eigen::VectorXd gap;
    const Eigen::VectorXd r = rows_at_feet(m, p, feet, with_end_rows, e, gap);
    if (!with_end_rows) {
        return r;
    }
    Eigen::VectorXd out(r.size() + gap.size());
    out << r, end_weight * gap;
    return out;
}

std::vector<double> foot_distances(const CurvatureModel& m, const std::vector<Point2>& pts) {
    SolveOptions unpinned;
    unpinned.pin_first = false;
    unpinned.pin_last = false;
    const std::vector<Pose> poses = m.knot_poses();
    std::vector<Foot> feet = feet_of(m, poses, pts, unpinned);
    refine_feet(m, poses, pts, feet, nullptr);
    std::vector<double> d(pts.size());
    for (std::size_t i = 0; i < pts.size(); ++i) {
        d[i] = std::hypot(pts[i].x - feet[i].cx, pts[i].y - feet[i].cy);
    }
    return d;
}

double total_length(const CurvatureModel& m) {
    double sum = 0.0;
    for (double l : m.lengths) {
        sum += l;
    }
    return sum;
}

void clamp_model(CurvatureModel& m, double min_length, const std::vector<double>& min_at, double max_length,
                 double max_curvature) {
    for (std::size_t j = 0; j < m.segments(); ++j) {
        if (m.length_free[j]) {
            const double floor = j < min_at.size() ? std::max(min_length, min_at[j]) : min_length;
            m.lengths[j] = std::clamp(m.lengths[j], floor, std::max(floor, max_length));
        }
    }
    for (double& k : m.curv) {
        k = std::clamp(k, -max_curvature, max_curvature);
    }
}

} // namespace railodd::geometry::fit
