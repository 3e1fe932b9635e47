#pragma once
// The end pose a window's fit must reach (the start of the track it is tied
// to), as equality constraints of the least-squares problem rather than as
// heavily weighted residual rows. Weighted rows make the problem stiff:
// Levenberg-Marquardt then crawls along the constraint at a few per mille per
// iteration and most end-tied solves ran into the iteration cap. Here every
// step solves the linearised constraints exactly (a KKT system) and the trial
// is projected back onto them, so the steps only have to reduce the data
// residuals.
#include "chain_system.hpp"
#include "curvature_model.hpp"

#include <Eigen/Dense>

#include <functional>
#include <optional>

namespace railodd::geometry::fit {

// Scales of the constraint rows: metres for x and y; heading and curvature
// scaled so that 1 m, 0.01 rad and 1e-4 1/m weigh the same.
constexpr double end_heading_scale = 100.0;
constexpr double end_curvature_scale = 1e4;

// Constraint rows for this model: x, y and heading always; curvature only
// where the last knot's curvature is a variable (a fixed one is met by
// construction and would make the system singular).
std::size_t end_rows(const CurvatureModel& m);

// Scaled gap between the curve's end pose and the target.
Eigen::VectorXd end_gap(const CurvatureModel& m, const Pose& end, const Pose& target);

// What the end may miss by, in the scaled units of end_gap: far below
// OpenDRIVE's link tolerances (1 mm, 1e-4 rad) and the 1e-4 m the chain fit
// checks for.
constexpr double end_tolerance = 1e-8;

// The step d minimising 1/2 d^T A d + g^T d subject to C d = -c, with A (the
// damped normal matrix) already factored. None if the constraints are
// degenerate for this model (fewer effective parameters than rows).
std::optional<Eigen::VectorXd> constrained_step(const NormalMatrix& A, const Eigen::VectorXd& g,
                                                const Eigen::MatrixXd& C, const Eigen::VectorXd& c);

// Moves `values` (the model's parameters) towards the constraint surface by
// chord Newton steps of least change in the metric A, while they contract
// the gap: each costs one pass over the segments. `apply` writes values into
// the model (with its bounds) and returns the model's gap. Returns the
// largest remaining gap row; below end_tolerance the end is met.
double project_onto_end(Eigen::VectorXd& values, const NormalMatrix& A, const Eigen::MatrixXd& C,
                      const std::function<Eigen::VectorXd(const Eigen::VectorXd&)>& apply);

// The model moved onto the end pose by the least change to its last
// segments' lengths and curvatures (a curvature variable's 1e-4 1/m weighs
// as 1 m of length), for a curve that misses it by millimetres: the design
// search's unpolished alignment, taken from its frame, misses a tied end by
// a fraction of a millimetre, beyond the chain fit's 0.1 mm (VDE 8.2: 114 of
// 347 tied ends, which were then rebuilt by corners). Whether it is met;
// the model is unchanged where not.
bool meet_end(CurvatureModel& m, const Pose& target);

} // namespace railodd::geometry::fit
