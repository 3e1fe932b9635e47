#include "curvature_trend.hpp"

#include "band_matrix.hpp"
#include "chord_heading.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <optional>
#include <numbers>

namespace railodd::geometry::fit {

namespace {

constexpr double pi = std::numbers::pi;

double wrap(double a) { return a - 2 * pi * std::round(a / (2 * pi)); }

// The reference line on a chainage grid of spacing h: poses integrated
// from the chords' headings, so that the nodes' offsets from it are small
// and their curvature a correction to its own.
struct Reference {
    double h = 4.0;
    std::vector<double> x, y, hdg, curv; // per grid point
};

// Poses integrated along hdg (one per grid point, spacing h) from (x0, y0).
Reference integrate(double x0, double y0, std::vector<double> hdg, double h) {
    Reference r;
    r.h = h;
    r.x.push_back(x0);
    r.y.push_back(y0);
    for (std::size_t k = 1; k < hdg.size(); ++k) {
        const double a = 0.5 * (hdg[k - 1] + hdg[k]);
        r.x.push_back(r.x.back() + h * std::cos(a));
        r.y.push_back(r.y.back() + h * std::sin(a));
    }
    r.curv.assign(hdg.size(), 0.0);
    for (std::size_t k = 1; k + 1 < hdg.size(); ++k) {
        r.curv[k] = (hdg[k + 1] - hdg[k - 1]) / (2 * h);
    }
    r.hdg = std::move(hdg);
    return r;
}

struct Offset {
    double s = 0.0;
    double e = 0.0;
};

// Each node's place on the reference: chainage and signed offset (left +).
std::vector<Offset> offsets(const std::vector<Point2>& p, const Reference& r) {
    const std::size_t cells = r.x.size() - 1;
    const double length = r.h * static_cast<double>(cells);
    std::vector<Offset> out;
    std::size_t j0 = 0;
    double last_s = 0.0;
    for (std::size_t i = 0; i < p.size(); ++i) {
        const double step = i > 0 ? std::hypot(p[i].x - p[i - 1].x, p[i].y - p[i - 1].y) : 0.0;
        const std::size_t lo = j0 > 8 ? j0 - 8 : 0;
        const std::size_t hi = std::min(cells - 1, j0 + static_cast<std::size_t>(1.5 * step / r.h) + 8);
        double best = std::numeric_limits<double>::infinity();
        Offset o;
        std::size_t bj = j0;
        for (std::size_t j = lo; j <= hi; ++j) {
            const double dx = r.x[j + 1] - r.x[j], dy = r.y[j + 1] - r.y[j];
            const double len2 = dx * dx + dy * dy;
            const double qx = p[i].x - r.x[j], qy = p[i].y - r.y[j];
            double u = (qx * dx + qy * dy) / len2;
            const bool first = j == 0, last = j + 1 == cells;
            u = std::clamp(u, first ? -0.5 : 0.0, last ? 1.5 : 1.0);
            const double ex = qx - u * dx, ey = qy - u * dy;
            const double d2 = ex * ex + ey * ey;
            if (d2 < best) {
                best = d2;
                bj = j;
                const double len = std::sqrt(len2);
                o.s = r.h * (static_cast<double>(j) + u);
                o.e = (dx * qy - dy * qx) / len;
            }
        }
        o.s = std::clamp(o.s, 0.0, length);
        o.s = std::max(o.s, last_s);
        last_s = o.s;
        j0 = bj;
        out.push_back(o);
    }
    return out;
}

// Catmull-Rom weights of y[j-1 .. j+2] at fraction u of cell j (linear in
// the first and last cell).
void interpolation_row(double s, double h, std::size_t cells, std::array<std::size_t, 4>& c,
                       std::array<double, 4>& v) {
    const std::size_t j = std::min(cells - 1, static_cast<std::size_t>(std::max(0.0, s / h)));
    const double u = std::clamp(s / h - static_cast<double>(j), 0.0, 1.0);
    if (j == 0 || j + 2 > cells) {
        c = {j, j + 1, j + 1, j + 1};
        v = {1 - u, u, 0.0, 0.0};
        return;
    }
    c = {j - 1, j, j + 1, j + 2};
    const double u2 = u * u, u3 = u2 * u;
    v = {0.5 * (-u3 + 2 * u2 - u), 0.5 * (3 * u3 - 5 * u2 + 2), 0.5 * (-3 * u3 + 4 * u2 + u), 0.5 * (u3 - u2)};
}

// The filter on one reference: offsets y per grid point minimising
// sum (e_i - y(s_i))^2 / sigma^2 + lambda sum |second difference of curvature|
// + straight_lambda h sum |curvature| (curvature = reference curvature + y''),
// by iteratively reweighted least squares; nothing where the band system is
// not positive definite.
struct Filtered {
    std::vector<double> y, curv, kink; // kink: second difference of curvature per grid point
};

class TrendFilter {
public:
    TrendFilter(const Reference& r, const std::vector<Offset>& o, const TrendEnds& ends, double sigma)
        : r_(r), o_(o), ends_(ends), sigma_(sigma), cells_(r.x.size() - 1) {}

