// Routes through a shared node, decided from branch directions alone.
#include "node_routes.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <tuple>

namespace railodd::geometry::detail {

namespace {

double dot(ingest::XY u, ingest::XY v) { return u.x * v.x + u.y * v.y; }

// Counter-clockwise angle from u to v in [0, 2 pi).
double ccw_angle(ingest::XY u, ingest::XY v) {
    const double a = std::atan2(u.x * v.y - u.y * v.x, dot(u, v));
    return a < 0.0 ? a + 2.0 * std::numbers::pi : a;
}

} // namespace

std::vector<Route> pair_routes(const std::vector<Branch>& branches) {
    struct Candidate {
        bool other_owner;
        double dot;
        std::size_t i;
        std::size_t j;
    };
    std::vector<Candidate> candidates;
    for (std::size_t i = 0; i < branches.size(); ++i) {
        for (std::size_t j = i + 1; j < branches.size(); ++j) {
            candidates.push_back(
                {branches[i].owner != branches[j].owner, dot(branches[i].dir, branches[j].dir), i, j});
        }
    }
    std::sort(candidates.begin(), candidates.end(), [](const Candidate& x, const Candidate& y) {
        return std::tie(x.other_owner, x.dot, x.i, x.j) < std::tie(y.other_owner, y.dot, y.i, y.j);
    });
    std::vector<bool> taken(branches.size(), false);
    std::vector<Route> routes;
    for (const auto& c : candidates) {
        if (!taken[c.i] && !taken[c.j]) {
            taken[c.i] = taken[c.j] = true;
            routes.push_back({c.i, c.j});
        }
    }
    for (std::size_t i = 0; i < branches.size(); ++i) {
        if (!taken[i]) {
            routes.push_back({i, std::nullopt});
        }
    }
    return routes;
}

Branch opposite(const Branch& b) { return {b.owner, no_node, {-b.dir.x, -b.dir.y}}; }

Side side_of(const Branch& back, const Branch& fwd, const Branch& b) {
    if (b.neighbour != no_node && (b.neighbour == back.neighbour || b.neighbour == fwd.neighbour)) {
        return Side::along;
    }
    // Left of the path is the sector swept counter-clockwise from the leaving
    // direction round to the arriving one.
    const double to_back = ccw_angle(fwd.dir, back.dir);
    const double to_b = ccw_angle(fwd.dir, b.dir);
    if (to_b == 0.0 || to_b == to_back) {
        return Side::along;
    }
    return to_b < to_back ? Side::left : Side::right;
}

ingest::XY unit(ingest::XY from, ingest::XY to) {
    const double dx = to.x - from.x;
    const double dy = to.y - from.y;
    const double n = std::hypot(dx, dy);
    return n > 0.0 ? ingest::XY{dx / n, dy / n} : ingest::XY{0.0, 0.0};
}

double line_angle_deg(ingest::XY u, ingest::XY v) {
    const double nu = std::hypot(u.x, u.y);
    const double nv = std::hypot(v.x, v.y);
    if (nu == 0.0 || nv == 0.0) {
        return 0.0;
    }
    // atan2 of |cross| and |dot| stays accurate near 0 and 90 degrees.
    const double cross = std::abs(u.x * v.y - u.y * v.x);
    return std::atan2(cross, std::abs(dot(u, v))) * 180.0 / std::numbers::pi;
}

double line_direction_deg(ingest::XY u, ingest::XY v) {
    if (std::hypot(u.x, u.y) == 0.0 || std::hypot(v.x, v.y) == 0.0) {
        return 90.0;
    }
    double deg = std::atan2(u.x * v.y - u.y * v.x, dot(u, v)) * 180.0 / std::numbers::pi;
    deg = std::fmod(deg + 360.0, 180.0);
    return deg >= 180.0 ? 0.0 : deg;
}

} // namespace railodd::geometry::detail
