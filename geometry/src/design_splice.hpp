#pragma once
// A tied stretch rebuilt as railway design: from a pose on the fit to the
// tied pose, curves of transition, arc, transition (reverse and compound
// curves meeting through one transition), fitted to the stretch's nodes by
// least squares with both poses held exactly. What tie_splice.hpp tries
// before the corner construction, whose corners at every zigzag of a few
// metres (a tram's junction curve) were sub-metre elements no design has.
#include "railodd/geometry/fit_alignment.hpp"

#include <optional>
#include <vector>

namespace railodd::geometry {

// points: the stretch's nodes from the one `from` stands at to the one
// `to` ties. The design with the fewest curves (up to four) whose every
// element is a metre or longer and that passes every node within
// tolerance_m; none where no such design exists or it loops.
std::optional<Alignment> design_splice(const std::vector<Point>& points, const Pose& from, const Pose& to,
                                       double tolerance_m);

} // namespace railodd::geometry
