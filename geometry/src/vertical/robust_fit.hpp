#pragma once
// Iteratively reweighted smoothing for the approaches to tunnels and bridges:
// portals sit in cuttings and abutments on embankments that reach beyond any
// fixed margin, so there the DEM shows ground metres above or below the
// track. Such samples are few and far off: robust weights find and drop them
// where least squares would bend towards them.
//
// Only samples flagged as adjustable are reweighted. Applied everywhere, the
// redescending biweight would also reject the fit's own bias at a genuine
// sharp change of grade and run away from it (on a clean 50 permille ramp it
// flattened the ramp to 34 permille), so the caller confines it to the
// approaches, where the ground is known to leave the track.
#include "hermite_spline.hpp"

#include <vector>

namespace railodd::geometry::vertical {

struct RobustOptions {
    // Lower bound of the residual scale, m: on clean data the scale estimate
    // shrinks towards zero and would reject the spline's own smoothing bias.
    double sigma_floor = 1.0;
    int huber_iterations = 3; // convex: a safe start for ...
    int tukey_iterations = 4; // ... the redescending biweight, which drops far outliers
};

struct RobustFit {
    HermiteKnots knots;
    std::vector<double> weights; // final robustness weight per datum, 0 = rejected
    double sigma = 0.0;          // residual scale of the least-squares start, m
};

// adjustable: per datum, whether robust weights apply to it (else weight 1).
RobustFit fit_robust(const SplineData& data, const std::vector<bool>& adjustable, double length,
                     double knot_spacing, double smoothing_length, const RobustOptions& options);

} // namespace railodd::geometry::vertical
