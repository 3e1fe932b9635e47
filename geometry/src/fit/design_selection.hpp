#pragma once
// A window's design: candidate structures (lines, transitions, arcs) read off
// the fine clothoid spline's curvature diagram, each fitted to the nodes and
// scored by penalised likelihood with the railway design rules as a prior.
// See docs/geometry.md, "Model selection by penalised likelihood".
#include "curvature_model.hpp"
#include "least_squares.hpp"
#include "structure.hpp"

#include <optional>
#include <vector>

namespace railodd::geometry::fit {

struct WindowFit {
    CurvatureModel model;
    SolveReport report;
    bool fallback = false; // the fine spline kept: no design came near the nodes
};

// ks, kk: the fine spline's knot chainages and curvatures; se: the window's
// ends; so: the solve options for candidates; fine_report: the fine spline's
// fit (its residuals bound what a design can reach); sigma: the node noise.
// Nothing where no candidate comes near enough the nodes.
std::optional<WindowFit> best_design(const std::vector<Point2>& p, const std::vector<double>& ks,
                                     const std::vector<double>& kk, const StructureEnds& se, SolveOptions so,
                                     const SolveReport& fine_report, double sigma);

} // namespace railodd::geometry::fit
