#pragma once
// The exact integrals the frame fit (frame_fit.cpp) is built from: the
// reference line's heading and its integral, and the double integrals of
// the knots' hat functions, whose sums are a piecewise-linear curvature's
// offset.
#include "frame_fit.hpp"

#include <Eigen/Dense>

#include <vector>

namespace railodd::geometry::fit {

// The reference's heading, linear between grid points (constant beyond),
// and its integral from 0 less the start heading.
class ReferenceHeading {
public:
    explicit ReferenceHeading(const Frame& f);

    struct At {
        double hdg = 0.0;
        double integral = 0.0;
    };

    At at(double s) const;

private:
    const Frame& f_;
    std::vector<double> integral_;
};

// The double integrals, from the start to each chainage s (ascending), of
// each knot's hat function (one at the knot, falling linearly to zero at
// its neighbours; the last knot's constant beyond the curve's end): the
// offset a unit curvature at that knot gives, split into the rising (left)
// and falling (right) halves of the hat. Exact, one pass.
struct HatIntegrals {
    Eigen::MatrixXd left, right; // rows: chainages; columns: knots
    Eigen::MatrixXd total() const { return left + right; }
};

HatIntegrals hat_integrals(const std::vector<double>& l, const std::vector<double>& s);

} // namespace railodd::geometry::fit
