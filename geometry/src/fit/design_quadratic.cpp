#include "design_quadratic.hpp"

#include <array>
#include <cmath>

namespace railodd::geometry::fit::design {

namespace {

// Keeps every variable's system positive definite before data reaches it
// (a fresh transition's slope): 1e-10 of a squared metre.
constexpr double ridge = 1e-10;

int variables(unsigned free, int* idx) {
    int d = 0;
    for (int i = 0; i < 4; ++i) {
        if (free & (1u << i)) {
            idx[d++] = i;
        }
    }
    return d;
}

// The mask of each set of free coordinates, as a vector of ones and zeros.
const Vec4& mask(unsigned free) {
    static const auto table = [] {
        std::array<Vec4, 16> t;
        for (unsigned m = 0; m < 16; ++m) {
            for (int i = 0; i < 4; ++i) {
                t[m](i) = (m & (1u << i)) ? 1.0 : 0.0;
            }
        }
        return t;
    }();
    return table[free & 15u];
}

// Coordinate i is no variable any more: fixed at zero.
void restrict_to_zero(Quad& f, int i) {
    f.P.row(i).setZero();
    f.P.col(i).setZero();
    f.q(i) = 0.0;
    f.free &= ~(1u << i);
}

// The inverse of the leading d x d block of an upper triangular matrix, by
// back substitution (zero elsewhere): Eigen's triangular solve takes its
// blocked path even for a fixed 4 x 4, and to_knot inverts once per parent
// at every knot.
template <int D>
void upper_inverse(const double (&M)[4][4], double (&X)[4][4]) {
    for (int i = D - 1; i >= 0; --i) {
        X[i][i] = 1.0 / M[i][i];
        for (int j = i + 1; j < D; ++j) {
            double v = 0.0;
            for (int k = i + 1; k <= j; ++k) {
                v += M[i][k] * X[k][j];
            }
            X[i][j] = -v * X[i][i];
        }
    }
}

// X = M^-1 for the map M of an element's d start variables (cols) onto the
// first d coordinates of its state at scaled length u: the flow's rows and
// those columns, upper triangular (a line ends at zero curvature, so its
// knot has two coordinates; an arc or a transition leaving a line three).
// Returns d.
int knot_map_inverse(double u, unsigned free, int* cols, double (&X)[4][4]) {
    const int d = variables(free, cols);
    const Mat4 F = flow(u);
    double M[4][4] = {};
    for (int i = 0; i < d; ++i) {
        for (int j = 0; j < d; ++j) {
            M[i][j] = F(i, cols[j]);
        }
    }
    if (d == 2) {
        upper_inverse<2>(M, X);
    } else {
        upper_inverse<3>(M, X);
    }
    return d;
}

// The cost in the knot's state from the cost in d start variables: X' P X
// and X' q for X = knot_map_inverse, on the d x d block only (the padded
// 4 x 4 Eigen products were a tenth of the fit). The sums run in the order
// those products took (terms two apart paired first where Eigen read X' by
// rows as packets, in turn elsewhere): designs are unchanged to the bit,
// checked on 200,000 random costs.
template <int D>
void to_knot_triangular(const double (&X)[4][4], const Quad& f, const int* cols, Quad& g) {
    double A[4][4]; // X' P
    for (int i = 0; i < D; ++i) {
        for (int j = 0; j < D; ++j) {
            const auto t = [&](int k) { return k < D ? X[k][i] * f.P(cols[k], cols[j]) : 0.0; };
            A[i][j] = (t(0) + t(2)) + (t(1) + t(3));
        }
    }
    for (int i = 0; i < D; ++i) {
        for (int j = 0; j < D; ++j) {
            double v = A[i][0] * X[0][j];
            for (int k = 1; k < D; ++k) {
                v += A[i][k] * X[k][j];
            }
            g.P(i, j) = v;
        }
        const auto t = [&](int k) { return k < D ? X[k][i] * f.q(cols[k]) : 0.0; };
        g.q(i) = (t(0) + t(2)) + (t(1) + t(3));
    }
}

template <int D>
double minimum_of(const Quad& f, const int* idx, Vec4* arg) {
    double a[4][4], b[4];
    for (int i = 0; i < D; ++i) {
        b[i] = f.q(idx[i]);
        for (int j = 0; j <= i; ++j) {
            a[i][j] = f.P(idx[i], idx[j]);
        }
    }
    double inv[4] = {}; // 1 / L(i, i); a keeps L below its diagonal
    for (int i = 0; i < D; ++i) {
        for (int j = 0; j <= i; ++j) {
            double v = a[i][j];
            for (int k = 0; k < j; ++k) {
                v -= a[i][k] * a[j][k];
            }
            if (i == j) {
                // Semidefinite: that direction costs nothing.
                inv[i] = v > 0.0 ? 1.0 / std::sqrt(v) : 1.0 / std::sqrt(1e-300);
            } else {
                a[i][j] = v * inv[j];
            }
        }
    }
    double x[4];
    for (int i = 0; i < D; ++i) {
        double v = b[i];
        for (int k = 0; k < i; ++k) {
            v -= a[i][k] * x[k];
        }
        x[i] = v * inv[i];
    }
    // value = c - b' P^-1 b = c - |L^-1 b|^2
    double value = f.c;
    for (int i = 0; i < D; ++i) {
        value -= x[i] * x[i];
    }
    if (arg) {
        for (int i = D; i-- > 0;) {
            double v = x[i];
            for (int k = i + 1; k < D; ++k) {
                v -= a[k][i] * x[k];
            }
            x[i] = v * inv[i];
        }
        arg->setZero();
        for (int i = 0; i < D; ++i) {
            (*arg)(idx[i]) = x[i];
        }
    }
    return value;
}

} // namespace

Mat4 flow(double u) {
    Mat4 F;
    F << 1.0, u, 0.5 * u * u, u * u * u / 6.0, //
        0.0, 1.0, u, 0.5 * u * u,              //
        0.0, 0.0, 1.0, u,                      //
        0.0, 0.0, 0.0, 1.0;
    return F;
}

Quad empty_quad(unsigned free) {
    Quad f;
    f.free = free;
    for (int i = 0; i < 4; ++i) {
        if (free & (1u << i)) {
            f.P(i, i) = ridge;
        }
    }
    return f;
}

void add_row(Quad& f, const Vec4& h, double w, double target) {
    const Vec4 m = h.cwiseProduct(mask(f.free));
    f.P.noalias() += (w * m) * m.transpose();
    f.q += (w * target) * m;
    f.c += w * target * target;
}

void add_curvature(Quad& f, double a, double b, double weight) {
    // k = (x2 + x3 u) / S^2 and ds = S du: integral of k^2 ds is
    // (x2^2 (b-a) + x2 x3 (b^2-a^2) + x3^2 (b^3-a^3)/3) / S^3.
    const double w = weight / (S * S * S);
    if (f.free & 4u) {
        f.P(2, 2) += w * (b - a);
    }
    if ((f.free & 4u) && (f.free & 8u)) {
        f.P(2, 3) += w * 0.5 * (b * b - a * a);
        f.P(3, 2) += w * 0.5 * (b * b - a * a);
    }
    if (f.free & 8u) {
        f.P(3, 3) += w * (b * b * b - a * a * a) / 3.0;
    }
}

void add_tie(Quad& f, const Vec4& target, double w) {
    for (int i = 0; i < 3; ++i) {
        if (f.free & (1u << i)) {
            f.P(i, i) += w;
            f.q(i) += w * target(i);
        }
        f.c += w * target(i) * target(i);
    }
}

double minimum(const Quad& f, Vec4* arg) {
    // Cholesky of the free block, at most 4 x 4, by hand on a packed copy
    // (sized at compile time, so the loops unroll): the search calls this
    // once per live hypothesis and node.
    int idx[4];
    switch (variables(f.free, idx)) {
    case 0:
        return minimum_of<0>(f, idx, arg);
    case 1:
        return minimum_of<1>(f, idx, arg);
    case 2:
        return minimum_of<2>(f, idx, arg);
    case 3:
        return minimum_of<3>(f, idx, arg);
    default:
        return minimum_of<4>(f, idx, arg);
    }
}

Quad to_knot(const Quad& f, double u, KnotMap* map) {
    Quad g;
    if (map) {
        map->free = f.free;
        map->length = u;
    }
    if (f.free == 15u) {
        // Every start coordinate free: (knot state, g) is the start state
        // moved by an invertible flow; then g is minimised out (Schur).
        const Mat4 Fi = flow(-u);
        const Mat4 P1 = Fi.transpose() * f.P * Fi;
        const Vec4 q1 = Fi.transpose() * f.q;
        const double p33 = P1(3, 3);
        g.P.topLeftCorner<3, 3>() = P1.topLeftCorner<3, 3>() - P1.block<3, 1>(0, 3) * P1.block<1, 3>(3, 0) / p33;
        g.q.head<3>() = q1.head<3>() - P1.block<3, 1>(0, 3) * (q1(3) / p33);
        g.c = f.c - q1(3) * q1(3) / p33;
        g.free = 7u;
        if (map) {
            map->p3 = P1.row(3).transpose();
            map->q3 = q1(3);
        }
        return g;
    }
    // d variables map one to one onto the first d knot coordinates.
    int cols[4];
    double X[4][4] = {};
    const int d = knot_map_inverse(u, f.free, cols, X);
    if (d == 2) {
        to_knot_triangular<2>(X, f, cols, g);
    } else {
        to_knot_triangular<3>(X, f, cols, g);
    }
    g.c = f.c;
    g.free = d == 2 ? 3u : 7u;
    return g;
}

Vec4 start_from_knot(const KnotMap& map, const Vec4& y) {
    if (map.free == 15u) {
        Vec4 end = y;
        end(3) = (map.q3 - map.p3.head<3>().dot(y.head<3>())) / map.p3(3);
        return flow(-map.length) * end;
    }
    int cols[4];
    double X[4][4] = {};
    const int d = knot_map_inverse(map.length, map.free, cols, X);
    Vec4 x = Vec4::Zero();
    for (int i = 0; i < d; ++i) {
        double v = X[i][0] * y(0);
        for (int k = 1; k < d; ++k) {
            v += X[i][k] * y(k);
        }
        x(cols[i]) = v;
    }
    return x;
}

bool open_element(Quad& f, ElementKind kind, bool after_transition) {
    switch (kind) {
    case ElementKind::line:
        if (f.free & 4u) {
            restrict_to_zero(f, 2);
        }
        return true;
    case ElementKind::arc:
        return (f.free & 4u) != 0;
    case ElementKind::transition:
        if (after_transition && (f.free & 4u)) {
            restrict_to_zero(f, 2);
        }
        f.free |= 8u;
        f.P(3, 3) = ridge;
        return true;
    }
    return false;
}

void add_quad(Quad& a, const Quad& b) {
    a.P += b.P;
    a.q += b.q;
    a.c += b.c;
    const unsigned both = a.free & b.free;
    for (int i = 0; i < 4; ++i) {
        if ((a.free & (1u << i)) && !(both & (1u << i))) {
            restrict_to_zero(a, i);
        }
    }
    a.free = both;
}

void fix_zero(Quad& f, int i) {
    if (f.free & (1u << i)) {
        restrict_to_zero(f, i);
    }
}

unsigned first_free(ElementKind kind) {
    switch (kind) {
    case ElementKind::line:
        return 3u;
    case ElementKind::arc:
        return 7u;
    case ElementKind::transition:
        return 15u;
    }
    return 0u;
}

} // namespace railodd::geometry::fit::design
