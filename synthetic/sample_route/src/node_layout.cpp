#include "node_layout.hpp"

#include <algorithm>
#include <stdexcept>
#include <string>

namespace railodd::sample {

namespace {

constexpr double min_fixed_gap = 5.0;

struct Zone {
    double from;
    double to;
};

// Stretches with curvature (arcs and transitions), where mappers draw densely.
std::vector<Zone> curved_zones(const geometry::Alignment& a) {
    std::vector<Zone> zones;
    const auto s0 = geometry::primitive_s(a);
    for (std::size_t i = 0; i < a.primitives.size(); ++i) {
        const auto& p = a.primitives[i];
        if (p.curv_start == 0.0 && p.curv_end == 0.0) {
            continue;
        }
        if (!zones.empty() && zones.back().to == s0[i]) {
            zones.back().to += p.length;
        } else {
            zones.push_back({s0[i], s0[i] + p.length});
        }
    }
    return zones;
}

void check_fixed(const std::vector<double>& fixed, double length) {
    if (fixed.size() < 2 || fixed.front() != 0.0 || fixed.back() != length) {
        throw std::logic_error("node layout: fixed chainages must include both track ends");
    }
    for (std::size_t i = 1; i < fixed.size(); ++i) {
        if (fixed[i] - fixed[i - 1] < min_fixed_gap) {
            throw std::logic_error("node layout: fixed nodes at s " + std::to_string(fixed[i - 1]) +
                                   " and " + std::to_string(fixed[i]) + " are closer than 5 m");
        }
    }
}

// Nodes strictly between two fixed ones.
void fill(double from, double to, const std::vector<Zone>& zones, Rng& rng, const NodeSpacing& sp,
          std::vector<double>& out) {
    double pos = from;
    for (;;) {
        const auto zone = std::find_if(zones.begin(), zones.end(),
                                       [&](const Zone& z) { return z.to > pos + 1e-9; });
        const bool dense = zone != zones.end() && zone->from <= pos + 1e-9;
        double next = pos + (dense ? rng.uniform(sp.curve_min, sp.curve_max)
                                   : rng.uniform(sp.straight_min, sp.straight_max));
        if (!dense && zone != zones.end() && zone->from < next) {
            // A mapper starts drawing the curve shortly after the straight ends.
            next = zone->from + rng.uniform(1.0, 15.0);
        }
        const double keep_clear = dense ? 0.4 * sp.curve_min : 0.25 * sp.straight_min;
        if (next > to - keep_clear) {
            return;
        }
        out.push_back(next);
        pos = next;
    }
}

} // namespace

std::vector<double> mapper_chainages(const geometry::Alignment& alignment, std::vector<double> fixed,
                                     Rng& rng, const NodeSpacing& spacing) {
    std::sort(fixed.begin(), fixed.end());
    check_fixed(fixed, geometry::length(alignment));
    const auto zones = curved_zones(alignment);
    std::vector<double> out;
    for (std::size_t i = 0; i + 1 < fixed.size(); ++i) {
        out.push_back(fixed[i]);
        fill(fixed[i], fixed[i + 1], zones, rng, spacing, out);
    }
    out.push_back(fixed.back());
    return out;
}

} // namespace railodd::sample
