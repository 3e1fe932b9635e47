// Evaluation of a single planView primitive.
#include "railodd/geometry/alignment.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <sstream>
#include <stdexcept>
#include <utility>

namespace railodd::geometry {

namespace {

// Heading change allowed per sub-interval of a spiral: keeps the phase of the
// series below (|a| + |b| <= 0.45) small enough that 20 terms reach 1e-18.
constexpr double max_sub_turn = 0.3; // rad

// The integral over [0, 1] of exp(i (a x + b x^2)), by the power series of
// the exponential: (a x + b x^2)^n / n! is a polynomial with terms x^n..x^2n,
// integrated exactly. One sub-interval then costs one sincos (its start
// heading) instead of the eight of a Gauss-Legendre rule, which made clothoid
// evaluation nine tenths of the fitting time.
constexpr int max_terms = 20;

constexpr std::array<double, 2 * max_terms + 2> reciprocals() {
    std::array<double, 2 * max_terms + 2> r{};
    for (std::size_t k = 0; k < r.size(); ++k) {
        r[k] = 1.0 / static_cast<double>(k + 1);
    }
    return r;
}
constexpr std::array<double, 2 * max_terms + 2> inv = reciprocals(); // inv[k] = 1 / (k + 1)

std::pair<double, double> unit_phase_integral(double a, double b) {
    std::array<double, 2 * max_terms + 2> q{}; // coefficients of (a x + b x^2)^n / n!
    q[0] = 1.0;
    double re = 1.0, im = 0.0;
    for (std::size_t n = 1; n <= max_terms; ++n) {
        // Highest power first, so that q[k - 1] and q[k - 2] still hold term n - 1.
        double integral = 0.0;
        for (std::size_t k = 2 * n; k >= n + 1; --k) {
            q[k] = (a * q[k - 1] + b * q[k - 2]) * inv[n - 1];
            integral += q[k] * inv[k];
        }
        q[n] = a * q[n - 1] * inv[n - 1]; // term n - 1 has no x^(n - 2)
        integral += q[n] * inv[n];
        q[n - 1] = 0.0;
        switch (n % 4) { // times i^n
        case 0: re += integral; break;
        case 1: im += integral; break;
        case 2: re -= integral; break;
        default: im -= integral; break;
        }
        if (std::abs(integral) < 1e-16) {
            break;
        }
    }
    return {re, im};
}

// 2 sin(a/2) / a, the chord-to-arc ratio, without cancellation near a = 0.
double chord_ratio(double a) {
    if (std::abs(a) < 1e-4) {
        return 1.0 - a * a / 24.0;
    }
    return 2.0 * std::sin(0.5 * a) / a;
}

// An arc (or line) as a chord: direction hdg + turn/2 and length ds * ratio.
// Unlike (sin(h + k ds) - sin h) / k this stays exact as k tends to zero.
Pose evaluate_constant(const Pose& start, double curvature, double ds) {
    const double turn = curvature * ds;
    const double chord = ds * chord_ratio(turn);
    const double mid = start.hdg + 0.5 * turn;
    return {start.x + chord * std::cos(mid), start.y + chord * std::sin(mid), start.hdg + turn,
            curvature};
}

Pose evaluate_spiral(const Pose& start, const Primitive& p, double ds) {
    const double rate = (p.curv_end - p.curv_start) / p.length; // dk/ds
    const double k_at_ds = p.curv_start + rate * ds;
    auto heading = [&](double t) { return start.hdg + t * (p.curv_start + 0.5 * rate * t); };

    const double max_curv = std::max(std::abs(p.curv_start), std::abs(k_at_ds));
    const int n = std::max(1, static_cast<int>(std::ceil(max_curv * ds / max_sub_turn)));
    const double h = ds / n;

    double x = start.x;
    double y = start.y;
    for (int i = 0; i < n; ++i) {
        const double t0 = i * h;
        // Local phase over the sub-interval, in units of its length.
        const auto [re, im] = unit_phase_integral((p.curv_start + rate * t0) * h, 0.5 * rate * h * h);
        const double th = heading(t0);
        const double c = std::cos(th), s = std::sin(th);
        x += h * (c * re - s * im);
        y += h * (s * re + c * im);
    }
    return {x, y, heading(ds), k_at_ds};
}

} // namespace

Primitive make_line(double length) { return {PrimitiveKind::line, length, 0.0, 0.0}; }

Primitive make_arc(double length, double curvature) {
    return {PrimitiveKind::arc, length, curvature, curvature};
}

Primitive make_spiral(double length, double curv_start, double curv_end) {
    return {PrimitiveKind::spiral, length, curv_start, curv_end};
}

const char* to_string(PrimitiveKind kind) {
    switch (kind) {
    case PrimitiveKind::line: return "line";
    case PrimitiveKind::arc: return "arc";
    case PrimitiveKind::spiral: return "spiral";
    }
    return "unknown";
}

void validate(const Primitive& p, std::size_t index) {
    auto fail = [&](const std::string& problem) {
        std::ostringstream msg;
        msg << "primitive " << index << " (" << to_string(p.kind) << ", length " << p.length
            << ", curvature " << p.curv_start << " -> " << p.curv_end << "): " << problem;
        throw std::invalid_argument(msg.str());
    };
    if (!std::isfinite(p.length) || p.length < 0.0) {
        fail("length must be finite and non-negative");
    }
    if (!std::isfinite(p.curv_start) || !std::isfinite(p.curv_end)) {
        fail("curvature must be finite");
    }
    if (p.kind == PrimitiveKind::line && (p.curv_start != 0.0 || p.curv_end != 0.0)) {
        fail("a line has zero curvature");
    }
    if (p.kind == PrimitiveKind::arc && p.curv_start != p.curv_end) {
        fail("an arc has constant curvature");
    }
}

Pose evaluate(const Pose& start, const Primitive& p, double ds) {
    ds = std::clamp(ds, 0.0, p.length);
    if (p.curv_start == p.curv_end || p.length <= 0.0) {
        return evaluate_constant(start, p.curv_start, ds);
    }
    return evaluate_spiral(start, p, ds);
}

} // namespace railodd::geometry
