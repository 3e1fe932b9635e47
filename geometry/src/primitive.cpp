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
// series small (|a| + |b| <= 0.45) so that a dozen terms reach 1e-17.
constexpr double max_sub_turn = 0.3; // rad

// The integral over [0, 1] of exp(i (a x + b x^2)), less the phase at x = 1/2
// (the caller turns by the heading at the sub-interval's middle). About the
// middle, x = (1 + z) / 2, the integrand is exp(i (al z + be z^2)) with
// al = (a + b) / 2 and be = b / 4; its Taylor coefficients follow from
// f' = i (al + 2 be z) f as d[k+1] = i (al d[k] + 2 be d[k-1]) / (k + 1),
// and over z in [-1, 1] only the even ones integrate to non-zero. One
// recurrence step per term (not the n^2 products of expanding (a x + b x^2)^n)
// and half the terms of a series about x = 0: clothoid evaluation was a third
// of the fitting time.
constexpr int max_terms = 40;

constexpr std::array<double, max_terms + 2> reciprocals() {
    std::array<double, max_terms + 2> r{};
    for (std::size_t k = 0; k < r.size(); ++k) {
        r[k] = 1.0 / static_cast<double>(k + 1);
    }
    return r;
}
constexpr std::array<double, max_terms + 2> inv = reciprocals(); // inv[k] = 1 / (k + 1)

std::pair<double, double> unit_phase_integral_about_middle(double a, double b) {
    const double al = 0.5 * (a + b);
    const double be2 = 0.5 * b; // 2 be
    double pr = 1.0, pi = 0.0;  // d[k - 1]
    double cr = 0.0, ci = al;   // d[k], k = 1
    double re = 1.0, im = 0.0;
    for (std::size_t k = 1; k < max_terms; k += 2) {
        // d[k + 1], even: it integrates to d[k + 1] / (k + 2) over [-1, 1] / 2.
        double nr = -(al * ci + be2 * pi) * inv[k];
        double ni = (al * cr + be2 * pr) * inv[k];
        re += nr * inv[k + 1];
        im += ni * inv[k + 1];
        pr = cr;
        pi = ci;
        cr = nr;
        ci = ni;
        // d[k + 2], odd: integrates to zero but feeds the next even term.
        nr = -(al * ci + be2 * pi) * inv[k + 1];
        ni = (al * cr + be2 * pr) * inv[k + 1];
        pr = cr;
        pi = ci;
        cr = nr;
        ci = ni;
        if (std::abs(pr) + std::abs(pi) + std::abs(cr) + std::abs(ci) < 1e-17) {
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
        const auto [re, im] = unit_phase_integral_about_middle((p.curv_start + rate * t0) * h, 0.5 * rate * h * h);
        const double th = heading(t0 + 0.5 * h);
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
