// Rebuilding a tied stretch as a few curves; see design_splice.hpp.
#include "design_splice.hpp"

#include "fit/curvature_model.hpp"
#include "fit/least_squares.hpp"
#include "tie_splice.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

namespace railodd::geometry {

namespace {

constexpr int max_curves = 4;
// No element of the splice is shorter: issue 37 wants none under a metre.
constexpr double min_element_m = 1.0;

double heading_between(const Point& a, const Point& b) { return std::atan2(b.y - a.y, b.x - a.x); }

// The mapped polyline's heading at chainage s (of the segment holding it),
// unwrapped to lie within half a turn of `near`.
double polyline_heading(const std::vector<Point>& p, const std::vector<double>& t, double s, double near) {
    std::size_t i = 1;
    while (i + 1 < p.size() && t[i] < s) {
        ++i;
    }
    const double h = heading_between(p[i - 1], p[i]);
    return near + std::remainder(h - near, 2 * std::numbers::pi);
}

// n curves over the stretch, each a transition in, an arc and (the last)
// a transition out to the tie's curvature; lengths in equal shares, each
// arc's curvature the polyline's turn over its share.
fit::CurvatureModel first_guess(const std::vector<Point>& p, const std::vector<double>& t, const Pose& from,
                                const Pose& to, int n, double max_curvature) {
    const double share = t.back() / static_cast<double>(3 * n + 1);
    fit::CurvatureModel m;
    m.start = from;
    m.start_free = false;
    m.knot_var.push_back(-1);
    m.knot_fixed.push_back(from.curvature);
    double at = from.hdg;
    for (int i = 0; i < n; ++i) {
        const double s = t.back() * static_cast<double>(i + 1) / static_cast<double>(n);
        const double next = i + 1 == n ? at + std::remainder(to.hdg - at, 2 * std::numbers::pi)
                                       : polyline_heading(p, t, s, at);
        m.curv.push_back(std::clamp((next - at) / (3.0 * share), -max_curvature, max_curvature));
        at = next;
        const int v = static_cast<int>(m.curv.size()) - 1;
        m.push_segment(share, true, v);
        m.push_segment(2.0 * share, true, v);
    }
    m.push_segment(share, true, -1, to.curvature);
    return m;
}

std::vector<fit::Point2> as_points(const std::vector<Point>& p) {
    std::vector<fit::Point2> out;
    out.reserve(p.size());
    for (const Point& q : p) {
        out.push_back({q.x, q.y});
    }
    return out;
}

// The design of n curves over the stretch, where the solve converges,
// meets the tied pose, passes the nodes within `tolerance_m`, turns as a
// track can and loops nowhere; with how far it passes from the nodes (the
// callers add the polyline's test, on the nodes they measure by).
struct Design {
    Alignment alignment;
    double off_m = 0.0;
};
std::optional<Design> design_of(int n, const std::vector<Point>& points, const std::vector<double>& t,
                                const Pose& from, const Pose& to, double tolerance_m, double max_curvature,
                                SpliceEnds ends) {
    fit::SolveOptions so;
    so.sigma_m = 0.3;
    so.pin_first = ends == SpliceEnds::from_free; // a free start stands at its node
    so.pin_last = true;
    if (ends != SpliceEnds::to_free) {
        so.end = to;
    }
    // Tiny problems (a few curves, a few dozen nodes): iterations are cheap,
    // and a stretch whose tie meets its nodes at an angle converges slowly.
    so.max_iterations = 100;
    so.geodesic_acceleration = true;
    so.abandon_loops = true;
    so.min_length_m = min_element_m;
    so.max_curvature = max_curvature;
    fit::CurvatureModel m = first_guess(points, t, from, to, n, max_curvature);
    m.start_free = ends == SpliceEnds::from_free;
    const fit::SolveReport r = fit::solve(m, as_points(points), so);
    if (!r.end_met || r.gave_up || r.max_m > tolerance_m) {
        return std::nullopt;
    }
    Design d{m.to_alignment(), r.max_m};
    if (peak_curvature(d.alignment) > max_curvature || loops_back(d.alignment, points)) {
        return std::nullopt;
    }
    return d;
}

bool room_for(int curves, double stretch) { return stretch >= min_element_m * static_cast<double>(3 * curves + 1); }

} // namespace

double peak_curvature(const Alignment& a) {
    double k = 0.0;
    for (const Primitive& e : a.primitives) {
        k = std::max({k, std::abs(e.curv_start), std::abs(e.curv_end)});
    }
    return k;
}

bool drivable(const Alignment& a) { return peak_curvature(a) <= max_track_curvature; }

std::optional<Alignment> design_splice(const std::vector<Point>& points, const Pose& from, const Pose& to,
                                       double tolerance_m, SpliceEnds ends) {
    if (points.size() < 2 || !(tolerance_m > 0.0)) {
        return std::nullopt;
    }
    const std::vector<double> t = polyline_chainage(points);
    for (int n = 1; n <= max_curves && room_for(n, t.back()); ++n) {
        std::optional<Design> d = design_of(n, points, t, from, to, tolerance_m, max_track_curvature, ends);
        // Between nodes far apart a few curves can swing wide of the chord
        // and still pass every node (truth seed 1266 at 1 m: 13 m off
        // between nodes 60 m apart, at R 24 m).
        if (d && off_polyline(d->alignment, points) <= tolerance_m) {
            return std::move(d->alignment);
        }
    }
    return std::nullopt;
}

std::optional<Alignment> closest_design_splice(const std::vector<Point>& points, const Pose& from, const Pose& to,
                                               double max_off_m, double max_curvature, SpliceEnds ends) {
    if (points.size() < 2) {
        return std::nullopt;
    }
    const std::vector<double> t = polyline_chainage(points);
    std::optional<Design> best;
    // The nodes that contradict a pose lie next to it, and pull the solve
    // into a loop or away from the pose it must meet (a siding drawn onto
    // its main line at 0.54 rad): the nodes within `clear` of either end
    // are left out of the solve, not of the measure.
    std::size_t last_kept = points.size() + 1;
    for (const double clear : {0.0, 5.0, 10.0, 20.0, std::numeric_limits<double>::infinity()}) {
        std::vector<Point> kept{points.front()};
        for (std::size_t i = 1; i + 1 < points.size(); ++i) {
            if (t[i] > clear && t.back() - t[i] > clear) {
                kept.push_back(points[i]);
            }
        }
        kept.push_back(points.back());
        if (kept.size() == last_kept) {
            continue;
        }
        last_kept = kept.size();
        const std::vector<double> tk = polyline_chainage(kept);
        for (int n = 1; n <= max_curves && room_for(n, t.back()); ++n) {
            std::optional<Design> d =
                design_of(n, kept, tk, from, to, std::numeric_limits<double>::infinity(), max_curvature, ends);
            if (!d || loops_back(d->alignment, points)) {
                continue;
            }
            d->off_m = std::max(measure_fit(d->alignment, points).max_m, off_polyline(d->alignment, points));
            if (!best || d->off_m < best->off_m) {
                best = std::move(d);
            }
        }
    }
    if (!best || best->off_m > max_off_m) {
        return std::nullopt;
    }
    return std::move(best->alignment);
}

} // namespace railodd::geometry
