#include "road_junctions.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>

namespace railodd::xodr::roads {

namespace {

constexpr double pi = std::numbers::pi;

// Gauss-Legendre nodes and weights on [-1, 1], 8 points.
constexpr std::array<double, 4> gl_x{0.1834346424956498, 0.5255324099163290, 0.7966664774136267, 0.9602898564975363};
constexpr std::array<double, 4> gl_w{0.3626837833783620, 0.3137066238953742, 0.2223810344533745, 0.1012285362903763};

struct Cubic {
    std::array<double, 4> u{}; // in t in [0, 1]
    std::array<double, 4> v{};
};

double speed(const Cubic& c, double t) {
    const double du = c.u[1] + t * (2.0 * c.u[2] + 3.0 * t * c.u[3]);
    const double dv = c.v[1] + t * (2.0 * c.v[2] + 3.0 * t * c.v[3]);
    return std::hypot(du, dv);
}

// Arc length over t in [0, 1]: composite 8-point Gauss-Legendre on 64 panels
// (the speed of a cubic is smooth; the error is far below 1e-9 m).
double arc_length(const Cubic& c) {
    constexpr int panels = 64;
    double total = 0.0;
    for (int k = 0; k < panels; ++k) {
        const double a = static_cast<double>(k) / panels;
        const double h = 0.5 / panels;
        const double mid = a + h;
        for (std::size_t i = 0; i < gl_x.size(); ++i) {
            total += h * gl_w[i] * (speed(c, mid - h * gl_x[i]) + speed(c, mid + h * gl_x[i]));
        }
    }
    return total;
}

} // namespace

std::vector<double> cut_back(const std::vector<LegShape>& legs, double min_clearance_m) {
    // Below 15 degrees between legs the requirement is held at its 15 degree value.
    const double min_sin = std::sin(15.0 * pi / 180.0);
    std::vector<double> out;
    for (std::size_t i = 0; i < legs.size(); ++i) {
        double need = min_clearance_m;
        for (std::size_t j = 0; j < legs.size(); ++j) {
            if (j == i) {
                continue;
            }
            const double theta = std::abs(std::remainder(legs[i].direction - legs[j].direction, 2.0 * pi));
            // Leg i's end cross-section at distance d spans +-hw_i across leg i;
            // its nearest point to leg j's centreline is d sin(theta) - hw_i cos(theta)
            // away, which must reach hw_j. Beyond a right angle leg i leaves leg
            // j's carriageway behind; hw_j still keeps the corner clear.
            const double d = theta < 0.5 * pi ? (legs[j].half_width + legs[i].half_width * std::cos(theta)) /
                                                    std::max(std::sin(theta), min_sin)
                                              : legs[j].half_width;
            need = std::max(need, d);
        }
        out.push_back(std::min(need, legs[i].length / 3.0));
    }
    return out;
}

PlanGeometry connecting_geometry(const geometry::Pose& from, const geometry::Pose& to) {
    PlanGeometry g;
    g.s = 0.0;
    g.x = from.x;
    g.y = from.y;
    g.hdg = from.hdg;
    const double cs = std::cos(from.hdg);
    const double sn = std::sin(from.hdg);
    const double dx = to.x - from.x;
    const double dy = to.y - from.y;
    const double U = dx * cs + dy * sn;  // end point in the start's frame
    const double V = -dx * sn + dy * cs;
    const double dh = std::remainder(to.hdg - from.hdg, 2.0 * pi);
    const double chord = std::hypot(U, V);
    if (U > 0.0 && std::abs(V) <= 1e-10 && std::abs(dh) * U <= 1e-10) {
        g.kind = PlanGeometry::Kind::line;
        g.length = U;
        return g;
    }
    // Tangent length of the cubic that best matches a circular arc turning
    // by dh over the chord (4 tan(dh/4) R, with R from the chord): the chord
    // for a straight, twice the chord for a half turn.
    const double half = 0.5 * std::abs(dh);
    const double k = half < 1e-6 ? chord : 2.0 * chord * std::tan(0.5 * half) / std::sin(half);
    const double c1 = std::cos(dh);
    const double s1 = std::sin(dh);
    Cubic c;
    // P(t) = P0 + T0 t + (3(P1-P0) - 2T0 - T1) t^2 + (2(P0-P1) + T0 + T1) t^3
    c.u = {0.0, k, 3.0 * U - 2.0 * k - k * c1, -2.0 * U + k + k * c1};
    c.v = {0.0, 0.0, 3.0 * V - k * s1, -2.0 * V + k * s1};
    const double length = arc_length(c);
    g.kind = PlanGeometry::Kind::param_poly3;
    g.length = length;
    if (length <= 0.0) {
        g.kind = PlanGeometry::Kind::line; // the two poses coincide
        g.length = 0.0;
        return g;
    }
    // p = t * length
    double scale = 1.0;
    for (std::size_t i = 0; i < 4; ++i) {
        g.u[i] = c.u[i] * scale;
        g.v[i] = c.v[i] * scale;
        scale /= length;
    }
    return g;
}

geometry::Pose evaluate_connecting(const PlanGeometry& g, double p) {
    geometry::Pose out;
    double u = 0.0;
    double v = 0.0;
    double du = 1.0;
    double dv = 0.0;
    if (g.kind == PlanGeometry::Kind::param_poly3) {
        u = g.u[0] + p * (g.u[1] + p * (g.u[2] + p * g.u[3]));
        v = g.v[0] + p * (g.v[1] + p * (g.v[2] + p * g.v[3]));
        du = g.u[1] + p * (2.0 * g.u[2] + 3.0 * p * g.u[3]);
        dv = g.v[1] + p * (2.0 * g.v[2] + 3.0 * p * g.v[3]);
    } else {
        u = p;
    }
    const double cs = std::cos(g.hdg);
    const double sn = std::sin(g.hdg);
    out.x = g.x + u * cs - v * sn;
    out.y = g.y + u * sn + v * cs;
    out.hdg = g.hdg + std::atan2(dv, du);
    return out;
}

} // namespace railodd::xodr::roads
