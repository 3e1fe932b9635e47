#pragma once
// Cant (superelevation of the outer rail) along a track: from railway:cant
// where mapped, otherwise optionally estimated from speed and radius.
//
// Sign convention. Cant values here are heights in metres by which the OUTER
// rail of a curve is raised; they are >= 0 and carry no side. The side comes
// from the curve: `left_curve` (curvature > 0, turning left when facing
// increasing s) means the outer rail is the right one. ASAM OpenDRIVE's
// road reference line frame is right-handed (s forward, t left, h up) and
// superelevation is the roll about the s-axis, so a positive roll lifts the
// left side and the road falls to the right. Hence
//     OpenDRIVE superelevation = (left_curve ? -1 : +1) * superelevation_rad(cant)
// which superelevation_at() computes.
#include "railodd/geometry/alignment.hpp"

#include <optional>
#include <vector>

namespace railodd::geometry {

// Cant varies linearly from cant_start_m at s_start to cant_end_m at s_end;
// between stretches the cant is zero.
struct CantStretch {
    double s_start = 0.0;
    double s_end = 0.0;
    double cant_start_m = 0.0;
    double cant_end_m = 0.0;
    bool estimated = false; // equilibrium cant, not mapped
    bool left_curve = false; // the outer (raised) rail is the right one
};

// One OSM way's stretch of the track.
struct CantTagSpan {
    double s_start = 0.0;
    double s_end = 0.0;
    std::optional<double> cant_mm;   // railway:cant
    std::optional<double> speed_kmh; // parsed maxspeed
};

struct CantOptions {
    bool estimate = false;
    double cap_m = 0.160;          // maximum cant of standard-gauge lines (EN 13803: 160-180 mm)
    double rail_spacing_m = 1.500; // 1435 mm gauge plus a rail head: distance of the running circles
};

// Cant on each arc: the railway:cant of the span covering most of the arc
// (at least half of it; 0 mm means explicitly none), else, with
// options.estimate, the equilibrium cant e = spacing * V^2 / (g R) for the
// highest maxspeed on the arc, capped at cap_m and marked estimated. The arc
// carries its cant in full; each spiral next to it ramps linearly between the
// cants at its two ends (0 at a line, the arc's cant at an arc), so a spiral
// between two arcs turning the same way ramps from one cant to the other,
// and one between opposite arcs is split where its ramp passes through zero.
// An arc with no spiral next to it starts its cant as a step: OSM drawings
// rarely resolve the ramp on the straight. Lines carry none. Stretches are in
// ascending s; zero-cant stretches are left out.
std::vector<CantStretch> compute_cant(const Alignment& alignment, const std::vector<CantTagSpan>& tags,
                                      const CantOptions& options);

// Roll angle of a sleeper whose rails, rail_spacing_m apart, differ in
// height by cant_m: asin, as the spacing is measured along the tilted sleeper.
double superelevation_rad(double cant_m, double rail_spacing_m);

// Cant (m, >= 0) at s, and the signed OpenDRIVE superelevation (rad) there.
double cant_at(const std::vector<CantStretch>& stretches, double s);
double superelevation_at(const std::vector<CantStretch>& stretches, double s, double rail_spacing_m);

} // namespace railodd::geometry
