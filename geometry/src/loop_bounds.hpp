#pragma once
// The measures behind loops_back (fit_alignment.hpp), apart from Alignment:
// a least-squares solve tests its curve against them after every step.
#include <cmath>
#include <cstddef>
#include <numbers>

namespace railodd::geometry {

// Total turning (sum of |heading change|) of a piece whose curvature goes
// linearly from k0 to k1 over `length`.
inline double piece_turning(double k0, double k1, double length) {
    if (k0 * k1 >= 0.0) {
        return 0.5 * std::abs(k0 + k1) * length;
    }
    // Curvature crosses zero inside: two triangles of the diagram.
    const double a0 = std::abs(k0), a1 = std::abs(k1);
    return 0.5 * (a0 * a0 + a1 * a1) / (a0 + a1) * length;
}

// A centreline fitted to nodes is about as long as the polyline through them
// and turns no more than it (mapping noise only adds turning to the
// polyline), so more than 5 % + 10 m of extra length or a full extra turn
// means a loop.
class LoopBounds {
public:
    // `points`: anything indexable with .x and .y members, in track order.
    template <class Points>
    explicit LoopBounds(const Points& points) {
        for (std::size_t i = 1; i < points.size(); ++i) {
            length_ += std::hypot(points[i].x - points[i - 1].x, points[i].y - points[i - 1].y);
            if (i + 1 < points.size()) {
                const double a = std::atan2(points[i].y - points[i - 1].y, points[i].x - points[i - 1].x);
                const double b = std::atan2(points[i + 1].y - points[i].y, points[i + 1].x - points[i].x);
                turning_ += std::abs(std::remainder(b - a, 2 * std::numbers::pi));
            }
        }
    }

    bool exceeded(double curve_length, double curve_turning) const {
        return curve_length > 1.05 * length_ + 10.0 || curve_turning > turning_ + 2 * std::numbers::pi;
    }

private:
    double length_ = 0.0;
    double turning_ = 0.0;
};

} // namespace railodd::geometry
