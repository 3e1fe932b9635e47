#pragma once
// The cost of one design hypothesis as a quadratic in the state at the start
// of its current element, and the exact moves of the design search
// (design_dp.cpp) on it: a node's residual is one rank-1 update, a knot
// carries the cost to the knot's state and opens the next element.
//
// State coordinates are scaled to metres at S = 100 m so that the 4 x 4
// systems are well conditioned: (z, z' S, k S^2, g S^3), g the element's
// curvature slope. An element constrains some of them to zero (a line: k
// and g; an arc: g; a transition leaving a line: k); those are not
// variables (`free`), so every constraint is exact.
#include "design_dp.hpp"

#include <Eigen/Dense>

namespace railodd::geometry::fit::design {

constexpr double S = 100.0;

using Mat4 = Eigen::Matrix4d;
using Vec4 = Eigen::Vector4d;

struct Quad {
    Mat4 P = Mat4::Zero();
    Vec4 q = Vec4::Zero();
    double c = 0.0;
    unsigned free = 0; // bit i: coordinate i is a variable
};

// How a knot was crossed, enough to recover the element's start state from
// the state at the knot (backtracking).
struct KnotMap {
    unsigned free = 0; // of the element ended there
    double length = 0.0; // scaled
    Vec4 p3 = Vec4::Zero(); // a transition with free start: row 3 of its cost at the knot, before g was eliminated
    double q3 = 0.0;
};

// The flow of the state along an element over scaled length u.
Mat4 flow(double u);

// A fresh element's cost with only a tiny ridge on its variables.
Quad empty_quad(unsigned free);

// Adds w (target - h.x)^2 for the variables of f.
void add_row(Quad& f, const Vec4& h, double w, double target);

// A node at scaled distance u from the element's start.
inline Vec4 node_row(double u) { return {1.0, u, 0.5 * u * u, u * u * u / 6.0}; }

// Adds weight * integral of k^2 ds over the element's scaled stretch [a, b].
void add_curvature(Quad& f, double a, double b, double weight);

// Adds w (x_i - target_i)^2 for i < 3 (position, heading, curvature): a
// tie (a non-variable coordinate adds its constant mismatch).
void add_tie(Quad& f, const Vec4& target, double w);

// Minimum of f over its variables; the minimiser in *arg (zeros elsewhere).
double minimum(const Quad& f, Vec4* arg = nullptr);

// The element's cost carried to the knot at scaled length u: a quadratic in
// the knot's state (z, z' S, k S^2); the curvature slope minimised out.
Quad to_knot(const Quad& f, double u, KnotMap* map = nullptr);

// Start state of the element from the state at its end knot.
Vec4 start_from_knot(const KnotMap& map, const Vec4& knot_state);

// Opens an element of `kind` at a knot with the cost `knot`; false where
// the design rules forbid it there (an arc needs a free curvature).
// `after_transition`: a transition following another meets it at zero
// curvature (a reverse curve's inflection).
bool open_element(Quad& knot, ElementKind kind, bool after_transition);

// Free coordinates of the first element of a design.
unsigned first_free(ElementKind kind);

// Adds b to a; a coordinate that is no variable in either is none in the sum.
void add_quad(Quad& a, const Quad& b);

// Coordinate i fixed at zero.
void fix_zero(Quad& f, int i);

} // namespace railodd::geometry::fit::design
