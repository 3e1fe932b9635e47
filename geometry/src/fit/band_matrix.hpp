#pragma once
// A symmetric positive definite band matrix, assembled from weighted rows
// and solved by Cholesky in O(n B^2): the trend filter's normal equations
// (curvature_trend.cpp), whose rows each touch at most five neighbouring
// grid points.
#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <vector>

namespace railodd::geometry::fit {

// A symmetric positive definite band matrix (half bandwidth B), factorised
// in place by Cholesky: O(n B^2), the whole window's grid at once.
class BandMatrix {
public:
    static constexpr std::size_t B = 4;
    explicit BandMatrix(std::size_t n) : n_(n), a_(n * (B + 1), 0.0) {}
    // Adds w * row^T row for a row with entries v at columns c.
    template <std::size_t N>
    void add(const std::array<std::size_t, N>& c, const std::array<double, N>& v, double w, double target,
             std::vector<double>& rhs) {
        for (std::size_t i = 0; i < N; ++i) {
            rhs[c[i]] += w * v[i] * target;
            for (std::size_t j = 0; j < N; ++j) {
                if (c[j] <= c[i]) {
                    at(c[i], c[i] - c[j]) += w * v[i] * v[j];
                }
            }
        }
    }
    void add_diagonal(double d) {
        for (std::size_t i = 0; i < n_; ++i) {
            at(i, 0) += d;
        }
    }
    // Solves A x = b (b overwritten by x); false where A is not positive definite.
    bool solve(std::vector<double>& b) {
        for (std::size_t i = 0; i < n_; ++i) {
            for (std::size_t d = std::min(i, B); d > 0; --d) { // L(i, i-d)
                const std::size_t j = i - d;
                double s = at(i, d);
                for (std::size_t k = 1; k + d <= B && k <= j; ++k) {
                    s -= at(i, d + k) * at(j, k);
                }
                at(i, d) = s / at(j, 0);
            }
            double s = at(i, 0);
            for (std::size_t d = 1; d <= std::min(i, B); ++d) {
                s -= at(i, d) * at(i, d);
            }
            if (!(s > 0.0)) {
                return false;
            }
            at(i, 0) = std::sqrt(s);
        }
        for (std::size_t i = 0; i < n_; ++i) {
            double s = b[i];
            for (std::size_t d = 1; d <= std::min(i, B); ++d) {
                s -= at(i, d) * b[i - d];
            }
            b[i] = s / at(i, 0);
        }
        for (std::size_t i = n_; i-- > 0;) {
            double s = b[i];
            for (std::size_t d = 1; d <= B && i + d < n_; ++d) {
                s -= at(i + d, d) * b[i + d];
            }
            b[i] = s / at(i, 0);
        }
        return true;
    }

private:
    double& at(std::size_t row, std::size_t d) { return a_[row * (B + 1) + d]; } // entry (row, row - d)
    std::size_t n_;
    std::vector<double> a_;
};

} // namespace railodd::geometry::fit
