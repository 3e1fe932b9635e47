#include "robust_fit.hpp"

#include <algorithm>
#include <cmath>

namespace railodd::geometry::vertical {

namespace {

constexpr double huber_k = 1.5;    // in units of sigma
constexpr double tukey_c = 4.685;  // 95 % efficiency under Gaussian noise

std::vector<double> residuals(const HermiteKnots& k, const SplineData& d) {
    std::vector<double> r;
    r.reserve(d.s.size());
    for (std::size_t i = 0; i < d.s.size(); ++i) {
        r.push_back(d.z[i] - evaluate(k, d.s[i]));
    }
    return r;
}

// 1.4826 * median |r|: the standard deviation for Gaussian residuals, blind
// to the outliers it is meant to find.
double mad_sigma(std::vector<double> r) {
    for (double& v : r) {
        v = std::abs(v);
    }
    const auto mid = r.begin() + static_cast<std::ptrdiff_t>(r.size() / 2);
    std::nth_element(r.begin(), mid, r.end());
    return 1.4826 * *mid;
}

double huber(double r, double sigma) {
    const double k = huber_k * sigma;
    return std::abs(r) <= k ? 1.0 : k / std::abs(r);
}

double tukey(double r, double sigma) {
    const double u = r / (tukey_c * sigma);
    return std::abs(u) < 1.0 ? (1.0 - u * u) * (1.0 - u * u) : 0.0;
}

// Whether the weighted data still pin down a spline: two distinct places.
bool determined(const SplineData& d) {
    double first = 0.0;
    bool seen = false;
    for (std::size_t i = 0; i < d.s.size(); ++i) {
        if (d.w[i] > 0.0) {
            if (seen && d.s[i] != first) {
                return true;
            }
            first = seen ? first : d.s[i];
            seen = true;
        }
    }
    return false;
}

} // namespace

RobustFit fit_robust(const SplineData& data, const std::vector<bool>& adjustable, double length,
                     double knot_spacing, double smoothing_length, const RobustOptions& options) {
    RobustFit fit;
    fit.knots = fit_hermite_spline(data, length, knot_spacing, smoothing_length);
    fit.weights.assign(data.s.size(), 1.0);
    if (std::find(adjustable.begin(), adjustable.end(), true) == adjustable.end()) {
        return fit;
    }
    fit.sigma = std::max(options.sigma_floor, mad_sigma(residuals(fit.knots, data)));
    const int total = options.huber_iterations + options.tukey_iterations;
    for (int it = 0; it < total; ++it) {
        const auto r = residuals(fit.knots, data);
        SplineData reweighted = data;
        std::vector<double> weights(r.size());
        for (std::size_t i = 0; i < r.size(); ++i) {
            weights[i] = !adjustable[i]                  ? 1.0
                         : it < options.huber_iterations ? huber(r[i], fit.sigma)
                                                         : tukey(r[i], fit.sigma);
            reweighted.w[i] = data.w[i] * weights[i];
        }
        if (!determined(reweighted)) {
            break; // everything rejected: keep the last fit that had data
        }
        fit.knots = fit_hermite_spline(reweighted, length, knot_spacing, smoothing_length);
        fit.weights = std::move(weights);
    }
    return fit;
}

} // namespace railodd::geometry::vertical