    std::optional<Filtered> run(double lambda, std::vector<double>& weights) const {
        Filtered f;
        for (int iteration = 0; iteration < iterations; ++iteration) {
            std::vector<double> y;
            if (!solve_once(lambda, weights, y)) {
                return std::nullopt;
            }
            f = read(y);
            double change = 0.0;
            const std::size_t n = f.kink.size();
            for (std::size_t k = 0; k < 2 * n; ++k) {
                const double w = k < n ? 1.0 / std::max(std::abs(f.kink[k]), epsilon)
                                       : 1.0 / std::max(std::abs(f.curv[k - n]), curvature_epsilon);
                change = std::max(change, std::abs(w - weights[k]) / std::max(w, weights[k]));
                weights[k] = w;
            }
            if (change < 1e-3) {
                break;
            }
        }
        return f;
    }

    static constexpr double epsilon = 1e-8; // 1/m per grid step: a kink's size below which it is none
    static constexpr double curvature_epsilon = 1e-7; // 1/m: a curvature below which it is a straight's
    double straight_lambda = 300.0; // per radian of turn: the prior for straights
    int iterations = 12;

private:
    bool solve_once(double lambda, const std::vector<double>& weights, std::vector<double>& y) const {
        const std::size_t n = cells_ + 1;
        const double h = r_.h, h2 = h * h;
        BandMatrix a(n);
        y.assign(n, 0.0);
        const double wd = 1.0 / (sigma_ * sigma_);
        for (const Offset& o : o_) {
            std::array<std::size_t, 4> c{};
            std::array<double, 4> v{};
            interpolation_row(o.s, h, cells_, c, v);
            a.add(c, v, wd, o.e, y);
        }
        for (std::size_t k = 2; k + 2 <= cells_; ++k) {
            const double dref = r_.curv[k - 1] - 2 * r_.curv[k] + r_.curv[k + 1];
            const std::array<std::size_t, 5> c{k - 2, k - 1, k, k + 1, k + 2};
            const std::array<double, 5> v{1 / h2, -4 / h2, 6 / h2, -4 / h2, 1 / h2};
            a.add(c, v, lambda * weights[k] * loosen(k), -dref, y);
        }
        for (std::size_t k = 1; k < cells_; ++k) {
            const std::array<std::size_t, 3> c{k - 1, k, k + 1};
            const std::array<double, 3> v{1 / h2, -2 / h2, 1 / h2};
            a.add(c, v, straight_lambda * h * weights[n + k] * loosen(k), -r_.curv[k], y);
        }
        const double tie = 1e4 * wd;
        if (ends_.start) {
            a.add(std::array<std::size_t, 1>{0}, std::array<double, 1>{1.0}, tie, 0.0, y);
            const double dh = wrap(ends_.start->hdg - r_.hdg[0]);
            a.add(std::array<std::size_t, 2>{0, 1}, std::array<double, 2>{-1 / h, 1 / h}, tie * h2, dh, y);
            a.add(std::array<std::size_t, 3>{0, 1, 2}, std::array<double, 3>{1 / h2, -2 / h2, 1 / h2}, tie * h2 * h2,
                  ends_.start->curvature - r_.curv[1], y);
        }
        if (ends_.end_curvature) {
            const std::size_t g = cells_;
            a.add(std::array<std::size_t, 3>{g - 2, g - 1, g}, std::array<double, 3>{1 / h2, -2 / h2, 1 / h2},
                  tie * h2 * h2, *ends_.end_curvature - r_.curv[g - 1], y);
        }
        a.add_diagonal(1e-9 * wd);
        return a.solve(y);
    }

    // A branch tied to its switch must leave along the through track and
    // bend away at turnout radius within a few tens of metres; mappers often
    // draw it leaving at an angle. Near a switch the penalties are a
    // hundredth, so that the line can turn there. (A window's start tied to
    // the previous window lies on a straight: no loosening there.)
    double loosen(std::size_t k) const {
        constexpr double near_m = 40.0;
        const double s = r_.h * static_cast<double>(k), rest = r_.h * static_cast<double>(cells_ - k);
        return (ends_.start_at_switch && s < near_m) || (ends_.end_curvature && rest < near_m) ? 0.01 : 1.0;
    }

    Filtered read(const std::vector<double>& y) const {
        Filtered f;
        const double h2 = r_.h * r_.h;
        f.y = y;
        f.curv.assign(y.size(), 0.0);
        for (std::size_t k = 1; k < cells_; ++k) {
            f.curv[k] = r_.curv[k] + (y[k - 1] - 2 * y[k] + y[k + 1]) / h2;
        }
        f.curv[0] = f.curv[1];
        f.curv[cells_] = f.curv[cells_ - 1];
        f.kink.assign(y.size(), 0.0);
        for (std::size_t k = 2; k + 2 <= cells_; ++k) {
            f.kink[k] = f.curv[k - 1] - 2 * f.curv[k] + f.curv[k + 1];
        }
        return f;
    }

