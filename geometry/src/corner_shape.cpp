// The symmetric clothoid corner. Its shape depends only on the deflection;
// everything else scales with one factor (lengths up, curvature down), so the
// shape is measured once at unit curvature and then sized to the limits.
#include "corner_shape.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>

namespace railodd::geometry::corner {

namespace {

// Share of the turn taken by the two spirals together. At one half each
// spiral is as long as the arc: the curvature ramps are gentle enough to
// read as transitions, and the peak curvature stays within 1.5 times that
// of a circular fillet in the same room.
constexpr double spiral_share = 0.5;

// No piece of a corner is shorter where the room allows: a slight bend at
// the widest radius is pieces of a fraction of a metre (a 1 mrad kink
// between two straights of Krems: three of 0.5 m), which no design has.
constexpr double min_piece_m = 1.0;

struct UnitShape {
    double spiral = 0.0;    // length of each spiral at unit curvature
    double arc = 0.0;       // length of the arc at unit curvature
    double tangent = 0.0;   // vertex to each end
    double deviation = 0.0; // vertex to the midpoint
};

// A left turn by `turn` (0 < turn < pi) at curvature 1, starting at the
// origin heading +x. By symmetry the vertex lies on the normal at the
// curve's midpoint, which is where that normal crosses the entry straight.
UnitShape unit_shape(double turn) {
    UnitShape u;
    u.spiral = spiral_share * turn;
    u.arc = (1.0 - spiral_share) * turn;
    const Pose entry{0.0, 0.0, 0.0, 0.0};
    const Pose arc_start = evaluate(entry, make_spiral(u.spiral, 0.0, 1.0), u.spiral);
    const Pose mid = evaluate(arc_start, make_arc(u.arc, 1.0), 0.5 * u.arc);
    const double half = 0.5 * turn;
    u.deviation = mid.y / std::cos(half);
    u.tangent = mid.x + u.deviation * std::sin(half);
    return u;
}

} // namespace

Corner make_corner(double deflection, const CornerLimits& limits) {
    Corner c;
    c.deflection = deflection;
    const double turn = std::abs(deflection);
    if (turn < negligible_deflection) {
        return c;
    }
    if (!(turn < std::numbers::pi) || !(limits.tangent_m > 0.0)) {
        throw std::invalid_argument("make_corner: needs a deflection below pi and room for the corner");
    }
    const UnitShape u = unit_shape(turn);
    const double widest = std::max(limits.max_radius_m, min_piece_m / std::min(u.spiral, u.arc));
    const double scale = std::min({limits.tangent_m / u.tangent, limits.deviation_m / u.deviation, widest});
    const double k = std::copysign(1.0 / scale, deflection);
    c.tangent = u.tangent * scale;
    c.deviation = u.deviation * scale;
    c.curvature = k;
    c.primitives = {make_spiral(u.spiral * scale, 0.0, k), make_arc(u.arc * scale, k),
                    make_spiral(u.spiral * scale, k, 0.0)};
    return c;
}

} // namespace railodd::geometry::corner
