#include "outlier_nodes.hpp"

#include <algorithm>
#include <cmath>
#include <optional>

namespace railodd::geometry::fit {

namespace {

constexpr int side = 2;            // kept neighbours each side
constexpr double min_offset_m = 3.0;
constexpr double scale_factor = 5.0;
// Near a chain's ends the track meets switches and other tracks, whose
// geometry a quadratic through four nodes does not follow: never marked there.
constexpr double end_guard_m = 150.0;

// Up to `side` kept neighbours of i on each side, or nothing near an end.
std::optional<std::vector<std::size_t>> neighbours(const std::vector<bool>& gone, std::size_t i) {
    std::vector<std::size_t> nb;
    for (std::size_t j = i, found = 0; j > 0 && found < side;) {
        --j;
        if (!gone[j]) {
            nb.push_back(j);
            ++found;
        }
    }
    if (nb.size() < side) {
        return std::nullopt;
    }
    std::size_t found = 0;
    for (std::size_t j = i + 1; j < gone.size() && found < side; ++j) {
        if (!gone[j]) {
            nb.push_back(j);
            ++found;
        }
    }
    if (found < side) {
        return std::nullopt;
    }
    return nb;
}

// Offset of p[i] across the quadratic (in chainage t) through its neighbours,
// divided by sqrt(1 + h), h the prediction's leverage: a node far from
// clustered neighbours is predicted by extrapolating their noise, and its
// offset counts for that much less (a studentised residual, in metres of
// node scatter).
double residual(const std::vector<Point2>& p, const std::vector<double>& t, const std::vector<bool>& gone,
                std::size_t i) {
    const auto nb = neighbours(gone, i);
    if (!nb) {
        return 0.0;
    }
    // Least squares of x(u) and y(u), u = t - t_i, on 1, u, u^2 (4 points).
    double s[5] = {0, 0, 0, 0, 0}, bx[3] = {0, 0, 0}, by[3] = {0, 0, 0};
    for (const std::size_t j : *nb) {
        const double u = (t[j] - t[i]) / 100.0; // scaled: well conditioned
        double up = 1.0;
        for (int k = 0; k < 5; ++k, up *= u) {
            s[k] += up;
            if (k < 3) {
                bx[k] += up * p[j].x;
                by[k] += up * p[j].y;
            }
        }
    }
    // Solve the 3x3 normal equations [s0 s1 s2; s1 s2 s3; s2 s3 s4] c = b by Cramer's rule.
    const double m[3][3] = {{s[0], s[1], s[2]}, {s[1], s[2], s[3]}, {s[2], s[3], s[4]}};
    auto det3 = [](const double a[3][3]) {
        return a[0][0] * (a[1][1] * a[2][2] - a[1][2] * a[2][1]) - a[0][1] * (a[1][0] * a[2][2] - a[1][2] * a[2][0]) +
               a[0][2] * (a[1][0] * a[2][1] - a[1][1] * a[2][0]);
    };
    const double d = det3(m);
    if (std::abs(d) < 1e-12) {
        return 0.0;
    }
    auto solve = [&](const double b[3], int col) {
        double a[3][3];
        for (int r = 0; r < 3; ++r) {
            for (int c = 0; c < 3; ++c) {
                a[r][c] = c == col ? b[r] : m[r][c];
            }
        }
        return det3(a) / d;
    };
    const double x0 = solve(bx, 0), x1 = solve(bx, 1), y0 = solve(by, 0), y1 = solve(by, 1);
    const double len = std::hypot(x1, y1);
    if (len < 1e-12) {
        return 0.0;
    }
    // Across the local direction only: chainage errors move a node along the line.
    const double leverage = (m[1][1] * m[2][2] - m[1][2] * m[2][1]) / d; // (M^-1)_00
    return std::abs((p[i].x - x0) * (-y1 / len) + (p[i].y - y0) * (x1 / len)) / std::sqrt(1.0 + std::max(0.0, leverage));
}

// Turn (cross product sign) of the polyline at i.
double turn(const std::vector<Point2>& p, std::size_t i) {
    const double ax = p[i].x - p[i - 1].x, ay = p[i].y - p[i - 1].y;
    const double bx = p[i + 1].x - p[i].x, by = p[i + 1].y - p[i].y;
    return ax * by - ay * bx;
}

// A node pulled aside makes the polyline turn one way at it and the other
// way at both neighbours; a curve entered between sparse nodes turns one way
// throughout, and is no outlier however badly a quadratic predicts it.
bool spike(const std::vector<Point2>& p, std::size_t i) {
    const double here = turn(p, i);
    return here * turn(p, i - 1) < 0.0 && here * turn(p, i + 1) < 0.0;
}

double median(std::vector<double> v) {
    if (v.empty()) {
        return 0.0;
    }
    const auto mid = v.begin() + static_cast<std::ptrdiff_t>(v.size() / 2);
    std::nth_element(v.begin(), mid, v.end());
    return *mid;
}

} // namespace

OutlierScan find_outlier_nodes(const std::vector<Point2>& p) {
    OutlierScan scan;
    const std::size_t n = p.size();
    scan.outlier.assign(n, false);
    if (n < 2 * side + 1) {
        return scan;
    }
    std::vector<double> t(n, 0.0);
    for (std::size_t i = 1; i < n; ++i) {
        t[i] = t[i - 1] + std::hypot(p[i].x - p[i - 1].x, p[i].y - p[i - 1].y);
    }
    std::vector<double> r(n, 0.0);
    std::vector<double> tested;
    for (std::size_t i = 0; i < n; ++i) {
        r[i] = residual(p, t, scan.outlier, i);
        if (i >= side && i + side < n) {
            tested.push_back(r[i]);
        }
    }
    scan.noise_sigma_m = 1.4826 * median(tested);
    const double limit = std::max(min_offset_m, scale_factor * scan.noise_sigma_m);
    std::vector<bool> cleared(n, false); // tested and kept
    while (true) {
        std::size_t worst = n;
        for (std::size_t i = side + 1; i + side + 1 < n; ++i) {
            const bool inner = t[i] > end_guard_m && t[n - 1] - t[i] > end_guard_m;
            if (inner && !scan.outlier[i] && !cleared[i] && r[i] > limit && spike(p, i) &&
                (worst == n || r[i] > r[worst])) {
                worst = i;
            }
        }
        if (worst == n) {
            return scan;
        }
        // Without it, its neighbours must line up: then it was a spike. Where
        // they do not (a curve entered between sparse straight nodes, which a
        // quadratic cannot follow), the point is kept.
        scan.outlier[worst] = true;
        const std::size_t lo = worst >= 2 * side ? worst - 2 * side : 0;
        const std::size_t hi = std::min(n, worst + 2 * side + 1);
        std::vector<double> again(hi - lo, 0.0);
        bool isolated = true;
        for (std::size_t i = lo; i < hi; ++i) {
            if (!scan.outlier[i]) {
                again[i - lo] = residual(p, t, scan.outlier, i);
                isolated = isolated && (again[i - lo] <= 0.5 * limit || scan.outlier[i]);
            }
        }
        if (!isolated) {
            scan.outlier[worst] = false;
            cleared[worst] = true;
            continue;
        }
        r[worst] = 0.0;
        for (std::size_t i = lo; i < hi; ++i) {
            if (!scan.outlier[i]) {
                r[i] = again[i - lo]; // its neighbours were predicted through it
            }
        }
    }
}

} // namespace railodd::geometry::fit