    const Reference& r_;
    const std::vector<Offset>& o_;
    const TrendEnds& ends_;
    double sigma_;
    std::size_t cells_;
};

// The grid's reference line moved onto the filtered offsets y.
Reference moved(const Reference& ref, const std::vector<double>& y, const std::optional<Pose>& start) {
    const std::size_t cells = ref.x.size() - 1;
    std::vector<double> hdg = ref.hdg;
    for (std::size_t k = 0; k <= cells; ++k) {
        const std::size_t a = k > 0 ? k - 1 : 0, b = std::min(cells, k + 1);
        hdg[k] += (y[b] - y[a]) / (ref.h * static_cast<double>(b - a));
    }
    const double nx = -std::sin(ref.hdg[0]), ny = std::cos(ref.hdg[0]);
    Reference out = integrate(ref.x[0] + y[0] * nx, ref.y[0] + y[0] * ny, std::move(hdg), ref.h);
    if (start) {
        out.x[0] = start->x; // exact: the tie rows hold y[0] at zero
        out.y[0] = start->y;
    }
    return out;
}

// The estimate a filtered grid gives: the start pose, the curvature
// diagram every `every` grid points, and the nodes' distances from the line.
CurvatureEstimate estimate(const Reference& ref, const std::vector<Offset>& o, const Filtered& f,
                           std::size_t every) {
    const std::size_t cells = ref.x.size() - 1;
    const double h = ref.h;
    CurvatureEstimate e;
    const double nx = -std::sin(ref.hdg[0]), ny = std::cos(ref.hdg[0]);
    e.start = Pose{ref.x[0] + f.y[0] * nx, ref.y[0] + f.y[0] * ny, ref.hdg[0] + (f.y[1] - f.y[0]) / h, f.curv[0]};
    for (std::size_t k = 0; k <= cells; k += every) {
        e.s.push_back(h * static_cast<double>(k));
        e.k.push_back(f.curv[k]);
    }
    if (e.s.back() < h * static_cast<double>(cells) - 1e-9) {
        e.s.push_back(h * static_cast<double>(cells));
        e.k.push_back(f.curv[cells]);
    }
    for (const Offset& q : o) {
        std::array<std::size_t, 4> c{};
        std::array<double, 4> v{};
        interpolation_row(q.s, h, cells, c, v);
        double y = 0.0;
        for (std::size_t j = 0; j < 4; ++j) {
            y += v[j] * f.y[c[j]];
        }
        e.rss_m2 += (q.e - y) * (q.e - y);
        e.max_m = std::max(e.max_m, std::abs(q.e - y));
        e.frame.s.push_back(q.s);
        e.frame.e.push_back(q.e);
    }
    e.frame.h = h;
    e.frame.x = ref.x;
    e.frame.y = ref.y;
    e.frame.hdg = ref.hdg;
    return e;
}

} // namespace

std::optional<CurvatureEstimate> estimate_curvature(const std::vector<Point2>& p, const TrendEnds& ends,
                                                    double sigma) {
    constexpr double grid_m = 4.0, diagram_m = 12.0;
    const double length = chainage(p).back();
    if (p.size() < 5 || length < 40.0) {
        return std::nullopt;
    }
    const std::size_t cells = std::max<std::size_t>(12, static_cast<std::size_t>(std::lround(length / grid_m)));
    const double h = length / static_cast<double>(cells);
    const ChordHeading chords(p, std::max(5.0, 15.0 * sigma));
    std::vector<double> hdg(cells + 1);
    for (std::size_t k = 0; k <= cells; ++k) {
        hdg[k] = chords.at(h * static_cast<double>(k));
    }
    const double x0 = ends.start ? ends.start->x : p.front().x, y0 = ends.start ? ends.start->y : p.front().y;
    Reference ref = integrate(x0, y0, std::move(hdg), h);
    // Kink weights first, then curvature weights; l2 to start with.
    std::vector<double> weights(cells + 1, 1.0 / 1e-6);
    weights.resize(2 * (cells + 1), 1.0 / 1e-4);
    // A first, smoother pass moves the reference onto the filtered line, so
    // that the offsets the second sees are small (the curvature of a line
    // offset by y differs from its reference's by about curvature^2 * y).
    {
        const std::vector<Offset> o = offsets(p, ref);
        std::vector<double> w = weights;
        TrendFilter first(ref, o, ends, sigma);
        first.iterations = 6;
        const auto f = first.run(1e6, w);
        if (!f) {
            return std::nullopt;
        }
        ref = moved(ref, f->y, ends.start);
    }
    const std::vector<Offset> o = offsets(p, ref);
    const TrendFilter filter(ref, o, ends, sigma);
    const auto f = filter.run(3e4, weights);
    if (!f) {
        return std::nullopt;
    }
    return estimate(ref, o, *f, static_cast<std::size_t>(std::max(1.0, std::round(diagram_m / h))));
}

} // namespace railodd::geometry::fit
