#include "rail_vertex_plan.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <sstream>

namespace railodd::xodr {

namespace {

// Two-colours the movement graph (movements always join legs leaving on
// opposite sides, so it is bipartite) and cuts the larger class of each
// component: a switch cuts its two diverging legs, a crossing one leg of each
// route. Ties keep the lowest leg uncut.
void choose_cuts(VertexPlan& plan) {
    const std::size_t n = plan.legs.size();
    std::vector<std::vector<std::size_t>> adj(n);
    for (const auto& [a, b] : plan.movements) {
        adj[a].push_back(b);
        adj[b].push_back(a);
    }
    std::vector<int> colour(n, -1);
    plan.cut.assign(n, false);
    for (std::size_t root = 0; root < n; ++root) {
        if (colour[root] >= 0 || adj[root].empty()) {
            continue;
        }
        std::vector<std::size_t> component{root}, stack{root};
        colour[root] = 0;
        while (!stack.empty()) {
            const std::size_t v = stack.back();
            stack.pop_back();
            for (std::size_t w : adj[v]) {
                if (colour[w] < 0) {
                    colour[w] = 1 - colour[v];
                    component.push_back(w);
                    stack.push_back(w);
                }
            }
        }
        const auto ones = std::count_if(component.begin(), component.end(), [&](std::size_t v) { return colour[v] == 1; });
        const int cut_colour = ones * 2 >= static_cast<long>(component.size()) ? 1 : 0;
        for (std::size_t v : component) {
            plan.cut[v] = colour[v] == cut_colour;
        }
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
