#include "play_geometry.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>

namespace railodd::scenario::play {

Path::Path(const std::vector<Sample>& ego) {
    for (const Sample& s : ego) {
        if (!std::isfinite(s.x) || !std::isfinite(s.y)) {
            continue;
        }
        if (!x_.empty() && std::hypot(s.x - x_.back(), s.y - y_.back()) < 0.5) {
            continue;
        }
        c_.push_back(c_.empty() ? 0.0 : c_.back() + std::hypot(s.x - x_.back(), s.y - y_.back()));
        x_.push_back(s.x);
        y_.push_back(s.y);
    }
}

Path::Foot Path::project(double x, double y) const {
    Foot best{0.0, std::numeric_limits<double>::infinity()};
    for (std::size_t i = 0; i + 1 < x_.size(); ++i) {
        const double dx = x_[i + 1] - x_[i], dy = y_[i + 1] - y_[i];
        const double len2 = dx * dx + dy * dy;
        const double u = std::clamp(((x - x_[i]) * dx + (y - y_[i]) * dy) / len2, 0.0, 1.0);
        const double d = std::hypot(x - x_[i] - u * dx, y - y_[i] - u * dy);
        if (d < best.distance) {
            best = {c_[i] + u * (c_[i + 1] - c_[i]), d};
        }
    }
    return best;
}

namespace {

double point_segment(double px, double py, double ax, double ay, double bx, double by) {
    const double dx = bx - ax, dy = by - ay;
    const double len2 = dx * dx + dy * dy;
    const double u = len2 > 0.0 ? std::clamp(((px - ax) * dx + (py - ay) * dy) / len2, 0.0, 1.0) : 0.0;
    return std::hypot(px - ax - u * dx, py - ay - u * dy);
}

} // namespace

double Path::sight_back(double chainage, double corridor, bool& limited) const {
    limited = false;
    if (empty()) {
        return 0.0;
    }
    // The target point, and the last polyline point before it.
    const auto upper = std::upper_bound(c_.begin(), c_.end(), chainage);
    const std::size_t last = static_cast<std::size_t>(std::max<std::ptrdiff_t>(0, upper - c_.begin() - 1));
    const std::size_t seg = std::min(last, x_.size() - 2);
    const double u = std::clamp((chainage - c_[seg]) / std::max(c_[seg + 1] - c_[seg], 1e-9), 0.0, 1.0);
    const double tx = x_[seg] + u * (x_[seg + 1] - x_[seg]), ty = y_[seg] + u * (y_[seg + 1] - y_[seg]);
    // Walk the observer back; the track between it and the target must stay
    // within the corridor of the line of sight.
    for (std::size_t k = last + 1; k-- > 0;) {
        for (std::size_t j = k + 1; j <= last; ++j) {
            if (point_segment(x_[j], y_[j], x_[k], y_[k], tx, ty) > corridor) {
                limited = true;
                return chainage - c_[std::min(k + 1, last)];
            }
        }
    }
    return chainage - c_.front();
}

double box_distance(const Box& a, const Box& b) {
    auto corners = [](const Box& q) {
        const double c = std::cos(q.h), s = std::sin(q.h), l = q.length / 2, w = q.width / 2;
        std::array<std::array<double, 2>, 4> p{};
        const double sx[4] = {1, 1, -1, -1}, sy[4] = {1, -1, -1, 1};
        for (int i = 0; i < 4; ++i) {
            p[i] = {q.x + sx[i] * l * c - sy[i] * w * s, q.y + sx[i] * l * s + sy[i] * w * c};
        }
        return p;
    };
    const auto pa = corners(a), pb = corners(b);
    // Separating axes: the boxes' edge normals.
    bool separated = false;
    for (const Box* q : {&a, &b}) {
        for (const double ang : {q->h, q->h + M_PI / 2}) {
            const double ax = std::cos(ang), ay = std::sin(ang);
            double a0 = 1e300, a1 = -1e300, b0 = 1e300, b1 = -1e300;
            for (int i = 0; i < 4; ++i) {
                const double da = pa[i][0] * ax + pa[i][1] * ay, db = pb[i][0] * ax + pb[i][1] * ay;
                a0 = std::min(a0, da), a1 = std::max(a1, da), b0 = std::min(b0, db), b1 = std::max(b1, db);
            }
            separated = separated || a1 < b0 || b1 < a0;
        }
    }
    if (!separated) {
        return 0.0;
    }
    double d = std::numeric_limits<double>::infinity();
    for (int i = 0; i < 4; ++i) {
        for (int j = 0; j < 4; ++j) {
            const auto& e0 = pb[j];
            const auto& e1 = pb[(j + 1) % 4];
            d = std::min(d, point_segment(pa[i][0], pa[i][1], e0[0], e0[1], e1[0], e1[1]));
            const auto& f0 = pa[j];
            const auto& f1 = pa[(j + 1) % 4];
            d = std::min(d, point_segment(pb[i][0], pb[i][1], f0[0], f0[1], f1[0], f1[1]));
        }
    }
    return d;
}

} // namespace railodd::scenario::play
