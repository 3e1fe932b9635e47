#pragma once
// The Jacobian of a chain's residuals in state-space form (chain_system.hpp):
// each parameter's own derivative in the rows of its segments, by forward
// differences as the dense linearisation, and the rigid motion it leaves
// beyond them.
#include "residuals.hpp"

namespace railodd::geometry::fit {

// Whether the solve can be a chain's: asked for, no kink or ridge rows
// (they join three knots), every curvature variable on consecutive knots.
bool chain_form(const CurvatureModel& m, const Problem& p);

// Fills lin.chain (and, with an end pose, lin.C and lin.end_state) for
// the model at `poses` with the feet and lin.r already in place.
void chain_linearise(const CurvatureModel& m, const ParameterMap& map, const Problem& p, const std::vector<Foot>& feet,
                     const std::vector<Pose>& poses, Linearisation& lin);

} // namespace railodd::geometry::fit
