#pragma once
// Mapped nodes far off the line their neighbours draw (a node dragged 3-10 m
// aside, a mistyped coordinate): a least-squares fit follows them, bending
// straights and mis-reading radii by tens of per cent. They are found before
// the fit, from the data alone, and left out of it.
#include "least_squares.hpp"

#include <cstddef>
#include <vector>

namespace railodd::geometry::fit {

struct OutlierScan {
    std::vector<bool> outlier;  // per point
    double noise_sigma_m = 0.0; // robust scale of the nodes about their neighbours' line
};

// Each interior point is predicted from two kept neighbours on each side (a
// quadratic in chainage through them, so curves are no outliers); its offset
// across that line, studentised by the prediction's leverage, is its
// residual. The scale is the MAD of the residuals; the worst point beyond
// max(3 m, 5 scale) that is a spike (the polyline turns one way at it and the
// other way at both neighbours) is marked if its neighbours then line up,
// and they are predicted again, until none is. Points within 150 m of either end (and the
// end points with the two next to them) are never marked: there the track
// meets switches and other tracks.
OutlierScan find_outlier_nodes(const std::vector<Point2>& p);

} // namespace railodd::geometry::fit
