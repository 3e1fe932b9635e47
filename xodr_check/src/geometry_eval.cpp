// Closed-form and quadrature evaluation of OpenDRIVE plan-view records, after
// the standard's definitions (ASAM OpenDRIVE 1.8, section 9). Written without
// railodd::geometry on purpose: a shared bug would hide itself.
#include "railodd/xodr_check/geometry_eval.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>

namespace railodd::xodr_check {

namespace {

// 10-point Gauss-Legendre on [-1, 1]: exact for polynomials of degree 19, so a
// panel over which the clothoid's heading turns by a quarter radian is
// integrated to rounding error.
constexpr std::array<double, 5> gl_x{0.1488743389816312, 0.4333953941292472, 0.6794095682990244,
                                     0.8650633666889845, 0.9739065285171717};
constexpr std::array<double, 5> gl_w{0.2955242247147529, 0.2692667193099963, 0.2190863625159820,
                                     0.1494513491505806, 0.0666713443086881};

// Composite Gauss-Legendre of f over [0, t] in n equal panels; f returns a
// pair so that cos and sin of one angle are integrated together.
template <class F>
std::array<double, 2> integrate(F f, double t, int n) {
    std::array<double, 2> sum{0.0, 0.0};
    const double h = t / n;
    for (int p = 0; p < n; ++p) {
        const double mid = (p + 0.5) * h;
        for (std::size_t i = 0; i < gl_x.size(); ++i) {
            for (double sign : {-1.0, 1.0}) {
                const auto v = f(mid + sign * 0.5 * h * gl_x[i]);
                sum[0] += gl_w[i] * v[0];
                sum[1] += gl_w[i] * v[1];
            }
        }
    }
    return {sum[0] * 0.5 * h, sum[1] * 0.5 * h};
}

int panels(double length, double max_turn_rad) {
    const double n = std::max({1.0, std::ceil(max_turn_rad / 0.25), std::ceil(length / 250.0)});
    return static_cast<int>(std::min(n, 1e6));
}

// sin(z)/z without the cancellation near zero (arcs of tiny curvature).
double sinc(double z) {
    return std::abs(z) < 1e-4 ? 1.0 - z * z / 6.0 : std::sin(z) / z;
}

Pose line_or_arc(const GeometryRecord& g, double ds, double k) {
    // Chord of length ds*sinc(k ds/2) along the mean heading: exact for both.
    const double half = 0.5 * k * ds;
    const double chord = ds * sinc(half);
    return {g.x + chord * std::cos(g.hdg + half), g.y + chord * std::sin(g.hdg + half), g.hdg + k * ds, k};
}

Pose spiral(const GeometryRecord& g, double ds) {
    const double rate = g.length > 0 ? (g.curv_end - g.curv_start) / g.length : 0.0;
    const auto heading = [&](double t) { return g.hdg + g.curv_start * t + 0.5 * rate * t * t; };
    const double max_k = std::max(std::abs(g.curv_start), std::abs(g.curv_start + rate * ds));
    const auto xy = integrate(
        [&](double t) {
            const double th = heading(t);
            return std::array<double, 2>{std::cos(th), std::sin(th)};
        },
        ds, panels(ds, max_k * ds));
    return {g.x + xy[0], g.y + xy[1], heading(ds), g.curv_start + rate * ds};
}

struct Cubic {
    double a, b, c, d;
    double at(double t) const { return a + t * (b + t * (c + t * d)); }
    double d1(double t) const { return b + t * (2 * c + 3 * d * t); }
    double d2(double t) const { return 2 * c + 6 * d * t; }
};

Pose local_to_world(const GeometryRecord& g, double u, double v, double du, double dv, double ddu, double ddv) {
    const double ch = std::cos(g.hdg);
    const double sh = std::sin(g.hdg);
    const double speed2 = du * du + dv * dv;
    const double k = speed2 > 0 ? (du * ddv - dv * ddu) / std::pow(speed2, 1.5) : 0.0;
    return {g.x + u * ch - v * sh, g.y + u * sh + v * ch, g.hdg + std::atan2(dv, du), k};
}

double poly3_arc_length(const Cubic& v, double u) {
    if (u <= 0) {
        return 0.0;
    }
    const auto r = integrate(
        [&](double t) {
            const double dv = v.d1(t);
            return std::array<double, 2>{std::sqrt(1.0 + dv * dv), 0.0};
        },
        u, panels(u, 0.0) * 4);
    return r[0];
}

// poly3 is a graph v(u); s is arc length, so u(s) is found by Newton's method
// on the arc-length integral.
Pose poly3(const GeometryRecord& g, double ds) {
    const Cubic v{g.a, g.b, g.c, g.d};
    double u = ds / std::sqrt(1.0 + v.d1(0) * v.d1(0));
    for (int it = 0; it < 60; ++it) {
        const double f = poly3_arc_length(v, u) - ds;
        const double step = f / std::sqrt(1.0 + v.d1(u) * v.d1(u));
        u -= step;
        if (std::abs(step) < 1e-13 * std::max(1.0, ds)) {
            break;
        }
    }
    return local_to_world(g, u, v.at(u), 1.0, v.d1(u), 0.0, v.d2(u));
}

Pose param_poly3(const GeometryRecord& g, double ds) {
    const Cubic u{g.au, g.bu, g.cu, g.du};
    const Cubic v{g.av, g.bv, g.cv, g.dv};
    const double p = g.normalized ? (g.length > 0 ? ds / g.length : 0.0) : ds;
    return local_to_world(g, u.at(p), v.at(p), u.d1(p), v.d1(p), u.d2(p), v.d2(p));
}

} // namespace

const char* kind_name(GeometryKind k) {
    switch (k) {
    case GeometryKind::line: return "line";
    case GeometryKind::arc: return "arc";
    case GeometryKind::spiral: return "spiral";
    case GeometryKind::poly3: return "poly3";
    case GeometryKind::param_poly3: return "paramPoly3";
    }
    return "?";
}

Pose evaluate(const GeometryRecord& g, double ds) {
    switch (g.kind) {
    case GeometryKind::line: return line_or_arc(g, ds, 0.0);
    case GeometryKind::arc: return line_or_arc(g, ds, g.curvature);
    case GeometryKind::spiral: return spiral(g, ds);
    case GeometryKind::poly3: return poly3(g, ds);
    case GeometryKind::param_poly3: return param_poly3(g, ds);
    }
    return {};
}

double curve_length(const GeometryRecord& g) {
    if (g.kind != GeometryKind::param_poly3) {
        return g.length;
    }
    const Cubic u{g.au, g.bu, g.cu, g.du};
    const Cubic v{g.av, g.bv, g.cv, g.dv};
    const double p_end = g.normalized ? 1.0 : g.length;
    const auto r = integrate(
        [&](double p) {
            return std::array<double, 2>{std::hypot(u.d1(p), v.d1(p)), 0.0};
        },
        p_end, panels(g.length, 0.0) * 4);
    return r[0];
}

double angle_diff(double a, double b) {
    constexpr double two_pi = 2.0 * std::numbers::pi;
    double d = std::fmod(a - b, two_pi);
    if (d <= -std::numbers::pi) {
        d += two_pi;
    } else if (d > std::numbers::pi) {
        d -= two_pi;
    }
    return d;
}

} // namespace railodd::xodr_check
