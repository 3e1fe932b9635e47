#pragma once
// Shared by the design search's tests: its fit options, and a tie where a
// switch would put it on a route of known design.
#include "railodd/geometry/fit_alignment.hpp"
#include "railodd/truth/alignment_truth.hpp"

#include <cstdint>

namespace railodd::test {

inline geometry::FitOptions design_search() {
    geometry::FitOptions o;
    o.method = geometry::FitMethod::design_search;
    return o;
}

// The design's pose where a node's foot is.
inline geometry::Pose pose_at(const geometry::Alignment& design, const geometry::Point& node) {
    return geometry::evaluate(design, geometry::project_point(design, node.x, node.y).s);
}

// A route of known design drawn with this noise, outlier share and spacing.
inline truth::TruthRoute truth_route(int seed, double sigma, double outliers, truth::Spacing spacing) {
    truth::TruthOptions t;
    t.sigma_m = sigma;
    t.outlier_fraction = outliers;
    t.spacing = spacing;
    return truth::make_route(static_cast<std::uint64_t>(seed), t);
}

} // namespace railodd::test
