// Splicing a rebuilt stretch onto the end of a fitted chain; see
// tie_splice.hpp.
#include "tie_splice.hpp"

#include "design_splice.hpp"
#include "railodd/geometry/indexed_alignment.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

namespace railodd::geometry {

std::vector<double> polyline_chainage(const std::vector<Point>& p) {
    std::vector<double> t(p.size(), 0.0);
    for (std::size_t i = 1; i < p.size(); ++i) {
        t[i] = t[i - 1] + std::hypot(p[i].x - p[i - 1].x, p[i].y - p[i - 1].y);
    }
    return t;
}

Projection node_on(const IndexedAlignment& fit, const std::vector<Point>& p, const std::vector<double>& t, std::size_t k) {
    const double expected = t.back() > 0.0 ? t[k] * fit.length() / t.back() : 0.0;
    return fit.project_within(p[k].x, p[k].y, expected - 100.0, expected + 100.0);
}

double off_polyline(const Alignment& piece, std::vector<Point> nodes) {
    const Pose a = evaluate(piece, 0.0), b = evaluate(piece, length(piece));
    nodes.front() = {a.x, a.y};
    nodes.back() = {b.x, b.y};
    double worst = 0.0;
    const double len = length(piece);
    for (double s = 0.0; s <= len + 1.0; s += 2.0) {
        const Pose q = evaluate(piece, std::min(s, len));
        double best = std::numeric_limits<double>::infinity();
        for (std::size_t i = 0; i + 1 < nodes.size(); ++i) {
            const double dx = nodes[i + 1].x - nodes[i].x, dy = nodes[i + 1].y - nodes[i].y;
            const double l2 = dx * dx + dy * dy;
            const double u = l2 > 0.0 ? std::clamp(((q.x - nodes[i].x) * dx + (q.y - nodes[i].y) * dy) / l2, 0.0, 1.0) : 0.0;
            best = std::min(best, std::hypot(q.x - nodes[i].x - u * dx, q.y - nodes[i].y - u * dy));
        }
        worst = std::max(worst, best);
    }
    return worst;
}

namespace {

// The bounds a splice between contradicting poses is tried at in turn
// (R 5, 2.5 and 1 m).
constexpr double relaxed_curvatures[] = {0.2, 0.4, 1.0};
// No piece of the fit kept beside a splice is shorter.
constexpr double min_piece_m = 1.0;

double node_s(const Alignment& fit, const std::vector<Point>& p, const std::vector<double>& t, std::size_t k) {
    return node_on(IndexedAlignment(fit, 2.0), p, t, k).s;
}

// Where the fit is cut for a splice: at node k's foot, or at the knot
// within a metre of it on the kept side, which would otherwise keep a
// sliver of its element (Munich: 2 of its 11 elements under a metre).
// `kept_before`: the fit is kept before the cut (a splice at the end).
double cut_at(const Alignment& fit, const std::vector<Point>& p, const std::vector<double>& t, std::size_t k,
              bool kept_before) {
    const double s = node_s(fit, p, t, k);
    const std::vector<double> knots = primitive_s(fit);
    for (std::size_t i = 1; i < knots.size(); ++i) {
        const double gap = kept_before ? s - knots[i] : knots[i] - s;
        if (gap > 0.0 && gap < min_piece_m) {
            return knots[i];
        }
    }
    return s;
}

EndMiss miss(const Pose& got, const Pose& want) {
    return {std::hypot(got.x - want.x, got.y - want.y),
            std::abs(std::remainder(got.hdg - want.hdg, 2 * std::numbers::pi)),
            std::abs(got.curvature - want.curvature)};
}

// The stretch from `from` to `to` through its nodes: a few curves of
// railway design where they follow the nodes, else corners; where those
// turn tighter than a track can (nodes leaving the tie at an angle), the
// design closest to the nodes, however far (the chain's fit chooses
// between it and the tied fit).
Alignment stretch(const std::vector<Point>& p, const Pose& from, const Pose& to, const CornerFitOptions& o,
                  double tolerance, SpliceEnds ends = SpliceEnds::both_held) {
    if (std::optional<Alignment> a = design_splice(p, from, to, tolerance, ends)) {
        return *a;
    }
    Alignment corners = corner_polyline(p, from, to, o);
    if (!drivable(corners)) {
        const double off = std::numeric_limits<double>::infinity();
        if (std::optional<Alignment> a = closest_design_splice(p, from, to, off, max_track_curvature, ends)) {
            return *a;
        }
        // Poses no track's curve joins (a short chain between two ties the
        // mapping contradicts: Munich, 96 degrees in 14 m): the design that
        // joins them turning least tightly, where the corners turn tighter
        // (R 0.2 m there, 15 elements under a metre in 19 m).
        const double corners_peak = peak_curvature(corners);
        for (const double k : relaxed_curvatures) {
            if (k >= corners_peak) {
                break;
            }
            if (std::optional<Alignment> a = closest_design_splice(p, from, to, off, k, ends)) {
                return *a;
            }
        }
    }
    return corners;
}

} // namespace

std::size_t splice_start_node(const std::vector<double>& t, double tail_m) {
    std::size_t k = 0;
    while (k + 1 < t.size() && (k == 0 || t[k] < tail_m)) {
        ++k;
    }
    return k;
}

std::size_t splice_end_node(const std::vector<double>& t, double tail_m) {
    std::size_t k = t.empty() ? 0 : t.size() - 1;
    while (k > 0 && (k + 1 == t.size() || t.back() - t[k] < tail_m)) {
        --k;
    }
    return k;
}

Alignment splice_end(const Alignment& fit, const std::vector<Point>& p, const Pose& end, double tail_m,
                     const CornerFitOptions& o, double tolerance, bool start_free) {
    const std::vector<double> t = polyline_chainage(p);
    const std::size_t k = splice_end_node(t, tail_m);
    if (k == 0) {
        // The whole chain is the stretch: only the fit's start pose is kept,
        // and only as a first guess where the chain's start is free.
        return stretch(p, evaluate(fit, 0.0), end, o, tolerance,
                       start_free ? SpliceEnds::from_free : SpliceEnds::both_held);
    }
    const double s = cut_at(fit, p, t, k, true);
    const std::vector<Alignment> parts = split_alignment(fit, {s});
    Alignment out = parts.front();
    const Pose cut = evaluate(fit, s);
    const std::vector<Point> tail(p.begin() + static_cast<long>(k), p.end());
    const Alignment a = stretch(tail, cut, end, o, tolerance);
    out.primitives.insert(out.primitives.end(), a.primitives.begin(), a.primitives.end());
    return out;
}

Alignment splice_start(const Alignment& fit, const std::vector<Point>& p, const Pose& start, double tail_m,
                       const CornerFitOptions& o, double tolerance, bool end_free) {
    const std::vector<double> t = polyline_chainage(p);
    const std::size_t k = splice_start_node(t, tail_m);
    if (k + 1 == p.size()) {
        return stretch(p, start, evaluate(fit, length(fit)), o, tolerance,
                       end_free ? SpliceEnds::to_free : SpliceEnds::both_held);
    }
    const double s = cut_at(fit, p, t, k, false);
    const std::vector<Alignment> parts = split_alignment(fit, {s});
    const std::vector<Point> head(p.begin(), p.begin() + static_cast<long>(k) + 1);
    Alignment out = stretch(head, start, evaluate(fit, s), o, tolerance);
    const auto& rest = parts.back().primitives;
    out.primitives.insert(out.primitives.end(), rest.begin(), rest.end());
    return out;
}

EndMiss start_miss(const Alignment& a, const Pose& start) { return miss(evaluate(a, 0.0), start); }

EndMiss end_miss(const Alignment& a, const Pose& end) { return miss(evaluate(a, length(a)), end); }

} // namespace railodd::geometry
