#pragma once
// Parallel tracks share a design: a window whose nodes run beside a track
// already fitted (3-6 m off, the same way or the other) is offered that
// track's design over the stretch, offset to the window's side, as a
// candidate whose curvatures are the neighbour's (concentric: curvature
// k / (1 - d k) at offset d) and whose only free parameters are the element
// lengths and a free start pose. The penalised likelihood takes it where it
// fits the window's own nodes as well as a design of its own: the two
// tracks' curvature then agrees by construction.
#include "least_squares.hpp"
#include "segmentation.hpp"

#include "railodd/geometry/indexed_alignment.hpp"

#include <optional>
#include <vector>

namespace railodd::geometry::fit {

struct GuidedStructure {
    std::vector<Piece> pieces; // in the window's direction, offset to its side
    Pose start;                // the offset guide's pose where the window starts
};

// Nothing where fewer than 80 % of the window's nodes (and fewer than five)
// lie 2.5-6.5 m to one side of the guide, or they do not run along it.
std::optional<GuidedStructure> guided_structure(const std::vector<Point2>& p, const IndexedAlignment& guide);

} // namespace railodd::geometry::fit
