#pragma once
// Gradients of a fitted profile, found exactly from each cubic's derivative
// (a quadratic) rather than by sampling, so short steep spots are not missed.
#include "railodd/geometry/vertical_profile.hpp"

#include <vector>

namespace railodd::geometry::vertical {

// max |dz/ds| over [polys.front().s, length].
double max_abs_gradient(const std::vector<ElevationPoly>& polys, double length);

// Maximal stretches where |dz/ds| > threshold (a ratio, not permille), merged
// across poly joints.
std::vector<SteepStretch> steep_stretches(const std::vector<ElevationPoly>& polys, double length,
                                          double threshold);

} // namespace railodd::geometry::vertical
