#include "least_squares.hpp"

#include "railodd/geometry/indexed_alignment.hpp"

#include <Eigen/Dense>

#include <algorithm>
#include <cmath>
#include <limits>

namespace railodd::geometry::fit {

namespace {

// Where a data point sits on the curve: segment, distance into it, and the
// unit normal there. Residuals use the normal (and, at the two ends, the
// tangent) fixed during one iteration, as in point-to-curve ICP.
struct Foot {
    std::size_t segment = 0;
    double u = 0.0;
    bool at_start = false; // the pinned first point: stays at arc length 0
    bool at_end = false;   // the pinned last point: follows the end of its segment when lengths change
    double nx = 0.0, ny = 0.0;
    double tx = 0.0, ty = 0.0;
    double cx = 0.0, cy = 0.0;
};

std::vector<Foot> feet_of(const CurvatureModel& m, const std::vector<Pose>& poses, const std::vector<Point2>& pts,
                          const SolveOptions& opt) {
    const IndexedAlignment ia(m.to_alignment(), 4.0);
    std::vector<double> s0(m.segments() + 1, 0.0);
    for (std::size_t j = 0; j < m.segments(); ++j) {
        s0[j + 1] = s0[j] + m.lengths[j];
    }
    std::vector<Foot> feet;
    feet.reserve(pts.size());
    for (std::size_t i = 0; i < pts.size(); ++i) {
        const bool last = opt.pin_last && i + 1 == pts.size();
        const bool first = opt.pin_first && i == 0;
        // Points are in track order: search near the previous point's foot,
        // as far on as the chord between the two points reaches.
        double s = 0.0;
        if (last) {
            s = ia.length();
        } else if (!first) {
            const double prev = feet.empty() ? 0.0 : s0[feet.back().segment] + feet.back().u;
            const double reach = i == 0 ? ia.length() : std::hypot(pts[i].x - pts[i - 1].x, pts[i].y - pts[i - 1].y);
            const Projection near = ia.project_within(pts[i].x, pts[i].y, prev - 50.0, prev + 1.5 * reach + 50.0);
            s = near.distance < 25.0 ? near.s : ia.project(pts[i].x, pts[i].y).s;
        }
        Foot f;
        auto it = std::upper_bound(s0.begin(), s0.end() - 1, s);
        f.segment = std::min<std::size_t>(m.segments() - 1, static_cast<std::size_t>(std::max<long>(0, it - s0.begin() - 1)));
        f.u = std::clamp(s - s0[f.segment], 0.0, m.lengths[f.segment]);
        f.at_end = last;
        f.at_start = first;
        const Pose c = evaluate(poses[f.segment], m.segment(f.segment), f.at_end ? m.lengths[f.segment] : f.u);
        f.cx = c.x;
        f.cy = c.y;
        f.tx = std::cos(c.hdg);
        f.ty = std::sin(c.hdg);
        f.nx = -f.ty;
        f.ny = f.tx;
        feet.push_back(f);
    }
    return feet;
}

// Huber-weighted residual: quadratic up to c, linear beyond, so a few real
// kinks (transition ends, a turnout) are not smoothed away with the noise.
double huber(double r, double c = 2.0) {
    const double a = std::abs(r);
    return a <= c ? r : std::copysign(std::sqrt(2 * c * a - c * c), r);
}

// Moves every foot to the nearest curve point by Newton steps along the curve
// from where it was: after one least-squares step the feet move little, and
// this costs a few evaluations per point instead of a global search.
void refine_feet(const CurvatureModel& m, const std::vector<Pose>& poses, const std::vector<Point2>& pts,
                 std::vector<Foot>& feet) {
    const std::size_t last = m.segments() - 1;
    for (std::size_t i = 0; i < feet.size(); ++i) {
        Foot& f = feet[i];
        f.segment = std::min(f.segment, last);
        f.u = std::clamp(f.u, 0.0, m.lengths[f.segment]);
        Pose c{};
        for (int it = 0; it < 8; ++it) {
            c = evaluate(poses[f.segment], m.segment(f.segment), f.at_end ? m.lengths[f.segment] : f.u);
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
        f.cx = c.x;
        f.cy = c.y;
        f.tx = std::cos(c.hdg);
        f.ty = std::sin(c.hdg);
        f.nx = -f.ty;
        f.ny = f.tx;
    }
}

struct Problem {
    const std::vector<Point2>& pts;
    const SolveOptions& opt;
};

// Residual rows: normal distance of every point, the along-track distance of
// the first and last point, curvature kinks, end pose.
std::size_t row_count(const CurvatureModel& m, const Problem& p) {
    std::size_t rows = p.pts.size() + (p.opt.pin_first ? 1 : 0) + (p.opt.pin_last ? 1 : 0);
    if (p.opt.kink_sigma > 0 && m.knot_var.size() > 2) {
        rows += m.knot_var.size() - 2;
    }
    if (p.opt.ridge_sigma > 0) {
        rows += m.knot_var.size();
    }
    return rows + (p.opt.end ? 4 : 0);
}

// Weight of the end-pose rows: the end is a link to another track, which must
// be met to far below a millimetre.
constexpr double end_weight = 1e5;

void fill_residuals(const CurvatureModel& m, const std::vector<Pose>& poses, const std::vector<Foot>& feet,
                    const std::vector<Point2>& curve, const Problem& p, Eigen::VectorXd& r) {
    const double w = 1.0 / p.opt.sigma_m;
    std::size_t row = 0;
    for (std::size_t i = 0; i < feet.size(); ++i) {
        r[row++] = w * ((p.pts[i].x - curve[i].x) * feet[i].nx + (p.pts[i].y - curve[i].y) * feet[i].ny);
    }
    auto along = [&](std::size_t i) {
        r[row++] = w * ((p.pts[i].x - curve[i].x) * feet[i].tx + (p.pts[i].y - curve[i].y) * feet[i].ty);
    };
    if (p.opt.pin_first) {
        along(0);
    }
    if (p.opt.pin_last) {
        along(feet.size() - 1);
    }
    if (p.opt.kink_sigma > 0 && m.knot_var.size() > 2) {
        for (std::size_t k = 1; k + 1 < m.knot_var.size(); ++k) {
            const double a = m.knot_curvature(k - 1), b = m.knot_curvature(k), c = m.knot_curvature(k + 1);
            // Tight curves change curvature by more in absolute terms: the
            // allowed kink grows with the local curvature.
            const double scale = std::max(p.opt.kink_sigma, 0.25 * std::max({std::abs(a), std::abs(b), std::abs(c)}));
            r[row++] = huber((a - 2 * b + c) / scale);
        }
    }
    if (p.opt.ridge_sigma > 0) {
        // Per unit length: long knot intervals are long because nodes are
        // sparse there, which mappers do on straight track.
        for (std::size_t k = 0; k < m.knot_var.size(); ++k) {
            const double left = k > 0 ? m.lengths[k - 1] : 0.0;
            const double right = k < m.segments() ? m.lengths[k] : 0.0;
            r[row++] = huber(m.knot_curvature(k) * std::sqrt(0.5 * (left + right) / 20.0) / p.opt.ridge_sigma);
        }
    }
    if (p.opt.end) {
        const Pose& e = poses.back();
        const Pose& t = *p.opt.end;
        r[row++] = end_weight * (e.x - t.x);
        r[row++] = end_weight * (e.y - t.y);
        r[row++] = end_weight * 100.0 * (e.hdg - t.hdg);
        r[row++] = end_weight * 1e4 * (e.curvature - t.curvature);
    }
}

Point2 rigid(const Point2& c, const Pose& from, const Pose& to) {
    const double d = to.hdg - from.hdg;
    const double dx = c.x - from.x, dy = c.y - from.y;
    return {to.x + dx * std::cos(d) - dy * std::sin(d), to.y + dx * std::sin(d) + dy * std::cos(d)};
}

// The curve points and end pose of a model that differs from the current one
// only in segments [a, b]: recomputed there, moved rigidly downstream.
void perturbed_curve(const CurvatureModel& m2, std::size_t a, std::size_t b, bool from_start,
                     const std::vector<Pose>& poses, const std::vector<Foot>& feet, const std::vector<Point2>& curve,
                     std::vector<Point2>& out, Pose& end_out) {
    std::vector<Pose> p2(poses);
    if (from_start) {
        p2[0] = m2.start;
        p2[0].curvature = m2.knot_curvature(0);
    }
    for (std::size_t j = a; j <= b; ++j) {
        p2[j + 1] = evaluate(p2[j], m2.segment(j), m2.lengths[j]);
    }
    for (std::size_t i = 0; i < feet.size(); ++i) {
        const Foot& f = feet[i];
        if (f.segment < a) {
            out[i] = curve[i];
        } else if (f.segment <= b) {
            const Pose c = evaluate(p2[f.segment], m2.segment(f.segment), f.at_end ? m2.lengths[f.segment] : f.u);
            out[i] = {c.x, c.y};
        } else {
            out[i] = rigid(curve[i], poses[b + 1], p2[b + 1]);
        }
    }
    const Pose& e = poses.back();
    if (b + 1 == poses.size() - 1) {
        end_out = p2.back();
    } else {
        const Point2 q = rigid({e.x, e.y}, poses[b + 1], p2[b + 1]);
        end_out = {q.x, q.y, e.hdg + (p2[b + 1].hdg - poses[b + 1].hdg), e.curvature};
    }
}

double step_for(const ParameterMap& map, std::size_t i) {
    if (map.is_curvature(i)) return 1e-8;
    if (map.is_start(i) && map.index(i) == 2) return 1e-7;
    return 1e-5;
}

struct Linearisation {
    Eigen::MatrixXd J;
    Eigen::VectorXd r;
};

Linearisation linearise(const CurvatureModel& m, const ParameterMap& map, const Problem& p, std::vector<Foot>& feet) {
    const std::vector<Pose> poses = m.knot_poses();
    refine_feet(m, poses, p.pts, feet);
    std::vector<Point2> curve(feet.size());
    for (std::size_t i = 0; i < feet.size(); ++i) {
        curve[i] = {feet[i].cx, feet[i].cy};
    }
    const std::size_t rows = row_count(m, p);
    Linearisation lin{Eigen::MatrixXd::Zero(static_cast<long>(rows), static_cast<long>(map.size())),
                      Eigen::VectorXd::Zero(static_cast<long>(rows))};
    fill_residuals(m, poses, feet, curve, p, lin.r);
    const std::vector<double> base = map.get(m);
    std::vector<Point2> moved(feet.size());
    Eigen::VectorXd r2(static_cast<long>(rows));
    for (std::size_t i = 0; i < map.size(); ++i) {
        CurvatureModel m2 = m;
        std::vector<double> v = base;
        const double h = step_for(map, i);
        v[i] += h;
        map.set(m2, v);
        const auto [a, b] = map.influence(i);
        std::vector<Pose> p2 = poses;
        Pose end2;
        perturbed_curve(m2, a, b, map.is_start(i), poses, feet, curve, moved, end2);
        p2.back() = end2;
        fill_residuals(m2, p2, feet, moved, p, r2);
        lin.J.col(static_cast<long>(i)) = (r2 - lin.r) / h;
    }
    return lin;
}

// Cost of a trial model with the feet (and their normals) of the current
// linearisation held fixed, as in point-to-curve ICP; the next linearisation
// moves the feet.
double cost_at_feet(const CurvatureModel& m, const Problem& p, const std::vector<Foot>& feet) {
    const std::vector<Pose> poses = m.knot_poses();
    std::vector<Point2> curve(feet.size());
    for (std::size_t i = 0; i < feet.size(); ++i) {
        const Foot& f = feet[i];
        const double u = f.at_end ? m.lengths[f.segment] : std::min(f.u, m.lengths[f.segment]);
        const Pose c = evaluate(poses[f.segment], m.segment(f.segment), u);
        curve[i] = {c.x, c.y};
    }
    Eigen::VectorXd r(static_cast<long>(row_count(m, p)));
    fill_residuals(m, poses, feet, curve, p, r);
    return r.squaredNorm();
}

double total_length(const CurvatureModel& m) {
    double sum = 0.0;
    for (double l : m.lengths) {
        sum += l;
    }
    return sum;
}

// Keeps a trial model in the range the data can support: curvature at most
// 0.1 1/m, every free length between min_length and max_length. Without the
// upper bound a diverging step could make a segment kilometres long and
// tightly curved, whose evaluation then takes minutes (seen on a replicated
// Cologne extract).
void clamp_model(CurvatureModel& m, double min_length, double max_length) {
    constexpr double max_curvature = 0.1;
    for (std::size_t j = 0; j < m.segments(); ++j) {
        if (m.length_free[j]) {
            m.lengths[j] = std::clamp(m.lengths[j], min_length, std::max(min_length, max_length));
        }
    }
    for (double& k : m.curv) {
        k = std::clamp(k, -max_curvature, max_curvature);
    }
}

} // namespace

std::vector<double> point_distances(const CurvatureModel& model, const std::vector<Point2>& points) {
    const IndexedAlignment ia(model.to_alignment(), 2.0);
    std::vector<double> d;
    d.reserve(points.size());
    for (const auto& q : points) {
        d.push_back(ia.project(q.x, q.y).distance);
    }
    return d;
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

SolveReport solve_once(CurvatureModel& model, const std::vector<Point2>& points, const SolveOptions& options) {
    const ParameterMap map(model);
    const Problem p{points, options};
    SolveReport report;
    std::vector<Foot> feet = feet_of(model, model.knot_poses(), points, options);
    double mu = 1e-3;
    const double give_up_cost = options.give_up_rss / (options.sigma_m * options.sigma_m);
    // No segment, nor the whole curve, needs to be longer than twice the
    // polyline through the data.
    double max_length = 50.0;
    for (std::size_t i = 1; i < points.size(); ++i) {
        max_length += 2.0 * std::hypot(points[i].x - points[i - 1].x, points[i].y - points[i - 1].y);
    }
    for (int it = 0; it < options.max_iterations && map.size() > 0; ++it) {
        report.iterations = it + 1;
        const Linearisation lin = linearise(model, map, p, feet);
        const double cost = lin.r.squaredNorm();
        // Only the lower triangle: LDLT reads no more, and it halves the
        // largest product of the solve.
        Eigen::MatrixXd JtJ = Eigen::MatrixXd::Zero(lin.J.cols(), lin.J.cols());
        JtJ.selfadjointView<Eigen::Lower>().rankUpdate(lin.J.transpose());
        const Eigen::VectorXd g = lin.J.transpose() * lin.r;
        bool improved = false;
        for (int tries = 0; tries < 10 && !improved; ++tries) {
            Eigen::MatrixXd A = JtJ;
            A.diagonal() += mu * (JtJ.diagonal().array() + 1e-12).matrix();
            const Eigen::VectorXd delta = A.ldlt().solve(-g);
            CurvatureModel trial = model;
            std::vector<double> v = map.get(model);
            for (std::size_t i = 0; i < v.size(); ++i) {
                v[i] += delta[static_cast<long>(i)];
            }
            map.set(trial, v);
            clamp_model(trial, options.min_length_m, max_length);
            const double c = cost_at_feet(trial, p, feet);
            if (std::isfinite(c) && c < cost) {
                const double gain = (cost - c) / std::max(cost, 1e-30);
                model = std::move(trial);
                mu = std::max(mu / 3, 1e-9);
                improved = true;
                if (total_length(model) > max_length) {
                    // Diverged: the curve has grown far longer than the data
                    // (spiralling at the curvature bound). Nothing to keep.
                    report.gave_up = true;
                    it = options.max_iterations;
                } else if (gain < 1e-7) {
                    it = options.max_iterations; // converged
                } else if (hopeless(c, gain, options.max_iterations - it - 1, give_up_cost)) {
                    report.gave_up = true;
                    it = options.max_iterations;
                }
            } else {
                mu *= 4;
            }
        }
        if (!improved) {
            break;
        }
    }
    return report;
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
    const std::vector<double> d = point_distances(model, points);
    double sum = 0.0;
    for (double x : d) {
        sum += x * x;
        report.max_m = std::max(report.max_m, x);
    }
    report.rms_m = d.empty() ? 0.0 : std::sqrt(sum / static_cast<double>(d.size()));
    return report;
}

} // namespace railodd::geometry::fit
