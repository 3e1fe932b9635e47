#include "gradient_stats.hpp"

#include <algorithm>
#include <cmath>

namespace railodd::geometry::vertical {

namespace {

double slope(const ElevationPoly& p, double t) { return p.b + t * (2.0 * p.c + 3.0 * p.d * t); }

double end_of(const std::vector<ElevationPoly>& polys, std::size_t k, double length) {
    return k + 1 < polys.size() ? polys[k + 1].s : length;
}

// The steepest slope (signed) of p on [t0, t1]: at an end or at the vertex of
// the quadratic.
double steepest(const ElevationPoly& p, double t0, double t1) {
    double best = slope(p, t0);
    auto consider = [&](double t) {
        const double g = slope(p, t);
        if (std::abs(g) > std::abs(best)) {
            best = g;
        }
    };
    consider(t1);
    if (p.d != 0.0) {
        const double vertex = -p.c / (3.0 * p.d);
        if (vertex > t0 && vertex < t1) {
            consider(vertex);
        }
    }
    return best;
}

// Roots in (0, h) of slope(p, t) = level.
void crossings(const ElevationPoly& p, double level, double h, std::vector<double>& out) {
    const double qa = 3.0 * p.d;
    const double qb = 2.0 * p.c;
    const double qc = p.b - level;
    auto keep = [&](double t) {
        if (t > 0.0 && t < h) {
            out.push_back(t);
        }
    };
    if (std::abs(qa) * h < 1e-12 * (std::abs(qb) + 1e-300)) {
        if (qb != 0.0) {
            keep(-qc / qb);
        }
        return;
    }
    const double disc = qb * qb - 4.0 * qa * qc;
    if (disc < 0.0) {
        return;
    }
    // The cancellation-free pair of quadratic roots.
    const double q = -0.5 * (qb + std::copysign(std::sqrt(disc), qb));
    if (q != 0.0) {
        keep(qc / q);
    }
    keep(q / qa);
}

} // namespace

double max_abs_gradient(const std::vector<ElevationPoly>& polys, double length) {
    double best = 0.0;
    for (std::size_t k = 0; k < polys.size(); ++k) {
        const double h = std::max(0.0, end_of(polys, k, length) - polys[k].s);
        best = std::max(best, std::abs(steepest(polys[k], 0.0, h)));
    }
    return best;
}

std::vector<SteepStretch> steep_stretches(const std::vector<ElevationPoly>& polys, double length,
                                          double threshold) {
    std::vector<SteepStretch> out;
    for (std::size_t k = 0; k < polys.size(); ++k) {
        const ElevationPoly& p = polys[k];
        const double h = std::max(0.0, end_of(polys, k, length) - p.s);
        std::vector<double> cuts{0.0, h};
        crossings(p, threshold, h, cuts);
        crossings(p, -threshold, h, cuts);
        std::sort(cuts.begin(), cuts.end());
        for (std::size_t i = 0; i + 1 < cuts.size(); ++i) {
            const double t0 = cuts[i];
            const double t1 = cuts[i + 1];
            if (!(t1 > t0) || std::abs(slope(p, 0.5 * (t0 + t1))) <= threshold) {
                continue;
            }
            const double g = 1000.0 * steepest(p, t0, t1);
            if (!out.empty() && std::abs(out.back().s_end - (p.s + t0)) < 1e-9) {
                out.back().s_end = p.s + t1; // continues across a joint
                if (std::abs(g) > std::abs(out.back().gradient_permille)) {
                    out.back().gradient_permille = g;
                }
            } else {
                out.push_back({p.s + t0, p.s + t1, g});
            }
        }
    }
    return out;
}

} // namespace railodd::geometry::vertical
