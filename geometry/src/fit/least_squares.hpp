#pragma once
// Levenberg-Marquardt on a CurvatureModel: orthogonal distances of the data
// points to the curve, plus optional smoothness of the knot curvatures and an
// optional end pose the curve must reach.
#include "curvature_model.hpp"

#include <limits>
#include <optional>
#include <vector>

namespace railodd::geometry::fit {

// No track turns tighter than this (R 10 m; tram curves are 15-25 m).
constexpr double max_track_curvature = 0.1;

struct Point2 {
    double x = 0.0;
    double y = 0.0;
};

struct SolveOptions {
    double sigma_m = 0.3;           // expected noise of the points: residual scale
    double kink_sigma = 0.0;        // > 0: penalise second differences of knot curvatures by this scale (1/m)
    double ridge_sigma = 0.0;       // > 0: pull knot curvatures towards zero (lines) where data is sparse
    double min_length_m = 0.5;      // free segment lengths stay at least this long
    double max_curvature = max_track_curvature; // 1/m, either way: knot curvatures stay within
    // Per segment, a longer floor than min_length_m (empty: none): a
    // transition standing for a curvature jump at a switch, whose length the
    // points cannot tell (design_polish.cpp).
    std::vector<double> min_length_at;
    int max_iterations = 40;
    bool pin_first = true;          // the first point marks the curve's start (along-track residual too)
    bool pin_last = true;           // the last point marks its end
    std::optional<Pose> end;        // end pose (x, y, hdg, curvature) to reach
    // Bend free steps along curved cost valleys (second-order correction):
    // structure fits, whose segment lengths couple with their curvatures,
    // converge in fewer iterations; the regularised fine spline does not
    // need it.
    bool geodesic_acceleration = false;
    // Sum of squared distances (m^2) above which the caller rejects the fit
    // anyway: the solve stops once its progress cannot bring it below.
    double give_up_rss = std::numeric_limits<double>::infinity();
    // The caller rejects a curve that loops (loops_back, fit_alignment.hpp):
    // the solve stops as soon as it does. Such a solve would run on at the
    // curvature bound, where every evaluation costs a sub-interval per 0.3
    // rad of turn.
    bool abandon_loops = false;
    // Per point, the factor its distance row is scaled by (empty: all one):
    // a robust fit's reweighting (best_design), so that an outlier node no
    // longer pulls the curve while the design is fitted.
    std::vector<double> point_scale;
    // Per segment, the weight of a prior on its length (empty: none): a
    // transition's length against the design rule's for its curvature
    // change (transition_length_for), cost w ln(L / L_rule)^2, the design
    // search's own prior (design_local.cpp), so the polish keeps what the
    // search chose it for.
    std::vector<double> transition_prior;
    // Per segment, a parallel track's mean curvature over it, where along
    // the segment (a share of its length) it asks for it, and the weight of
    // the segment's curvature's distance from it there (empty: none): the
    // design search's guide (design_guide.hpp), so the polish keeps it.
    std::vector<double> guide_curvature, guide_at, guide_weight;
    // Per knot (segments + 1), the arc length from the start it is held at
    // and the weight of its distance from there (empty: none): a knot the
    // chain shares with a parallel track (design_guided.cpp), which the
    // chain's own nodes, sparse, would let slide along a flat valley.
    std::vector<double> knot_at, knot_weight;
    // Solve the normal equations by the chain's Riccati recursion
    // (chain_system.hpp): linear in the segments where the dense solve is
    // cubic. Only where no kink or ridge rows are asked for.
    bool chain_solve = false;
};

struct SolveReport {
    double rms_m = 0.0;
    double max_m = 0.0;
    int iterations = 0;
    bool gave_up = false; // stopped early: the fit could not reach give_up_rss
    bool end_met = true;  // the end pose, if any, is met within end_tolerance (end_constraint.hpp)
    std::vector<double> distances_m; // of every point to the fitted curve (empty where it gave up)
};

// Distances of every point to the model's curve (after the last update).
std::vector<double> point_distances(const CurvatureModel& model, const std::vector<Point2>& points);

SolveReport solve(CurvatureModel& model, const std::vector<Point2>& points, const SolveOptions& options);

// One round of robust reweighting (iteratively reweighted least squares for
// a likelihood capped at `cap` metres): the scale of every point further
// than cap is cap / distance (squared in the cost). False, scale untouched,
// where no point is so far, where too many are (more than 2 + n/50: then
// the structure is wrong, not the points) or the same as the last round
// (`previous`, which this updates).
bool far_point_scale(const std::vector<double>& distances, double cap, std::vector<std::size_t>& previous,
                     std::vector<double>& scale);

} // namespace railodd::geometry::fit
