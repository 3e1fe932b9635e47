// Cant per primitive: arcs carry it, spirals ramp it, lines have none.
// Internally the cant is signed by the curve's side (positive on left
// curves, like curvature) so ramps between opposite curves pass through zero
// by plain linear interpolation.
#include "railodd/geometry/cant.hpp"

#include <algorithm>
#include <cmath>

namespace railodd::geometry {

namespace {

constexpr double gravity = 9.81; // m/s^2

struct SignedCant {
    double value = 0.0; // m, positive on left curves
    bool estimated = false;
};

double overlap(const CantTagSpan& t, double a, double b) {
    return std::max(0.0, std::min(t.s_end, b) - std::max(t.s_start, a));
}

bool usable(const std::optional<double>& v) { return v && std::isfinite(*v) && *v >= 0.0; }

// Mapped cant (mm) of the curve over [a, b]: from the span covering most of
// it, at least half; a point (a == b) takes the first span containing it.
std::optional<double> tagged_cant(const std::vector<CantTagSpan>& tags, double a, double b) {
    std::optional<double> best;
    double best_cover = 0.0;
    for (const auto& t : tags) {
        if (!usable(t.cant_mm)) {
            continue;
        }
        if (a == b) {
            if (t.s_start <= a && a <= t.s_end) {
                return t.cant_mm;
            }
            continue;
        }
        const double cover = overlap(t, a, b);
        if (cover > best_cover) {
            best_cover = cover;
            best = t.cant_mm;
        }
    }
    return a == b || best_cover >= 0.5 * (b - a) ? best : std::nullopt;
}

// Highest maxspeed (km/h) anywhere on [a, b]: the curve has to be canted for
// the fastest train allowed on it.
std::optional<double> top_speed(const std::vector<CantTagSpan>& tags, double a, double b) {
    std::optional<double> top;
    for (const auto& t : tags) {
        const bool touches = a == b ? (t.s_start <= a && a <= t.s_end) : overlap(t, a, b) > 0.0;
        if (touches && t.speed_kmh && std::isfinite(*t.speed_kmh) && *t.speed_kmh > 0.0) {
            top = std::max(top.value_or(0.0), *t.speed_kmh);
        }
    }
    return top;
}

// Cant of a curve of the given curvature over [a, b].
SignedCant curve_cant(const std::vector<CantTagSpan>& tags, const CantOptions& o, double a, double b,
                      double curvature) {
    if (curvature == 0.0) {
        return {};
    }
    const double side = curvature > 0.0 ? 1.0 : -1.0;
    if (const auto mm = tagged_cant(tags, a, b)) {
        return {side * *mm / 1000.0, false};
    }
    if (!o.estimate) {
        return {};
    }
    const auto kmh = top_speed(tags, a, b);
    if (!kmh) {
        return {};
    }
    const double v = *kmh / 3.6;
    const double equilibrium = o.rail_spacing_m * v * v * std::abs(curvature) / gravity;
    return {side * std::min(equilibrium, o.cap_m), true};
}

struct Ends {
    SignedCant start;
    SignedCant end;
};

// Signed cant at both ends of each primitive. A spiral takes its neighbours'
// cants; where its neighbour is another spiral (or none), the joint is
// treated as a zero-length arc of the joint's curvature.
std::vector<Ends> primitive_cants(const Alignment& al, const std::vector<CantTagSpan>& tags, const CantOptions& o) {
    const auto& p = al.primitives;
    const auto s0 = primitive_s(al);
    std::vector<Ends> ends(p.size());
    for (std::size_t i = 0; i < p.size(); ++i) {
        if (p[i].kind == PrimitiveKind::arc) {
            const SignedCant c = curve_cant(tags, o, s0[i], s0[i] + p[i].length, p[i].curv_start);
            ends[i] = {c, c};
        }
    }
    for (std::size_t i = 0; i < p.size(); ++i) {
        if (p[i].kind != PrimitiveKind::spiral) {
            continue;
        }
        const double s_end = s0[i] + p[i].length;
        ends[i].start = i > 0 && p[i - 1].kind != PrimitiveKind::spiral
                            ? ends[i - 1].end
                            : curve_cant(tags, o, s0[i], s0[i], p[i].curv_start);
        ends[i].end = i + 1 < p.size() && p[i + 1].kind != PrimitiveKind::spiral
                          ? ends[i + 1].start
                          : curve_cant(tags, o, s_end, s_end, p[i].curv_end);
    }
    return ends;
}

void append(std::vector<CantStretch>& out, double s0, double s1, double c0, double c1, bool estimated) {
    if (s1 > s0 && (c0 != 0.0 || c1 != 0.0)) {
        const bool left = c0 + c1 > 0.0;
        out.push_back({s0, s1, std::abs(c0), std::abs(c1), estimated, left});
    }
}

double value_in(const CantStretch& c, double s) {
    const double t = c.s_end > c.s_start ? (s - c.s_start) / (c.s_end - c.s_start) : 0.0;
    return c.cant_start_m + t * (c.cant_end_m - c.cant_start_m);
}

} // namespace

std::vector<CantStretch> compute_cant(const Alignment& alignment, const std::vector<CantTagSpan>& tags,
                                      const CantOptions& options) {
    const auto ends = primitive_cants(alignment, tags, options);
    const auto s0 = primitive_s(alignment);
    std::vector<CantStretch> out;
    for (std::size_t i = 0; i < ends.size(); ++i) {
        const double a = s0[i];
        const double b = a + alignment.primitives[i].length;
        const double c0 = ends[i].start.value;
        const double c1 = ends[i].end.value;
        const bool estimated = ends[i].start.estimated || ends[i].end.estimated;
        if (c0 * c1 < 0.0) {
            // Reverse curve: the ramp changes side where it passes through zero.
            const double at = a + (b - a) * c0 / (c0 - c1);
            append(out, a, at, c0, 0.0, estimated);
            append(out, at, b, 0.0, c1, estimated);
        } else {
            append(out, a, b, c0, c1, estimated);
        }
    }
    return out;
}

double superelevation_rad(double cant_m, double rail_spacing_m) {
    return std::asin(std::clamp(cant_m / rail_spacing_m, -1.0, 1.0));
}

double cant_at(const std::vector<CantStretch>& stretches, double s) {
    for (const auto& c : stretches) {
        if (s >= c.s_start && s <= c.s_end) {
            return value_in(c, s);
        }
    }
    return 0.0;
}

double superelevation_at(const std::vector<CantStretch>& stretches, double s, double rail_spacing_m) {
    for (const auto& c : stretches) {
        if (s >= c.s_start && s <= c.s_end) {
            const double roll = superelevation_rad(value_in(c, s), rail_spacing_m);
            return c.left_curve ? -roll : roll;
        }
    }
    return 0.0;
}

} // namespace railodd::geometry
