#pragma once
// The mapped polyline's chainage and heading: what the fine spline and the
// trend filter (curvature_trend.cpp) both start from.
#include "least_squares.hpp"

#include <vector>

namespace railodd::geometry::fit {

// Cumulative length along the polyline at each point.
std::vector<double> chainage(const std::vector<Point2>& p);

// Heading of the polyline as a function of chainage: chord directions,
// unwrapped, at chord midpoints; linear in between. Chords shorter than
// min_chord are skipped (their direction is mostly noise: 0.3 m of scatter on
// a 2 m chord turns it by 0.2 rad).
class ChordHeading {
public:
    ChordHeading(const std::vector<Point2>& p, double min_chord);
    double at(double s) const;
    bool empty() const noexcept { return hdg_.empty(); }

private:
    std::vector<double> mid_, hdg_;
};

} // namespace railodd::geometry::fit
