#pragma once
// The residuals of a CurvatureModel against its data points, and their
// Jacobian: feet of the points on the curve, normal distances, smoothness
// rows, the end gap (least_squares.cpp runs Levenberg-Marquardt on them).
#include "chain_system.hpp"
#include "curvature_model.hpp"
#include "least_squares.hpp"

#include <Eigen/Dense>

#include <cmath>
#include <optional>
#include <vector>

namespace railodd::geometry::fit {

// Where a data point sits on the curve: segment, distance into it, and the
// unit normal there. Residuals use the normal (and, at the two ends, the
// tangent) fixed during one iteration, as in point-to-curve ICP.
struct Foot {
    std::size_t segment = 0;
    double u = 0.0;
    bool at_start = false; // the pinned first point: stays at arc length 0
    bool at_end = false;   // the pinned last point: follows the end of its segment when lengths change
    double nx = 0.0, ny = 0.0;
    double tx = 0.0, ty = 0.0;
    double cx = 0.0, cy = 0.0;

    // The curve point c is where the foot now is.
    void place(const Pose& c) {
        cx = c.x;
        cy = c.y;
        tx = std::cos(c.hdg);
        ty = std::sin(c.hdg);
        nx = -ty;
        ny = tx;
    }
};

// The data and options of one solve.
struct Problem {
    const std::vector<Point2>& pts;
    const SolveOptions& opt;
};

// Weight of the end-pose rows where the end cannot be an exact constraint:
// the end is a link to another track, which must be met to far below a
// millimetre.
constexpr double end_weight = 1e5;

// A model evaluated at its knots and at the feet of the points.
struct Evaluated {
    std::vector<Pose> knots;
    std::vector<Pose> at_feet;
};

struct Linearisation {
    Eigen::MatrixXd J; // data rows
    Eigen::VectorXd r;
    // J's first dense_rows rows are the points' (every parameter upstream of
    // a point moves it); below them the smoothness rows, each touching a few
    // knots, and any appended end rows.
    long dense_rows = 0;
    Eigen::MatrixXd C; // end gap rows, with an end pose
    Eigen::VectorXd c;
    // Where the solve is a chain's (SolveOptions::chain_solve): J in
    // state-space form instead (J above stays empty), and the end gap's
    // rows on the end state.
    std::optional<ChainJacobian> chain;
    Eigen::MatrixXd end_state;
};

// First feet of the points, in track order: each is searched along the curve
// from the previous one's, where the chord between the two points leads.
std::vector<Foot> feet_of(const CurvatureModel& m, const std::vector<Pose>& poses, const std::vector<Point2>& pts,
                          const SolveOptions& opt);

// Per segment (and one past the last), the first foot on or beyond it: a
// parameter of segments [a, b] moves only feet from the a-th on.
std::vector<std::size_t> first_feet_on(const std::vector<Foot>& feet, std::size_t segments);

// Residuals and Jacobian at the model, after moving the feet to the nearest
// curve points. `known`, where given, is the model evaluated at the feet as
// they stand (by the cost of the step that made it).
Linearisation linearise(const CurvatureModel& m, const ParameterMap& map, const Problem& p, std::vector<Foot>& feet,
                        const Evaluated* known);

// Cost of a trial model with the feet (and their normals) of the current
// linearisation held fixed, as in point-to-curve ICP; the next linearisation
// moves the feet. With end_rows, the end pose's weighted rows count too.
// The evaluation is kept in `e`: the next linearisation starts from it.
double cost_at_feet(const CurvatureModel& m, const Problem& p, const std::vector<Foot>& feet, bool with_end_rows,
                    Evaluated& e);

// The residual vector whose squared norm cost_at_feet returns.
Eigen::VectorXd residuals_at_feet(const CurvatureModel& m, const Problem& p, const std::vector<Foot>& feet,
                                  bool with_end_rows);

// Distance of every point to the curve: each foot walked to from the
// previous point's along the curve, as feet_of, then settled by Newton steps
// (to 1e-6 m along the curve).
std::vector<double> foot_distances(const CurvatureModel& m, const std::vector<Point2>& pts);

double total_length(const CurvatureModel& m);

// Keeps a trial model in the range the data can support: curvature at most
// max_curvature (SolveOptions': max_track_curvature, unless a splice
// between poses that ask for more relaxes it), every free length between
// min_length (or its segment's min_at, where longer) and max_length.
// Without the upper bound a diverging step could make a segment kilometres
// long and tightly curved, whose evaluation then takes minutes (seen on a
// replicated Cologne extract).
void clamp_model(CurvatureModel& m, double min_length, const std::vector<double>& min_at, double max_length,
                 double max_curvature);

} // namespace railodd::geometry::fit
