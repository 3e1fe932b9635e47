#pragma once
// Penalised least-squares cubic Hermite spline: the smoothing engine of the
// vertical profile, independent of where the elevations come from.
#include "railodd/geometry/vertical_profile.hpp"

#include <vector>

namespace railodd::geometry::vertical {

// Weighted data to smooth: s ascending, w > 0 (metres of track each point
// stands for, so the fit does not depend on the sampling density).
struct SplineData {
    std::vector<double> s;
    std::vector<double> z;
    std::vector<double> w;
};

// Value and slope at equally spaced knots from 0 to length: the spline is
// C1 by construction, as neighbouring cubics share the knot's value and slope.
struct HermiteKnots {
    std::vector<double> s;
    std::vector<double> z;
    std::vector<double> m; // dz/ds
};

// Minimises  sum w_i (z(s_i) - z_i)^2 + L^4 * integral z''(s)^2 ds  over the
// Hermite spline with knots about knot_spacing apart. With data weights per
// metre, this is a low-pass filter with transfer 1 / (1 + (L omega)^4), so
// L (smoothing_length) is a physical scale independent of the sampling step.
// Gaps in the data are bridged by a cubic (the curvature penalty's
// minimiser); beyond the first and last datum the spline runs on straight.
// Needs at least two distinct s; throws std::invalid_argument otherwise.
HermiteKnots fit_hermite_spline(const SplineData& data, double length, double knot_spacing,
                                double smoothing_length);

double evaluate(const HermiteKnots& knots, double s);

// One OpenDRIVE cubic per knot interval.
std::vector<ElevationPoly> to_polys(const HermiteKnots& knots);

} // namespace railodd::geometry::vertical
