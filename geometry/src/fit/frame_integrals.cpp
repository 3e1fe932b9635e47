#include "frame_integrals.hpp"

#include <algorithm>

namespace railodd::geometry::fit {

ReferenceHeading::ReferenceHeading(const Frame& f) : f_(f), integral_(f.hdg.size(), 0.0) {
    for (std::size_t k = 1; k < f.hdg.size(); ++k) {
        integral_[k] = integral_[k - 1] + f.h * (0.5 * (f.hdg[k - 1] + f.hdg[k]) - f.hdg[0]);
    }
}

ReferenceHeading::At ReferenceHeading::at(double s) const {
    const std::vector<double>& g = f_.hdg;
    const std::size_t last = g.size() - 1;
    if (s <= 0.0) {
        return {g[0], 0.0};
    }
    const std::size_t k = std::min(last - 1, static_cast<std::size_t>(s / f_.h));
    const double t = s - f_.h * static_cast<double>(k);
    if (t > f_.h) {
        const double beyond = s - f_.h * static_cast<double>(last);
        return {g[last], integral_[last] + (g[last] - g[0]) * beyond};
    }
    const double slope = (g[k + 1] - g[k]) / f_.h;
    return {g[k] + slope * t, integral_[k] + (g[k] - g[0]) * t + 0.5 * slope * t * t};
}

HatIntegrals hat_integrals(const std::vector<double>& l, const std::vector<double>& s) {
    const std::size_t m = l.size();
    std::vector<double> knot(m + 1, 0.0);
    for (std::size_t j = 0; j < m; ++j) {
        knot[j + 1] = knot[j] + l[j];
    }
    const auto rows = static_cast<Eigen::Index>(s.size()), cols = static_cast<Eigen::Index>(m + 1);
    HatIntegrals h{Eigen::MatrixXd::Zero(rows, cols), Eigen::MatrixXd::Zero(rows, cols)};
    std::size_t j = 0;
    for (std::size_t i = 0; i < s.size(); ++i) {
        while (j < m && knot[j + 1] <= s[i]) {
            ++j;
        }
        const auto row = static_cast<Eigen::Index>(i);
        for (std::size_t k = 0; k < j; ++k) { // hats wholly behind s
            const double left = k > 0 ? l[k - 1] : 0.0, right = l[k], d = s[i] - knot[k];
            h.left(row, static_cast<Eigen::Index>(k)) = d * left / 2 + left * left / 6;
            h.right(row, static_cast<Eigen::Index>(k)) = d * right / 2 - right * right / 6;
        }
        const double t = s[i] - knot[j];
        const auto col = static_cast<Eigen::Index>(j);
        h.left(row, col) = j > 0 ? t * l[j - 1] / 2 + l[j - 1] * l[j - 1] / 6 : 0.0;
        if (j < m) {
            h.right(row, col) = t * t / 2 - t * t * t / (6 * l[j]);
            h.left(row, col + 1) = t * t * t / (6 * l[j]);
        } else {
            h.right(row, col) = t * t / 2; // constant beyond the end
        }
    }
    return h;
}

} // namespace railodd::geometry::fit
