// Evaluation of a single planView primitive.
#include "railodd/geometry/alignment.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <sstream>
#include <stdexcept>

namespace railodd::geometry {

namespace {

// Nodes and weights of the 8-point Gauss-Legendre rule on [-1, 1]; exact for
// polynomials up to degree 15, so with sub-intervals whose heading change stays
// small the truncation error is far below double rounding.
constexpr std::array<double, 4> gl_nodes{0.1834346424956498, 0.5255324099163290,
                                         0.7966664774136267, 0.9602898564975363};
constexpr std::array<double, 4> gl_weights{0.3626837833783620, 0.3137066458778873,
                                           0.2223810344533745, 0.1012285362903763};

constexpr double max_sub_length = 10.0; // m
constexpr double max_sub_turn = 0.25;   // rad of heading change per sub-interval

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
    const auto by_length = static_cast<int>(std::ceil(ds / max_sub_length));
    const auto by_turn = static_cast<int>(std::ceil(max_curv * ds / max_sub_turn));
    const int n = std::max({1, by_length, by_turn});
    const double h = ds / n;

    double sx = 0.0;
    double sy = 0.0;
    for (int i = 0; i < n; ++i) {
        const double mid = (i + 0.5) * h;
        for (std::size_t j = 0; j < gl_nodes.size(); ++j) {
            const double d = 0.5 * h * gl_nodes[j];
            const double a = heading(mid - d);
            const double b = heading(mid + d);
            sx += gl_weights[j] * (std::cos(a) + std::cos(b));
            sy += gl_weights[j] * (std::sin(a) + std::sin(b));
        }
    }
    return {start.x + 0.5 * h * sx, start.y + 0.5 * h * sy, heading(ds), k_at_ds};
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
