#include "railodd/geometry/vertex_legs.hpp"

#include <cmath>
#include <numbers>
#include <sstream>

namespace railodd::geometry {

std::vector<std::vector<Leg>> legs_by_vertex(const TrackGraph& graph, const FittedNetwork& fitted,
                                             const std::vector<bool>& written) {
    std::vector<std::vector<Leg>> legs(graph.vertices.size());
    for (std::size_t e = 0; e < fitted.edges.size(); ++e) {
        if (!written.empty() && !written[e]) {
            continue;
        }
        const auto& fe = fitted.edges[e];
        const auto& ge = graph.edges[e];
        const std::size_t start_v = fe.reversed ? ge.to : ge.from;
        const std::size_t end_v = fe.reversed ? ge.from : ge.to;
        const Pose a = evaluate(fe.alignment, 0.0);
        Pose b = evaluate(fe.alignment, length(fe.alignment));
        b.hdg += std::numbers::pi; // leaving the vertex means running backwards
        b.curvature = -b.curvature;
        legs[start_v].push_back({e, true, a});
        legs[end_v].push_back({e, false, b});
    }
    return legs;
}

// Entering along one leg runs it backwards, so the outgoing curvatures of
// two legs a train passes between must cancel.
std::string g2_mismatch(const Leg& a, const Leg& b, const LegTolerances& tol) {
    const double gap = std::hypot(a.out.x - b.out.x, a.out.y - b.out.y);
    const double turn = std::abs(std::remainder(a.out.hdg - b.out.hdg - std::numbers::pi, 2 * std::numbers::pi));
    const double dk = std::abs(a.out.curvature + b.out.curvature);
    std::ostringstream why;
    if (gap > tol.gap_m) {
        why << "ends " << gap << " m apart";
    } else if (turn > tol.heading_rad) {
        why << "deflection " << turn * 180.0 / std::numbers::pi << " deg";
    } else if (dk > tol.curvature) {
        why << "curvature jump " << dk << " 1/m";
    }
    return why.str();
}

LegSides movement_sides(std::size_t n, const std::vector<std::pair<std::size_t, std::size_t>>& movements) {
    std::vector<std::vector<std::size_t>> adj(n);
    for (const auto& [a, b] : movements) {
        adj[a].push_back(b);
        adj[b].push_back(a);
    }
    LegSides out{std::vector<int>(n, -1), std::vector<long>(n, -1)};
    for (std::size_t root = 0; root < n; ++root) {
        if (out.colour[root] >= 0 || adj[root].empty()) {
            continue;
        }
        std::vector<std::size_t> stack{root};
        out.colour[root] = 0;
        out.component[root] = static_cast<long>(root);
        while (!stack.empty()) {
            const std::size_t v = stack.back();
            stack.pop_back();
            for (const std::size_t w : adj[v]) {
                if (out.colour[w] < 0) {
                    out.colour[w] = 1 - out.colour[v];
                    out.component[w] = static_cast<long>(root);
                    stack.push_back(w);
                }
            }
        }
    }
    return out;
}

} // namespace railodd::geometry
