#pragma once
// The last step of a chain's design (design_fit.cpp): with the structure the
// search chose fixed, a few Levenberg-Marquardt steps on exact clothoids
// (docs/geometry.md, step 7).
#include "design_pass.hpp"
#include "least_squares.hpp"

#include "railodd/geometry/alignment.hpp"
#include "railodd/geometry/fit_alignment.hpp"

#include <optional>
#include <vector>

namespace railodd::geometry::fit {

// What the frame's small-angle model left (second order in the offsets, the
// lengths along a curve) taken out; an arc the polish shrinks to nothing
// between two transitions taken out of the structure where that costs less
// than the arc's length parameter; a transition at a tied end kept at least
// switch_transition_m long. The alignment kept and its distances to the
// nodes (`all`, the same nodes as p): the pass's own, moved onto a tied end,
// where the polish fails or brings a node further off.
FitResult polish(const DesignPass& pass, const std::vector<Point2>& p, const std::vector<Point>& all,
                 const std::vector<double>& weight, double sigma, const std::optional<Pose>& start,
                 const std::optional<Pose>& end);

// A transition at a switch standing for the turnout's curvature jump (a
// turnout's curve starts at its switch without one) is this long at least:
// shorter, nothing in the nodes tells it from the jump (into R 150 m it lies
// 1 mm inside the curve), and a sub-metre element is one no design has.
constexpr double switch_transition_m = 2.0;

} // namespace railodd::geometry::fit
