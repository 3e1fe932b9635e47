#pragma once
// Which chain runs beside which: for each chain, the chains ranked before it
// (longer) that its nodes lie 2.5-6.5 m from, along them (either way), most
// nodes first: the designs it is offered as guides (fit/parallel_guide.hpp).
// Decided on the mapped nodes only, before any fit, so that the fitting
// order stays a function of the graph.
#include "railodd/geometry/fit_alignment.hpp"

#include <cstddef>
#include <optional>
#include <vector>

namespace railodd::geometry {

// points: each chain's mapped nodes; rank: each chain's place in the
// fitting priority (lower first). A guide has a lower rank and at least
// five nodes of the chain beside it.
std::vector<std::vector<std::size_t>> parallel_guides(const std::vector<std::vector<Point>>& points,
                                                      const std::vector<std::size_t>& rank);

} // namespace railodd::geometry
