#pragma once
// Turns a list of pieces (lines, arcs, transitions) into a CurvatureModel
// whose knots make the sequence G2: an arc's two knots share one curvature
// variable, lines pin theirs to zero, and a transition is inserted wherever
// two constant pieces would otherwise meet with a curvature jump.
#include "curvature_model.hpp"
#include "segmentation.hpp"

#include <optional>

namespace railodd::geometry::fit {

struct StructureEnds {
    Pose start;                         // initial x, y, hdg
    bool start_fixed = false;           // start pose and curvature given
    std::optional<double> end_curvature; // given when the end pose is fixed
};

CurvatureModel build_structure(std::vector<Piece> pieces, const StructureEnds& ends);

} // namespace railodd::geometry::fit
