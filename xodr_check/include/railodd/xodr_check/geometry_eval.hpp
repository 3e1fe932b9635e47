#pragma once
// Closed-form evaluation of one OpenDRIVE plan-view record (<geometry>), written
// from the standard's formulas and independent of railodd::geometry.
#include <string>

namespace railodd::xodr_check {

enum class GeometryKind { line, arc, spiral, poly3, param_poly3 };

const char* kind_name(GeometryKind k);

struct GeometryRecord {
    GeometryKind kind = GeometryKind::line;
    double s = 0.0; // start along the road's reference line
    double x = 0.0;
    double y = 0.0;
    double hdg = 0.0;
    double length = 0.0;
    double curvature = 0.0;       // arc
    double curv_start = 0.0;      // spiral
    double curv_end = 0.0;        // spiral
    double a = 0, b = 0, c = 0, d = 0; // poly3: v(u) = a + b u + c u^2 + d u^3
    double au = 0, bu = 0, cu = 0, du = 0; // paramPoly3 u(p)
    double av = 0, bv = 0, cv = 0, dv = 0; // paramPoly3 v(p)
    bool normalized = false;      // paramPoly3 pRange="normalized": p in [0, 1], else p in [0, length]
};

struct Pose {
    double x = 0.0;
    double y = 0.0;
    double hdg = 0.0;       // tangent direction (rad)
    double curvature = 0.0; // 1/m, positive to the left
};

// The pose at ds (0 <= ds <= length) from the record's start.
Pose evaluate(const GeometryRecord& g, double ds);

// Arc length of the record's curve over its parameter range; for poly3 this is
// the same as evaluating along u, for paramPoly3 it tells whether @length is
// the curve's length.
double curve_length(const GeometryRecord& g);

// The angle a - b wrapped into (-pi, pi].
double angle_diff(double a, double b);

} // namespace railodd::xodr_check
