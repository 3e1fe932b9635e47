#pragma once
// How well the nodes can tell a design arc's radius at all: the Cramer-Rao
// bound of its curvature, given the true structure (lines, transitions,
// arcs: start pose, every element's length and every arc's curvature free)
// and the nodes' lateral scatter. No unbiased fit can do better; a route
// whose short or flat arcs have a bound of several percent cannot meet a
// radius target of 2-3 % on them. Fisher information from the signed node
// offsets' Jacobian by central differences.
#include "railodd/truth/alignment_truth.hpp"

#include <vector>

namespace railodd::bench {

// Per design arc (route.arcs order): the bound's standard deviation of the
// curvature relative to the arc's curvature; empty where singular.
std::vector<double> arc_curvature_bounds(const truth::TruthRoute& route, double sigma);

} // namespace railodd::bench
