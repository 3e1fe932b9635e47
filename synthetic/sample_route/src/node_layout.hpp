#pragma once
// Where a mapper puts the nodes of a track: a few on straights, many in curves
// and transitions, always irregular. The fitter must cope with exactly this.
#include "rng.hpp"

#include "railodd/geometry/alignment.hpp"

#include <vector>

namespace railodd::sample {

struct NodeSpacing {
    double straight_min = 150.0;
    double straight_max = 400.0;
    double curve_min = 8.0;
    double curve_max = 25.0;
};

// Sorted chainages of the nodes of one track: every fixed chainage (which must
// include both ends, lie on the track and be at least 5 m apart, else
// std::logic_error) plus irregularly spaced ones in between.
std::vector<double> mapper_chainages(const geometry::Alignment& alignment, std::vector<double> fixed,
                                     Rng& rng, const NodeSpacing& spacing = {});

} // namespace railodd::sample
