#pragma once
// OpenDRIVE planView primitives (line, arc, clothoid spiral) evaluated in
// closed form, so that designed, fitted and written alignments are all measured
// against the same exact geometry that an OpenDRIVE reader reconstructs.
#include <cstddef>
#include <vector>

namespace railodd::geometry {

// Heading is never wrapped: chaining keeps it continuous, so heading changes
// along an alignment are plain differences.
struct Pose {
    double x = 0.0;
    double y = 0.0;
    double hdg = 0.0;       // radians, counter-clockwise from +x (east)
    double curvature = 0.0; // 1/m, positive turns left
};

enum class PrimitiveKind { line, arc, spiral };

// Curvature varies linearly with distance from curv_start to curv_end, which
// covers all three kinds: line (both 0), arc (equal), spiral (OpenDRIVE's
// <spiral curvStart curvEnd>).
struct Primitive {
    PrimitiveKind kind = PrimitiveKind::line;
    double length = 0.0;
    double curv_start = 0.0;
    double curv_end = 0.0;
};

Primitive make_line(double length);
Primitive make_arc(double length, double curvature);
Primitive make_spiral(double length, double curv_start, double curv_end);

// Start pose (x, y, hdg at s = 0) plus the primitives in order; the start
// pose's curvature is ignored because the first primitive defines it.
struct Alignment {
    Pose start;
    std::vector<Primitive> primitives;
};

const char* to_string(PrimitiveKind kind);

// Throws std::invalid_argument naming the primitive when a length is negative
// or not finite, or the curvatures contradict the kind (a line with curvature,
// an arc whose ends differ).
void validate(const Primitive& primitive, std::size_t index);
void validate(const Alignment& alignment);

double length(const Alignment& alignment);

// Pose at distance ds along one primitive from `start`; ds is clamped to
// [0, primitive.length]. Lines and arcs are exact; spirals integrate the
// quadratic heading by its power series on sub-intervals of at most 0.3 rad
// of turn (error below 1e-9 m on the pieces the fit uses, 1e-6 m per km).
Pose evaluate(const Pose& start, const Primitive& primitive, double ds);

// Pose at arc length s, clamped to [0, length(alignment)]. At a joint between
// primitives the later primitive's curvature is reported.
Pose evaluate(const Alignment& alignment, double s);

// The same curve run the other way: starts at the end pose turned by pi,
// primitives in reverse order with their curvatures negated. Exact up to the
// evaluation of the end pose.
Alignment reversed(const Alignment& alignment);

// Pose at the start of each primitive, chained from the closed-form ends.
std::vector<Pose> primitive_starts(const Alignment& alignment);

// Arc length at the start of each primitive.
std::vector<double> primitive_s(const Alignment& alignment);

// Chainages in [s0, s1] where a polyline through the alignment stays within
// max_sagitta (m) of it: s0, s1, every primitive joint between them, and in
// each primitive's stretch evenly spaced stations whose chord sagitta
// h^2 |k| / 8 is at most max_sagitta at the stretch's largest curvature
// (none inside a line). Ascending; s0 == s1 gives one station.
std::vector<double> chord_stations(const Alignment& alignment, double s0, double s1, double max_sagitta);

struct Projection {
    double s = 0.0;        // arc length of the nearest point
    double offset = 0.0;   // signed lateral distance, left of the heading positive
    double distance = 0.0; // Euclidean distance to the nearest point
};

// Nearest point of the alignment to (x, y). For many queries against the same
// alignment use IndexedAlignment (indexed_alignment.hpp), which caches samples.
Projection project_point(const Alignment& alignment, double x, double y);

} // namespace railodd::geometry

namespace railodd::geometry {

// The alignment cut at the given arc lengths (ascending, within the
// alignment): cuts.size() + 1 pieces, each starting with the exact pose at its
// cut. Cutting a line, arc or clothoid is exact, so the pieces chain into the
// original with no gap.
std::vector<Alignment> split_alignment(const Alignment& alignment, const std::vector<double>& cuts);

} // namespace railodd::geometry
