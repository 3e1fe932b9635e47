#include "reference_line.hpp"

#include "band_matrix.hpp"
#include "chord_heading.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <stdexcept>

namespace railodd::geometry::fit {

namespace {

double unwrap_near(double a, double ref) { return a + 2 * std::numbers::pi * std::round((ref - a) / (2 * std::numbers::pi)); }

} // namespace

ReferenceLine::ReferenceLine(std::vector<double> x, std::vector<double> y) : x_(std::move(x)), y_(std::move(y)) {
    if (x_.size() < 2 || x_.size() != y_.size()) {
        throw std::invalid_argument("reference line: fewer than two vertices");
    }
    s_.assign(x_.size(), 0.0);
    hdg_.assign(x_.size(), 0.0);
    for (std::size_t k = 0; k + 1 < x_.size(); ++k) {
        const double dx = x_[k + 1] - x_[k], dy = y_[k + 1] - y_[k];
        s_[k + 1] = s_[k] + std::hypot(dx, dy);
        const double h = std::atan2(dy, dx);
        hdg_[k] = k == 0 ? h : unwrap_near(h, hdg_[k - 1]);
    }
    hdg_.back() = hdg_[hdg_.size() - 2];
    phi_.assign(x_.size(), 0.0);
    for (std::size_t k = 0; k + 1 < x_.size(); ++k) {
        phi_[k + 1] = phi_[k] + (hdg_[k] - hdg_[0]) * (s_[k + 1] - s_[k]);
    }
}

std::size_t ReferenceLine::segment(double s) const {
    const auto it = std::upper_bound(s_.begin(), s_.end(), s);
    const std::size_t k = it == s_.begin() ? 0 : static_cast<std::size_t>(it - s_.begin()) - 1;
    return std::min(k, s_.size() - 2);
}

Pose ReferenceLine::at(double s) const {
    const std::size_t k = segment(s);
    const double d = s - s_[k];
    return {x_[k] + d * std::cos(hdg_[k]), y_[k] + d * std::sin(hdg_[k]), hdg_[k], 0.0};
}

double ReferenceLine::developed(double s) const {
    const std::size_t k = segment(s);
    return phi_[k] + (hdg_[k] - hdg_[0]) * (s - s_[k]);
}

std::pair<double, double> ReferenceLine::project(double px, double py, std::size_t& hint, double reach_m) const {
    const std::size_t last = s_.size() - 2;
    const std::size_t lo = segment(s_[std::min(hint, last)] - reach_m);
    const std::size_t hi = segment(s_[std::min(hint, last)] + reach_m);
    double best = std::numeric_limits<double>::infinity();
    std::pair<double, double> out{0.0, 0.0};
    for (std::size_t k = lo; k <= hi; ++k) {
        const double len = s_[k + 1] - s_[k];
        const double c = std::cos(hdg_[k]), sn = std::sin(hdg_[k]);
        const double qx = px - x_[k], qy = py - y_[k];
        double u = qx * c + qy * sn;
        u = std::clamp(u, k == 0 ? -std::numeric_limits<double>::infinity() : 0.0,
                       k == last ? std::numeric_limits<double>::infinity() : len);
        const double ex = qx - u * c, ey = qy - u * sn;
        const double d2 = ex * ex + ey * ey;
        if (d2 < best) {
            best = d2;
            hint = k;
            out = {s_[k] + u, c * qy - sn * qx};
        }
    }
    return out;
}

ReferenceLine smooth_reference(const std::vector<Point2>& p, double bandwidth_m, double h) {
    const std::vector<double> tau = chainage(p);
    const double total = std::max(tau.back(), h);
    const auto cells = static_cast<std::size_t>(std::max(1.0, std::ceil(total / h)));
    const double step = total / static_cast<double>(cells);
    const std::size_t n = cells + 1;
    BandMatrix A(n);
    std::vector<double> bx(n, 0.0), by(n, 0.0), unused(n, 0.0);
    for (std::size_t i = 0; i < p.size(); ++i) {
        const double f = std::clamp(tau[i] / step, 0.0, static_cast<double>(cells));
        const std::size_t j = std::min(static_cast<std::size_t>(f), cells - 1);
        const double a = f - static_cast<double>(j);
        A.add<2>({j, j + 1}, {1.0 - a, a}, 1.0, p[i].x, bx);
        by[j] += (1.0 - a) * p[i].y;
        by[j + 1] += a * p[i].y;
    }
    // lambda * integral of the squared second derivative: an equivalent
    // kernel of half-width bandwidth at the chain's mean node density.
    const double density = static_cast<double>(p.size()) / total;
    const double lambda = std::pow(bandwidth_m, 4) * density / (step * step * step);
    for (std::size_t k = 1; k + 1 < n; ++k) {
        A.add<3>({k - 1, k, k + 1}, {1.0, -2.0, 1.0}, lambda, 0.0, unused);
    }
    A.add_diagonal(1e-9);
    BandMatrix B = A;
    if (!A.solve(bx) || !B.solve(by)) {
        throw std::runtime_error("reference line: the smoothing system is singular");
    }
    return ReferenceLine(std::move(bx), std::move(by));
}

ReferenceLine alignment_reference(const Alignment& a, double h) {
    const std::vector<Pose> starts = primitive_starts(a);
    std::vector<double> x{a.start.x}, y{a.start.y};
    for (std::size_t i = 0; i < a.primitives.size(); ++i) {
        const Primitive& q = a.primitives[i];
        const auto steps = static_cast<std::size_t>(std::ceil(q.length / h));
        for (std::size_t k = 1; k <= steps; ++k) {
            const Pose e = evaluate(starts[i], q, q.length * static_cast<double>(k) / static_cast<double>(steps));
            x.push_back(e.x);
            y.push_back(e.y);
        }
    }
    if (x.size() < 2) {
        x.push_back(a.start.x + std::cos(a.start.hdg));
        y.push_back(a.start.y + std::sin(a.start.hdg));
    }
    return ReferenceLine(std::move(x), std::move(y));
}

std::vector<FrameNode> develop(const ReferenceLine& r, const std::vector<Point2>& p) {
    std::vector<FrameNode> out;
    out.reserve(p.size());
    std::size_t hint = 0;
    for (std::size_t i = 0; i < p.size(); ++i) {
        const double step = i > 0 ? std::hypot(p[i].x - p[i - 1].x, p[i].y - p[i - 1].y) : 0.0;
        const auto [t, e] = r.project(p[i].x, p[i].y, hint, 1.5 * step + 20.0);
        out.push_back({t, e + r.developed(t), 1.0});
    }
    return out;
}

FrameState frame_state(const ReferenceLine& r, const Pose& pose, double& t) {
    constexpr double reach_m = 50.0;
    std::size_t hint = r.segment(t);
    const auto [s, e] = r.project(pose.x, pose.y, hint, reach_m);
    t = s;
    const double rel = unwrap_near(pose.hdg, r.at(s).hdg) - r.start_heading();
    return {e + r.developed(s), rel, pose.curvature};
}

namespace {

// Transition j's ends take the curvature of what they meet, and it keeps its
// turn in the frame: a turn lost is a heading error for all that follows
// (0.002 rad on one transition of a sparse truth route at 2 m, seed 1146,
// put the chain's end 14 m off). Its length keeps it where its curvature
// does not nearly cancel along it; across an inflection of a reverse curve
// the arc after it does.
void meet_neighbours(std::vector<FrameElement>& m, std::size_t j, double turn) {
    if (j > 0 && m[j - 1].kind != ElementKind::transition) {
        m[j].k0 = m[j - 1].k1;
    }
    if (j + 1 < m.size() && m[j + 1].kind != ElementKind::transition) {
        m[j].k1 = m[j + 1].k0;
    }
    const double mean = 0.5 * (m[j].k0 + m[j].k1), len = m[j].s1 - m[j].s0;
    if (std::abs(mean) > 0.25 * (std::abs(m[j].k0) + std::abs(m[j].k1)) && std::abs(mean) > 1e-9) {
        m[j].s1 = m[j].s0 + std::clamp(turn / mean, 0.5 * len, 2.0 * len);
    } else if (j + 1 < m.size() && m[j + 1].kind == ElementKind::arc && std::abs(m[j + 1].k0) > 1e-9) {
        const double arc = m[j + 1].s1 - m[j + 1].s0;
        m[j + 1].s1 = m[j + 1].s0 + std::max(0.5 * arc, arc + (turn - mean * len) / m[j + 1].k0);
    }
}

} // namespace

std::vector<FrameElement> on_map(const ReferenceLine& r, const FrameDesign& d) {
    std::vector<FrameElement> m = d.elements;
    FrameState at = d.start;
    for (FrameElement& el : m) {
        const FrameState from = at;
        const auto offset = [&](double t) {
            const FrameState x = state_along(el, from, t - el.s0);
            return std::pair<double, double>{x.z - r.developed(t), x.dz - (r.heading(t) - r.start_heading())};
        };
        const double len = el.s1 - el.s0;
        const double c = len > 1e-9 ? std::clamp(r.offset_length(el.s0, el.s1, offset) / len, 0.5, 2.0) : 1.0;
        at = state_along(el, from, len);
        el.s1 = el.s0 + c * len;
        el.k0 /= c;
        el.k1 /= c;
    }
    for (std::size_t j = 0; j < m.size(); ++j) {
        if (m[j].kind == ElementKind::transition) {
            meet_neighbours(m, j, 0.5 * (d.elements[j].k0 + d.elements[j].k1) * (d.elements[j].s1 - d.elements[j].s0));
        }
    }
    for (std::size_t j = 1; j < m.size(); ++j) {
        const double len = m[j].s1 - m[j].s0;
        m[j].s0 = m[j - 1].s1;
        m[j].s1 = m[j].s0 + len;
    }
    return m;
}

Alignment to_alignment(const ReferenceLine& r, const FrameDesign& d) {
    Alignment a;
    const double s0 = d.elements.front().s0;
    const Pose p = r.at(s0);
    const double e = d.start.z - r.developed(s0);
    const std::vector<FrameElement> m = on_map(r, d);
    a.start = {p.x - e * std::sin(p.hdg), p.y + e * std::cos(p.hdg), r.start_heading() + d.start.dz, m.front().k0};
    for (const FrameElement& el : m) {
        const double len = el.s1 - el.s0;
        if (!(len > 1e-9)) {
            continue;
        }
        switch (el.kind) {
        case ElementKind::line:
            a.primitives.push_back(make_line(len));
            break;
        case ElementKind::arc:
            a.primitives.push_back(make_arc(len, 0.5 * (el.k0 + el.k1)));
            break;
        case ElementKind::transition:
            a.primitives.push_back(make_spiral(len, el.k0, el.k1));
            break;
        }
    }
    return a;
}

} // namespace railodd::geometry::fit
