#include "hermite_spline.hpp"

#include <Eigen/Dense>
#include <Eigen/Sparse>

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace railodd::geometry::vertical {

namespace {

// Unknowns per knot k: z_k at 2k and p_k = h * m_k at 2k + 1. Scaling the
// slope by the knot spacing gives both unknowns the unit of metres, which
// keeps the normal equations well conditioned.
using Matrix4 = Eigen::Matrix4d;
using Vector4 = Eigen::Vector4d;

// Hermite basis at t in [0, 1] for (z_k, p_k, z_k+1, p_k+1).
Vector4 basis(double t) {
    const double t2 = t * t;
    const double t3 = t2 * t;
    return {2 * t3 - 3 * t2 + 1, t3 - 2 * t2 + t, -2 * t3 + 3 * t2, t3 - t2};
}

// integral over one interval of z''(s)^2 ds, as a quadratic form in the
// scaled unknowns: the Euler-Bernoulli beam element, divided by h^3.
Matrix4 bending(double h) {
    Matrix4 k;
    k << 12, 6, -12, 6, //
        6, 4, -6, 2,    //
        -12, -6, 12, -6, //
        6, 2, -6, 4;
    return k / (h * h * h);
}

struct Grid {
    int intervals;
    double h;

    int interval(double s) const {
        return std::clamp(static_cast<int>(std::floor(s / h)), 0, intervals - 1);
    }
};

void check(const SplineData& d) {
    if (d.s.size() != d.z.size() || d.s.size() != d.w.size()) {
        throw std::invalid_argument("hermite spline: s, z and w differ in size");
    }
    if (d.s.size() < 2 || !(d.s.back() > d.s.front())) {
        throw std::invalid_argument("hermite spline: needs data at two distinct s at least");
    }
}

} // namespace

HermiteKnots fit_hermite_spline(const SplineData& data, double length, double knot_spacing,
                                double smoothing_length) {
    check(data);
    const int intervals = std::max(1, static_cast<int>(std::lround(length / knot_spacing)));
    const Grid grid{intervals, length / intervals};
    const int unknowns = 2 * (intervals + 1);

    double wsum = 0.0;
    double zref = 0.0;
    for (std::size_t i = 0; i < data.z.size(); ++i) {
        wsum += data.w[i];
        zref += data.w[i] * data.z[i];
    }
    zref /= wsum; // fitting around the mean keeps a, c and d free of cancellation

    std::vector<Matrix4> blocks(static_cast<std::size_t>(intervals), Matrix4::Zero());
    Eigen::VectorXd rhs = Eigen::VectorXd::Zero(unknowns);
    for (std::size_t i = 0; i < data.s.size(); ++i) {
        const int k = grid.interval(data.s[i]);
        const Vector4 b = basis((data.s[i] - k * grid.h) / grid.h);
        blocks[static_cast<std::size_t>(k)] += data.w[i] * b * b.transpose();
        rhs.segment<4>(2 * k) += data.w[i] * (data.z[i] - zref) * b;
    }
    const double lambda = std::pow(smoothing_length, 4);
    const Matrix4 penalty = lambda * bending(grid.h);
    std::vector<Eigen::Triplet<double>> triplets;
    triplets.reserve(static_cast<std::size_t>(intervals) * 16);
    for (int k = 0; k < intervals; ++k) {
        const Matrix4 block = blocks[static_cast<std::size_t>(k)] + penalty;
        for (int r = 0; r < 4; ++r) {
            for (int c = 0; c < 4; ++c) {
                triplets.emplace_back(2 * k + r, 2 * k + c, block(r, c));
            }
        }
    }
    Eigen::SparseMatrix<double> normal(unknowns, unknowns);
    normal.setFromTriplets(triplets.begin(), triplets.end());
    // Natural ordering: the matrix is banded (7 wide), so it factors without fill-in.
    Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>, Eigen::Lower, Eigen::NaturalOrdering<int>> solver(normal);
    if (solver.info() != Eigen::Success) {
        throw std::invalid_argument("hermite spline: normal equations are singular");
    }
    const Eigen::VectorXd x = solver.solve(rhs);

    HermiteKnots knots;
    for (int k = 0; k <= intervals; ++k) {
        knots.s.push_back(k == intervals ? length : k * grid.h);
        knots.z.push_back(zref + x(2 * k));
        knots.m.push_back(x(2 * k + 1) / grid.h);
    }
    return knots;
}

double evaluate(const HermiteKnots& knots, double s) {
    const auto it = std::upper_bound(knots.s.begin() + 1, knots.s.end() - 1, s);
    const auto k = static_cast<std::size_t>(it - knots.s.begin()) - 1;
    const double h = knots.s[k + 1] - knots.s[k];
    const Vector4 b = basis((s - knots.s[k]) / h);
    return b(0) * knots.z[k] + b(1) * h * knots.m[k] + b(2) * knots.z[k + 1] + b(3) * h * knots.m[k + 1];
}

std::vector<ElevationPoly> to_polys(const HermiteKnots& knots) {
    std::vector<ElevationPoly> polys;
    for (std::size_t k = 0; k + 1 < knots.s.size(); ++k) {
        const double h = knots.s[k + 1] - knots.s[k];
        const double secant = (knots.z[k + 1] - knots.z[k]) / h;
        const double m0 = knots.m[k];
        const double m1 = knots.m[k + 1];
        polys.push_back({knots.s[k], knots.z[k], m0, (3.0 * secant - 2.0 * m0 - m1) / h,
                         (m0 + m1 - 2.0 * secant) / (h * h)});
    }
    return polys;
}

} // namespace railodd::geometry::vertical
