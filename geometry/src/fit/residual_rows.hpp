#pragma once
// The residual rows of a CurvatureModel against its points, in the order
// every linearisation uses: the points' normal distances, the pinned ends'
// along-track distances, then curvature kinks, the ridge, the transition
// priors, the guide, the held knots.
#include "residuals.hpp"

#include <Eigen/Dense>

#include <vector>

namespace railodd::geometry::fit {

std::size_t row_count(const CurvatureModel& m, const Problem& p);

// The point rows; only points from `from` on are filled (those before it
// have not moved). Returns the rows' count.
std::size_t fill_point_rows(const std::vector<Foot>& feet, const std::vector<Point2>& curve, const Problem& p,
                            Eigen::VectorXd& r, std::size_t from = 0);

bool has_kink_rows(const CurvatureModel& m, const Problem& p);
// Curvature kink at knot k (1 .. knots - 2).
double kink_row(const CurvatureModel& m, const Problem& p, std::size_t k);
double ridge_row(const CurvatureModel& m, const Problem& p, std::size_t k);
// Segment j's length against the design rule's for its curvature change.
double transition_row(const CurvatureModel& m, const Problem& p, std::size_t j);
// Segment j's curvature against its guide's.
double guide_row(const CurvatureModel& m, const Problem& p, std::size_t j);
// Knot k's arc length against where it is held.
double knot_row(const CurvatureModel& m, const Problem& p, std::size_t k);

void fill_residuals(const CurvatureModel& m, const std::vector<Foot>& feet, const std::vector<Point2>& curve,
                    const Problem& p, Eigen::VectorXd& r);

} // namespace railodd::geometry::fit
