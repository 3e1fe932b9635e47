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
    std::size_t tested = 0;     // nodes the scale is taken over
};

// Each node is predicted from its neighbours (a quadratic in chainage, so
// curves are no outliers); its offset across that line, studentised by the
// prediction's leverage, is its residual. The noise scale is the MAD of the
// residuals from two neighbours each side. Outliers are then found by a
// robust prediction from three each side, re-weighted by Tukey's biweight of
// each node's own residual (three rounds, as robust LOWESS does), so that a
// second outlier nearby spoils neither. The worst node beyond max(2.5 m,
// 5 scales) that is a spike (the polyline through the kept nodes turns one
// way at it and the other way at both neighbours) is marked, and so on. The
// chain's two end nodes (switches, buffer stops) are never marked.
OutlierScan find_outlier_nodes(const std::vector<Point2>& p);

// The upper median (0 for none): the robust scales' centre.
double median(std::vector<double> v);

} // namespace railodd::geometry::fit
