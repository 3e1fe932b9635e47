#pragma once
// A window's design: candidate structures (lines, transitions, arcs) read off
// the fine clothoid spline's curvature diagram, each fitted to the nodes and
// scored by penalised likelihood with the railway design rules as a prior.
// See docs/geometry.md, "Model selection by penalised likelihood".
#include "curvature_model.hpp"
#include "least_squares.hpp"
#include "parallel_guide.hpp"
#include "structure.hpp"

#include <optional>
#include <vector>

namespace railodd::geometry::fit {

struct WindowFit {
    CurvatureModel model;
    SolveReport report;
    bool fallback = false; // the fine spline kept: no design came near the nodes
};

// Nodes a fit passes far from while it stays close to their neighbours:
// outliers (3-10 m off in a curve, where a quadratic through four nodes is no
// good predictor, or on a straight held by two or three sparse nodes). Each
// is more than max(2 m, 5 sigma) off and 1.5 times further than both
// neighbours (or two such nodes side by side, 1.5 times further than the
// nodes around the pair). The first and last nodes (switches, chain ends, the
// previous window's pose) and their neighbours, which alone may hold a sparse
// straight at an end, are never among them.
std::vector<std::size_t> far_nodes(const std::vector<double>& d, double sigma);

// ks, kk: the fine spline's knot chainages and curvatures; se: the window's
// ends; so: the solve options for candidates; fine_report: the fine spline's
// fit (its residuals bound what a design can reach); sigma: the node noise.
// Nothing where no candidate comes near enough the nodes.
std::optional<WindowFit> best_design(const std::vector<Point2>& p, const std::vector<double>& ks,
                                     const std::vector<double>& kk, const StructureEnds& se, SolveOptions so,
                                     const SolveReport& fine_report, double sigma,
                                     const GuidedStructure* guided = nullptr);

// The same, with the curvature diagram read from the nodes themselves by
// the trend filter (curvature_trend.hpp) instead of a fine spline: no
// clothoid is evaluated before the candidates. se: the window's ends (its
// start pose is used where the start is tied); start_at_switch: the tied
// start is a switch (not the previous window's end). Nothing where the window is
// too small for the filter or no candidate comes near enough the nodes.
// guided: a parallel track's design over the window (parallel_guide.hpp),
// tried first in both.
std::optional<WindowFit> trend_design(const std::vector<Point2>& p, const StructureEnds& se, bool start_at_switch,
                                      SolveOptions so, double sigma, const GuidedStructure* guided = nullptr);

} // namespace railodd::geometry::fit
