#include "outlier_nodes.hpp"

#include <algorithm>
#include <cmath>
#include <optional>

namespace railodd::geometry::fit {

namespace {

constexpr std::size_t side = 2;    // neighbours each side of the plain prediction (noise scale)
constexpr std::size_t wide = 3;    // neighbours each side of the robust prediction
constexpr double min_offset_m = 2.5;
constexpr double scale_factor = 5.0;
constexpr int robust_rounds = 3;
constexpr double max_scale_span_m = 150.0; // of the four neighbours a node's scale residual comes from

// `each` neighbours of i on each side; next to a chain end, as many as there
// are on that side (at least one) and the rest from the other.
std::optional<std::vector<std::size_t>> neighbours(std::size_t n, std::size_t i, std::size_t each) {
    if (i == 0 || i + 1 >= n || n < 2 * each + 1) {
        return std::nullopt;
    }
    const std::size_t before = std::min(each, i), after = std::min(each, n - 1 - i);
    const std::size_t lo = i - std::min(i, before + (each - after)), hi = std::min(n - 1, i + after + (each - before));
    std::vector<std::size_t> nb;
    for (std::size_t j = lo; j <= hi; ++j) {
        if (j != i) {
            nb.push_back(j);
        }
    }
    return nb;
}

// Offset of p[i] across the weighted least-squares quadratic (in chainage t)
// through its neighbours, divided by sqrt(1 + h), h the prediction's
// leverage: a node far from clustered neighbours is predicted by
// extrapolating their noise, and its offset counts for that much less (a
// studentised residual, in metres of node scatter).
double offset_from(const std::vector<Point2>& p, const std::vector<double>& t, const std::vector<std::size_t>& nb,
                   const std::vector<double>& w, std::size_t i) {
    // Weighted sums for x(u) and y(u), u = t - t_i, on 1, u, u^2.
    double s[5] = {0, 0, 0, 0, 0}, bx[3] = {0, 0, 0}, by[3] = {0, 0, 0};
    for (const std::size_t j : nb) {
        const double u = (t[j] - t[i]) / 100.0; // scaled: well conditioned
        double up = w[j];
        for (int k = 0; k < 5; ++k, up *= u) {
            s[k] += up;
            if (k < 3) {
                bx[k] += up * p[j].x;
                by[k] += up * p[j].y;
            }
        }
    }
    const double m[3][3] = {{s[0], s[1], s[2]}, {s[1], s[2], s[3]}, {s[2], s[3], s[4]}};
    auto det3 = [](const double a[3][3]) {
        return a[0][0] * (a[1][1] * a[2][2] - a[1][2] * a[2][1]) - a[0][1] * (a[1][0] * a[2][2] - a[1][2] * a[2][0]) +
               a[0][2] * (a[1][0] * a[2][1] - a[1][1] * a[2][0]);
    };
    const double d = det3(m);
    if (std::abs(d) < 1e-12) {
        return 0.0; // too few weighted neighbours to predict it: no evidence either way
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
// throughout, and is no outlier however badly a quadratic predicts it. Two
// nodes pulled aside together (a bump) turn one way at both and the other
// way at the nodes around them. Judged on the polyline through the nodes not
// marked: the run (i and the `run - 1` kept nodes after it), two kept nodes
// on each side of it.
bool spike_among_kept(const std::vector<Point2>& p, const std::vector<bool>& gone, std::size_t i, std::size_t run) {
    std::vector<Point2> q;
    std::size_t before = 0;
    for (std::size_t j = i; j > 0 && before < 2;) {
        --j;
        if (!gone[j]) {
            q.insert(q.begin(), p[j]);
            ++before;
        }
    }
    std::size_t in_run = 0, after = 0;
    for (std::size_t j = i; j < p.size() && after < 2; ++j) {
        if (gone[j]) {
            continue;
        }
        q.push_back(p[j]);
        if (in_run < run) {
            ++in_run;
        } else {
            ++after;
        }
    }
    // Next to a chain end a curve's exit between sparse nodes turns the same
    // way as an outlier there would: no call either way.
    if (before < 2 || after < 2 || in_run < run) {
        return false;
    }
    const std::size_t first = before, last = before + run - 1;
    const double here = turn(q, first);
    for (std::size_t k = first + 1; k <= last; ++k) {
        if (here * turn(q, k) <= 0.0) {
            return false;
        }
    }
    return here * turn(q, first - 1) < 0.0 && here * turn(q, last + 1) < 0.0;
}

// The kept node after i, or n.
std::size_t next_kept(const std::vector<bool>& gone, std::size_t i) {
    for (std::size_t j = i + 1; j < gone.size(); ++j) {
        if (!gone[j]) {
            return j;
        }
    }
    return gone.size();
}

// Tukey's biweight: full weight within a few scales, none beyond `limit`.
double biweight(double r, double limit) {
    const double u = r / limit;
    return u >= 1.0 ? 0.0 : (1.0 - u * u) * (1.0 - u * u);
}

} // namespace

double median(std::vector<double> v) {
    if (v.empty()) {
        return 0.0;
    }
    const auto mid = v.begin() + static_cast<std::ptrdiff_t>(v.size() / 2);
    std::nth_element(v.begin(), mid, v.end());
    return *mid;
}

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
    // The noise scale from the plain prediction (two neighbours each side).
    std::vector<double> w(n, 1.0), tested;
    for (std::size_t i = side; i + side < n; ++i) {
        // Only where the neighbours are close: across sparse nodes a quadratic
        // misses the curvature's own change (a transition) by more than the
        // scatter, and the scale would measure the track, not the mapping.
        if (t[i + side] - t[i - side] <= max_scale_span_m) {
            tested.push_back(offset_from(p, t, *neighbours(n, i, side), w, i));
        }
    }
    scan.noise_sigma_m = 1.4826 * median(tested);
    scan.tested = tested.size();
    const double limit = std::max(min_offset_m, scale_factor * scan.noise_sigma_m);
    // Robust prediction from three neighbours each side, re-weighted by each
    // node's own residual (as in robust LOWESS): two outliers a node apart no
    // longer spoil each other's prediction, nor their good neighbours'.
    std::vector<double> r(n, 0.0);
    for (int round = 0; round < robust_rounds; ++round) {
        for (std::size_t i = 0; i < n; ++i) {
            auto nb = neighbours(n, i, wide);
            if (!nb) {
                nb = neighbours(n, i, side);
            }
            r[i] = nb ? offset_from(p, t, *nb, w, i) : 0.0;
        }
        for (std::size_t i = 0; i < n; ++i) {
            w[i] = biweight(r[i], limit);
        }
    }
    // Worst first; a spike is judged against the nodes still kept, so that
    // of two outliers a node apart the second is a spike once the first is gone.
    // Two far nodes side by side go together where they make a bump.
    while (true) {
        std::size_t worst = n, partner = n;
        for (std::size_t i = 1; i + 1 < n; ++i) {
            if (scan.outlier[i] || r[i] <= limit || (worst < n && r[i] <= r[worst])) {
                continue;
            }
            const std::size_t k = next_kept(scan.outlier, i);
            if (spike_among_kept(p, scan.outlier, i, 1)) {
                worst = i;
                partner = n;
            } else if (k + 1 < n && r[k] > limit && spike_among_kept(p, scan.outlier, i, 2)) {
                worst = i;
                partner = k;
            }
        }
        if (worst == n) {
            break;
        }
        scan.outlier[worst] = true;
        if (partner < n) {
            scan.outlier[partner] = true;
        }
    }
    return scan;
}

} // namespace railodd::geometry::fit
