#include "rail_vertex_plan.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <sstream>

namespace railodd::xodr {

namespace {

// Cuts the larger side of each component of the movement graph
// (geometry::movement_sides): a switch cuts its two diverging legs, a
// crossing one leg of each route. Ties keep the lowest leg uncut.
void choose_cuts(VertexPlan& plan) {
    const std::size_t n = plan.legs.size();
    const geometry::LegSides sides = geometry::movement_sides(n, plan.movements);
    std::vector<long> size(n, 0), ones(n, 0); // per component root
    for (std::size_t v = 0; v < n; ++v) {
        if (sides.component[v] >= 0) {
            ++size[sides.component[v]];
            ones[sides.component[v]] += sides.colour[v];
        }
    }
    plan.cut.assign(n, false);
    for (std::size_t v = 0; v < n; ++v) {
        const long c = sides.component[v];
        plan.cut[v] = c >= 0 && sides.colour[v] == (ones[c] * 2 >= size[c] ? 1 : 0);
    }
    for (auto& [a, b] : plan.movements) {
        if (plan.cut[a]) {
            std::swap(a, b); // (uncut, cut)
        }
    }
}

} // namespace

std::vector<VertexPlan> plan_vertices(const geometry::TrackGraph& graph, const geometry::FittedNetwork& fitted,
                                      const std::vector<bool>& written, const PlanTolerances& tolerances) {
    std::vector<std::vector<Leg>> legs = geometry::legs_by_vertex(graph, fitted, written);
    std::vector<VertexPlan> plans;
    for (std::size_t v = 0; v < legs.size(); ++v) {
        if (legs[v].size() < 2) {
            continue;
        }
        VertexPlan plan;
        plan.vertex = v;
        plan.legs = std::move(legs[v]);
        plan.junction = plan.legs.size() > 2;
        std::vector<std::string> why(plan.legs.size());
        for (std::size_t i = 0; i < plan.legs.size(); ++i) {
            for (std::size_t j = i + 1; j < plan.legs.size(); ++j) {
                std::string m = geometry::g2_mismatch(plan.legs[i], plan.legs[j], tolerances);
                if (m.empty()) {
                    plan.movements.emplace_back(i, j);
                } else {
                    for (std::size_t k : {i, j}) {
                        if (why[k].empty()) {
                            why[k] = m;
                        }
                    }
                }
            }
        }
        choose_cuts(plan);
        for (std::size_t i = 0; i < plan.legs.size(); ++i) {
            const bool moves = std::any_of(plan.movements.begin(), plan.movements.end(),
                                           [&](const auto& m) { return m.first == i || m.second == i; });
            if (!moves) {
                plan.unlinked.emplace_back(i, "no through route from this end (closest other end: " + why[i] + ")");
            }
        }
        if (!plan.junction) {
            plan.cut.assign(plan.legs.size(), false); // two ends link directly
        }
        plans.push_back(std::move(plan));
    }
    return plans;
}

} // namespace railodd::xodr
