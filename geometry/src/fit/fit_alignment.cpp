// Window-by-window fitting: the node noise and outlier nodes are read from
// the nodes, a fine clothoid spline estimates the curvature diagram, and the
// design read off it with the least penalised-likelihood score
// (design_selection.cpp) gives the final alignment. See docs/geometry.md.
#include "railodd/geometry/fit_alignment.hpp"

#include "chord_heading.hpp"
#include "curvature_model.hpp"
#include "design_fit.hpp"
#include "design_selection.hpp"
#include "least_squares.hpp"
#include "outlier_nodes.hpp"
#include "parallel_guide.hpp"
#include "railodd/geometry/indexed_alignment.hpp"
#include "structure.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <numeric>
#include <set>
#include <stdexcept>

namespace railodd::geometry {

namespace {

using fit::CurvatureModel;
using fit::WindowFit;
using fit::Point2;

using fit::chainage;
using fit::ChordHeading;

struct WindowEnds {
    std::optional<Pose> start;
    std::optional<Pose> end;
    bool start_at_switch = false; // start is the chain's tie, not the previous window's end
};

// Knot chainages of the fine spline: about every knot_spacing where nodes are
// dense, at the nodes themselves where they are sparse (long straights), so
// that no knot interval is without data.
std::vector<double> knot_chainages(const std::vector<double>& t, double spacing) {
    std::vector<double> knots{0.0};
    for (std::size_t i = 1; i < t.size(); ++i) {
        if (t[i] - knots.back() >= spacing) {
            // Split long gaps between this and the previous knot evenly at node density.
            knots.push_back(t[i]);
        }
    }
    if (t.back() - knots.back() > 1e-6) {
        if (knots.size() > 1 && t.back() - knots.back() < 0.5 * spacing) {
            knots.back() = t.back(); // a short tail joins the last interval
        } else {
            knots.push_back(t.back());
        }
    }
    return knots;
}

// A branch tied to its switch must leave along the main track and then bend
// away at turnout radius (190-500 m) within a few tens of metres; mappers
// often draw that as one kinked segment. Extra knots there let the spline
// follow it.
void add_turnout_knots(std::vector<double>& knots, bool start_tied, bool end_tied, double spacing) {
    const double total = knots.back();
    std::vector<double> extra;
    for (double d = spacing; d < 4.5 * spacing && d < 0.4 * total; d += spacing) {
        if (start_tied) {
            extra.push_back(d);
        }
        if (end_tied) {
            extra.push_back(total - d);
        }
    }
    for (double e : extra) {
        const auto it = std::lower_bound(knots.begin(), knots.end(), e);
        const bool near = (it != knots.end() && *it - e < 0.5 * spacing) ||
                          (it != knots.begin() && e - *(it - 1) < 0.5 * spacing);
        if (!near) {
            knots.insert(it, e);
        }
    }
}

// The fine clothoid spline: every knot curvature free.
CurvatureModel fine_spline(const std::vector<Point2>& p, const WindowEnds& ends, const FitOptions& o) {
    const std::vector<double> t = chainage(p);
    const ChordHeading heading(p, std::max(5.0, 15.0 * o.noise_sigma_m));
    CurvatureModel m;
    m.start_free = !ends.start;
    m.start = ends.start.value_or(Pose{p.front().x, p.front().y, heading.at(0.0), 0.0});
    std::vector<double> knots = knot_chainages(t, o.knot_spacing_m);
    if (knots.size() < 2) {
        knots = {0.0, std::max(t.back(), 1.0)};
    }
    add_turnout_knots(knots, ends.start.has_value(), ends.end.has_value(), o.knot_spacing_m);
    // Each knot's curvature is the heading change across half of each
    // neighbouring interval, at least a knot spacing. Where nodes are sparse
    // a knot's curvature is carried (linearly fading) across the whole
    // interval, so a difference over a few metres beside a long chord (one
    // short, noisy chord's heading) would turn the curve by tenths of a
    // radian there: hundreds of metres off by the window's end, too far for
    // the solve to recover (seen on the sample route).
    const double h = o.knot_spacing_m;
    auto curvature_at = [&](double s, double before, double after) {
        const double back = std::max(h, 0.5 * before), ahead = std::max(h, 0.5 * after);
        return (heading.at(s + ahead) - heading.at(s - back)) / (back + ahead);
    };
    if (ends.start) {
        m.knot_var.push_back(-1);
        m.knot_fixed.push_back(ends.start->curvature);
    } else {
        m.curv.push_back(curvature_at(0.0, 0.0, knots.size() > 1 ? knots[1] : 0.0));
        m.knot_var.push_back(0);
        m.knot_fixed.push_back(0.0);
    }
    for (std::size_t k = 1; k < knots.size(); ++k) {
        const double length = knots[k] - knots[k - 1];
        if (k + 1 == knots.size() && ends.end) {
            m.push_segment(length, false, -1, ends.end->curvature);
        } else {
            const double after = k + 1 < knots.size() ? knots[k + 1] - knots[k] : 0.0;
            m.curv.push_back(curvature_at(knots[k], length, after));
            m.push_segment(length, false, static_cast<int>(m.curv.size() - 1));
        }
    }
    return m;
}

fit::SolveOptions solve_options(const WindowEnds& ends, const FitOptions& o) {
    fit::SolveOptions so;
    so.sigma_m = o.noise_sigma_m;
    so.pin_first = !ends.start;
    so.pin_last = true;
    so.end = ends.end;
    return so;
}

fit::SolveOptions design_solve_options(const WindowEnds& ends, const FitOptions& o) {
    fit::SolveOptions so = solve_options(ends, o);
    so.geodesic_acceleration = true;
    so.abandon_loops = true; // a candidate that loops is not chosen (best_candidate)
    return so;
}

// The fine spline's way: its curvature diagram segmented into candidate
// designs; the spline itself (or a denser one) where none comes near. Taken
// only where the trend filter's designs do not (fit_window).
WindowFit fit_window_by_spline(const std::vector<Point2>& p, const WindowEnds& ends, const FitOptions& o,
                               const fit::GuidedStructure* guided) {
    CurvatureModel fine = fine_spline(p, ends, o);
    fit::SolveOptions so = solve_options(ends, o);
    so.kink_sigma = o.kink_sigma;
    so.ridge_sigma = o.ridge_sigma;
    const fit::SolveReport fine_report = fit::solve(fine, p, so);
    so.kink_sigma = 0.0;
    so.ridge_sigma = 0.0;
    so.geodesic_acceleration = true;
    so.abandon_loops = true; // a candidate that loops is not chosen (best_design)

    std::vector<double> ks, kk;
    double s = 0.0;
    for (std::size_t k = 0; k < fine.knot_var.size(); ++k) {
        ks.push_back(s);
        kk.push_back(fine.knot_curvature(k));
        s += k < fine.segments() ? fine.lengths[k] : 0.0;
    }
    fit::StructureEnds se;
    se.start = ends.start.value_or(fine.start);
    se.start_fixed = ends.start.has_value();
    if (ends.end) {
        se.end_curvature = ends.end->curvature;
    }
    if (auto best = best_design(p, ks, kk, se, so, fine_report, o.noise_sigma_m, guided)) {
        return std::move(*best);
    }
    if (fine_report.max_m > 1.0) {
        // Nothing came within 1 m of every node: a denser, looser spline
        // (half the knot spacing, kink and curvature scales ten times wider)
        // follows tight, kinked mapping and is still G2.
        FitOptions loose = o;
        loose.knot_spacing_m = 0.5 * o.knot_spacing_m;
        CurvatureModel dense = fine_spline(p, ends, loose);
        fit::SolveOptions ds = solve_options(ends, o);
        ds.kink_sigma = 10 * o.kink_sigma;
        ds.ridge_sigma = 10 * o.ridge_sigma;
        const fit::SolveReport dr = fit::solve(dense, p, ds);
        if (dr.max_m < fine_report.max_m) {
            return {std::move(dense), dr, true};
        }
    }
    return {std::move(fine), fine_report, true};
}

// The design read from the nodes by the trend filter where one comes near
// them; else the fine spline's way. Either way a parallel track's design
// (guides, already fitted) is a candidate where the window runs beside it.
WindowFit fit_window(const std::vector<Point2>& p, const WindowEnds& ends, const FitOptions& o,
                     const std::vector<IndexedAlignment>& guides) {
    std::optional<fit::GuidedStructure> g;
    for (std::size_t i = 0; i < guides.size() && !g; ++i) {
        g = fit::guided_structure(p, guides[i]);
    }
    const fit::GuidedStructure* guided = g ? &*g : nullptr;
    fit::StructureEnds se;
    if (ends.start) {
        se.start = *ends.start;
        se.start_fixed = true;
    }
    if (ends.end) {
        se.end_curvature = ends.end->curvature;
    }
    if (auto best = fit::trend_design(p, se, ends.start_at_switch, design_solve_options(ends, o), o.noise_sigma_m,
                                      guided)) {
        return std::move(*best);
    }
    return fit_window_by_spline(p, ends, o, guided);
}

// Where to cut a window's fit: at `preferred` if a straight is there, else
// at the nearest point of a straight between 35 % and 80 % of the window (at
// least 20 m into it), else at `preferred` all the same. A window starting
// inside a curve is tied to the curvature this one read there, and splits
// the curve in two.
double window_cut(const Alignment& a, double preferred) {
    constexpr double inset = 20.0;
    const double lo = 0.35 / 0.6 * preferred, hi = 0.8 / 0.6 * preferred;
    double s = 0.0, cut = preferred, best = std::numeric_limits<double>::infinity();
    for (const auto& q : a.primitives) {
        const double a0 = std::max(s + inset, lo), a1 = std::min(s + q.length - inset, hi);
        if (q.kind == PrimitiveKind::line && a0 <= a1) {
            const double here = std::clamp(preferred, a0, a1);
            if (std::abs(here - preferred) < best) {
                best = std::abs(here - preferred);
                cut = here;
            }
        }
        s += q.length;
    }
    return std::min(cut, s);
}

// fit_window, again without far nodes until none is left (at most three
// rounds). `kept` says which of p the fit used.
WindowFit fit_window_robust(const std::vector<Point2>& p, const WindowEnds& ends, const FitOptions& o,
                            const std::vector<IndexedAlignment>& guides, std::vector<bool>& kept) {
    kept.assign(p.size(), true);
    std::vector<std::size_t> index(p.size()); // of p, for each point fitted
    std::iota(index.begin(), index.end(), std::size_t{0});
    WindowFit w = fit_window(p, ends, o, guides);
    for (int round = 0; round < 3; ++round) {
        const std::vector<std::size_t> far = fit::far_nodes(w.report.distances_m, o.noise_sigma_m);
        if (far.empty()) {
            break;
        }
        for (auto f = far.rbegin(); f != far.rend(); ++f) {
            kept[index[*f]] = false;
            index.erase(index.begin() + static_cast<std::ptrdiff_t>(*f));
        }
        std::vector<Point2> q;
        for (const std::size_t i : index) {
            q.push_back(p[i]);
        }
        w = fit_window(q, ends, o, guides);
    }
    return w;
}

} // namespace

std::vector<double> distances(const Alignment& alignment, const std::vector<Point>& points) {
    if (points.empty()) {
        return {};
    }
    return distances(IndexedAlignment(alignment, 2.0), points);
}

std::vector<double> distances(const IndexedAlignment& ia, const std::vector<Point>& points) {
    std::vector<double> d;
    d.reserve(points.size());
    for (const auto& p : points) {
        d.push_back(ia.project(p.x, p.y).distance);
    }
    return d;
}

FitQuality measure_fit(const Alignment& alignment, const std::vector<Point>& points) {
    FitQuality q;
    q.points = points.size();
    std::vector<double> d = distances(alignment, points);
    if (d.empty()) {
        return q;
    }
    double sum = 0.0;
    for (double x : d) {
        sum += x * x;
    }
    q.rms_m = std::sqrt(sum / static_cast<double>(d.size()));
    std::sort(d.begin(), d.end());
    q.max_m = d.back();
    q.p95_m = d[static_cast<std::size_t>(std::floor(0.95 * static_cast<double>(d.size() - 1)))];
    return q;
}

namespace {

// The chain's node scatter as the outlier scan measured it (the MAD of each
// node's offset from its neighbours' local quadratic), no finer than the
// design can be told from: track lies within centimetres of its design, and
// OSM stores 1e-7 degrees (about a centimetre). Where too few nodes lie close
// enough together to give a scale, the value for traced OSM track is used.
double estimated_noise(const fit::OutlierScan& scan) {
    constexpr double floor_m = 0.05, ceiling_m = 5.0, untested_m = 0.1;
    return scan.tested < 12 ? untested_m : std::clamp(scan.noise_sigma_m, floor_m, ceiling_m);
}

// Per point, the index among the distinct points of the one it is or
// repeats (within a micrometre of the last distinct one).
std::vector<std::size_t> distinct_indices(const std::vector<Point>& in) {
    std::vector<std::size_t> k(in.size(), 0);
    for (std::size_t i = 1, last = 0; i < in.size(); ++i) {
        const bool repeat = std::hypot(in[i].x - in[last].x, in[i].y - in[last].y) <= 1e-6;
        last = repeat ? last : i;
        k[i] = k[i - 1] + (repeat ? 0 : 1);
    }
    return k;
}

std::vector<Point2> without_repeats(const std::vector<Point>& in, const std::vector<std::size_t>& distinct) {
    std::vector<Point2> out;
    for (std::size_t i = 0; i < in.size(); ++i) {
        if (i == 0 || distinct[i] != distinct[i - 1]) {
            out.push_back({in[i].x, in[i].y});
        }
    }
    return out;
}

// Per distinct point, whether it is held: a repeat holds the point it repeats.
std::vector<char> held_mask(const std::vector<std::size_t>& distinct, const std::vector<std::size_t>& held,
                            std::size_t n) {
    std::vector<char> mask(n, 0);
    for (const std::size_t h : held) {
        if (h < distinct.size()) {
            mask[distinct[h]] = 1;
        }
    }
    return mask;
}

// Headings are never wrapped along an alignment: the end target must be the
// turn of the mapped line away from the start, not that plus 2 pi.
std::optional<Pose> end_target(const std::vector<Point2>& p, const std::vector<double>& t,
                               const std::optional<Pose>& start, std::optional<Pose> end, double sigma) {
    if (end) {
        const ChordHeading h(p, std::max(5.0, 15.0 * sigma));
        const double start_hdg = start ? start->hdg : h.at(0.0);
        const double expected = start_hdg + (h.at(t.back()) - h.at(0.0));
        end->hdg += 2 * std::numbers::pi * std::round((expected - end->hdg) / (2 * std::numbers::pi));
    }
    return end;
}

// Index of the last node of the window starting at i0 (chainages t): a
// window's length, or the rest where that is at most one and a half.
std::size_t window_end(const std::vector<double>& t, std::size_t i0, double window_m) {
    if (t.back() - t[i0] <= 1.5 * window_m) {
        return t.size() - 1;
    }
    std::size_t i1 = i0 + 1;
    while (i1 + 1 < t.size() && t[i1 + 1] - t[i0] <= window_m) {
        ++i1;
    }
    return i1;
}

// Fits p window by window into result (alignment, window counts); returns the
// nodes (of p) some window's fit left out as far off.
std::set<std::size_t> fit_windows(const std::vector<Point2>& p, std::optional<Pose> window_start,
                                  const std::optional<Pose>& end, const FitOptions& o, const std::vector<IndexedAlignment>& guides,
                                  FitResult& result) {
    const std::vector<double> t = chainage(p);
    std::set<std::size_t> far;
    for (std::size_t i0 = 0;;) {
        const std::size_t i1 = window_end(t, i0, o.window_m);
        const bool last = i1 + 1 == p.size();
        const std::vector<Point2> wp(p.begin() + static_cast<long>(i0), p.begin() + static_cast<long>(i1) + 1);
        std::vector<bool> kept;
        const WindowFit w =
            fit_window_robust(wp, {window_start, last ? end : std::nullopt, i0 == 0 && window_start}, o, guides, kept);
        for (std::size_t j = 0; j < kept.size(); ++j) {
            if (!kept[j]) {
                far.insert(i0 + j);
            }
        }
        ++result.quality.windows;
        result.quality.fallback_windows += w.fallback ? 1 : 0;
        const Alignment a = w.model.to_alignment();
        if (result.alignment.primitives.empty()) {
            result.alignment.start = a.start;
        }
        auto& out = result.alignment.primitives;
        if (last) {
            out.insert(out.end(), a.primitives.begin(), a.primitives.end());
            return far;
        }
        // Keep the first ~60 % of the window; the next window starts exactly
        // where it ends, on a straight where there is one (a window starting
        // inside a curve is tied to the curvature this one read there).
        // The cut is at a node's foot: the next window's first node marks its start.
        const IndexedAlignment ia(a, 2.0);
        const double cut = window_cut(a, 0.6 * o.window_m);
        std::size_t k = i0 + 1;
        while (k + 1 < i1 && ia.project(p[k + 1].x, p[k + 1].y).s <= cut) {
            ++k;
        }
        const std::vector<Alignment> parts = split_alignment(a, {ia.project(p[k].x, p[k].y).s});
        out.insert(out.end(), parts.front().primitives.begin(), parts.front().primitives.end());
        window_start = parts.back().start;
        i0 = k;
    }
}

} // namespace

FitResult fit_alignment(const std::vector<Point>& points, const std::optional<Pose>& start,
                        const std::optional<Pose>& end, const FitOptions& options) {
    return fit_alignment(points, start, end, options, {});
}

FitResult fit_alignment(const std::vector<Point>& points, const std::optional<Pose>& start,
                        const std::optional<Pose>& end, const FitOptions& options, const std::vector<IndexedAlignment>& guides,
                        const std::vector<std::size_t>& held) {
    const std::vector<std::size_t> distinct = distinct_indices(points);
    const std::vector<Point2> mapped = without_repeats(points, distinct);
    if (mapped.size() < 2) {
        throw std::invalid_argument("fit_alignment: fewer than two distinct points");
    }
    if (options.method == FitMethod::design_search) {
        return fit::fit_design(mapped, start, end, options, guides, held_mask(distinct, held, mapped.size()));
    }
    // Outlier nodes are left out of the fit; its quality is still measured
    // on every node, so the report shows them.
    const fit::OutlierScan outliers = fit::find_outlier_nodes(mapped);
    FitOptions o = options;
    if (!(o.noise_sigma_m > 0.0)) {
        o.noise_sigma_m = estimated_noise(outliers);
    }
    std::vector<Point2> p;
    for (std::size_t i = 0; i < mapped.size(); ++i) {
        if (!outliers.outlier[i]) {
            p.push_back(mapped[i]);
        }
    }
    FitResult result;
    const std::set<std::size_t> far =
        fit_windows(p, start, end_target(p, chainage(p), start, end, o.noise_sigma_m), o, guides, result);
    std::vector<Point> all;
    all.reserve(mapped.size());
    for (const auto& q : mapped) {
        all.push_back({q.x, q.y});
    }
    const FitQuality q = measure_fit(result.alignment, all);
    result.quality.points = q.points;
    result.quality.rms_m = q.rms_m;
    result.quality.p95_m = q.p95_m;
    result.quality.max_m = q.max_m;
    result.quality.followed_max_m = q.max_m;
    result.quality.noise_sigma_m = o.noise_sigma_m;
    result.quality.outliers =
        far.size() + static_cast<std::size_t>(std::count(outliers.outlier.begin(), outliers.outlier.end(), true));
    return result;
}

} // namespace railodd::geometry
