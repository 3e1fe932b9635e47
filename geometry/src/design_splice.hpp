#pragma once
// A tied stretch rebuilt as railway design: from a pose on the fit to the
// tied pose, curves of transition, arc, transition (reverse and compound
// curves meeting through one transition), fitted to the stretch's nodes by
// least squares with both poses held exactly. What tie_splice.hpp tries
// before the corner construction, whose corners at every zigzag of a few
// metres (a tram's junction curve) were sub-metre elements no design has.
#include "fit/least_squares.hpp"
#include "railodd/geometry/fit_alignment.hpp"

#include <optional>
#include <vector>

namespace railodd::geometry {

using fit::max_track_curvature;

// The largest curvature of any element, either way (1/m).
double peak_curvature(const Alignment& a);
// Whether every element turns as a track can (max_track_curvature).
bool drivable(const Alignment& a);

// Which of a stretch's poses holds: both, or only the tied one where the
// stretch is a whole chain whose other end is free (that end's pose, the
// free fit's, is a guess the nodes may move: held, a Cologne tram leg tied
// 27 degrees past its nodes' heading had no drivable splice and kept a fit
// 17 m off them; free, 2.2 m).
enum class SpliceEnds { both_held, from_free, to_free };

// points: the stretch's nodes from the one `from` stands at to the one
// `to` ties. The design with the fewest curves (up to four) whose every
// element is a metre or longer, that turns as a track can and passes every
// node within tolerance_m; none where no such design exists or it loops.
std::optional<Alignment> design_splice(const std::vector<Point>& points, const Pose& from, const Pose& to,
                                       double tolerance_m, SpliceEnds ends = SpliceEnds::both_held);

// The same designs, the one passing closest to the nodes, where that is
// within max_off_m of them: for nodes leaving a tie at an angle no track
// can turn. The nodes next to either pose are left out of the solve where
// they pull it into a loop or off the pose, not out of the measure.
// `max_curvature`: what the design may turn at most (a track's, unless the
// poses themselves ask for more).
std::optional<Alignment> closest_design_splice(const std::vector<Point>& points, const Pose& from, const Pose& to,
                                               double max_off_m, double max_curvature = max_track_curvature,
                                               SpliceEnds ends = SpliceEnds::both_held);

} // namespace railodd::geometry
