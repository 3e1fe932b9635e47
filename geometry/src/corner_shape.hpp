#pragma once
// One symmetric clothoid corner: the curve that takes a straight into the
// next straight across a polyline vertex with curvature rising from zero and
// falling back to zero (spiral, arc, spiral), so it joins lines G2.
#include "railodd/geometry/alignment.hpp"

#include <limits>
#include <vector>

namespace railodd::geometry::corner {

// Limits on the size of one corner. A corner's shape is fixed by its
// deflection; its size (scale) grows until the first limit binds.
struct CornerLimits {
    double tangent_m = 0.0;                                       // vertex to each end of the corner
    double deviation_m = std::numeric_limits<double>::infinity(); // vertex to the curve
    double max_radius_m = 1000.0;                                 // of the arc (1 / peak curvature), but wider
                                                                  // where its pieces would be under a metre
};

struct Corner {
    double deflection = 0.0; // signed turn, left positive
    double tangent = 0.0;    // vertex to each end of the corner along the straights
    double deviation = 0.0;  // vertex to the curve's midpoint (its nearest point)
    double curvature = 0.0;  // peak curvature (signed); 0: no corner
    std::vector<Primitive> primitives;
};

// Deflections this small are left as they are: the heading jump stays below
// the tolerance of any consumer, and the corner would be a sliver.
inline constexpr double negligible_deflection = 1e-10;

// |deflection| must be below pi; a corner this close to reversing (a spike in
// the mapping) has no sensible symmetric rounding and is not asked for.
Corner make_corner(double deflection, const CornerLimits& limits);

} // namespace railodd::geometry::corner
