#pragma once
// The frame the design search works in (design_dp.hpp): a reference line
// near the nodes, and each node's chainage t along it and developed lateral
// coordinate z = offset + Phi(t), Phi the double integral of the reference's
// curvature. In that frame a curve near the reference has curvature z''
// (small-angle: exact to first order in its offset and its angle to the
// reference), so a railway design is a piecewise cubic in t.
#include "design_dp.hpp"
#include "least_squares.hpp"
#include "railodd/geometry/alignment.hpp"

#include <vector>

namespace railodd::geometry::fit {

// A fine polyline: vertices at chainage s, headings of the segment leaving
// each vertex (unwrapped; the last repeats), and Phi at each vertex.
class ReferenceLine {
public:
    ReferenceLine(std::vector<double> x, std::vector<double> y);
    double length() const { return s_.back(); }
    // Position and heading at chainage s (extrapolated straight beyond the ends).
    Pose at(double s) const;
    double developed(double s) const; // Phi(s)
    double start_heading() const { return hdg_.front(); }
    // Chainage and signed offset (left +) of a point, searched near segment `hint` (updated).
    std::pair<double, double> project(double x, double y, std::size_t& hint, double reach_m) const;
    // The segment holding chainage s (the first or last beyond the ends).
    std::size_t segment(double s) const;
    // The length of a curve at lateral offset e(t) (left +) from the
    // reference over chainages [a, b], to second order: the integral of
    // 1 - kappa e + e'^2 / 2, kappa the reference's curvature (its turns at
    // vertices). `offset(t)` gives e and e' = de/dt.
    template <class Offset>
    double offset_length(double a, double b, Offset offset) const {
        double len = b - a;
        double t = a;
        for (std::size_t k = segment(a) + 1; k + 1 < s_.size() && s_[k] <= b; ++k) {
            if (s_[k] > a) {
                const auto [e, de] = offset(s_[k]);
                len += 0.5 * de * de * (s_[k] - t) - (hdg_[k] - hdg_[k - 1]) * e;
                t = s_[k];
            }
        }
        const double de = offset(b).second;
        return len + 0.5 * de * de * (b - t);
    }
    double heading(double s) const { return hdg_[segment(s)]; }

private:
    std::vector<double> s_, x_, y_, hdg_, phi_;
};

// A smoothing spline through the nodes (chord-length parameter, curvature
// penalised; one band solve) sampled every h metres; bandwidth_m is the
// length over which it averages the nodes.
ReferenceLine smooth_reference(const std::vector<Point2>& p, double bandwidth_m, double h);

// An alignment sampled every h metres.
ReferenceLine alignment_reference(const Alignment& a, double h);

// Every node in the frame (weights 1).
std::vector<FrameNode> develop(const ReferenceLine& r, const std::vector<Point2>& p);

// A state given as a pose (a tied end) in the frame. `t`: in, the chainage
// of the chain end it ties (its node's); out, the pose's own. Sought near
// the end only: a chain that comes back close to where it began would
// otherwise tie its end to its start (a loop's 7 m chord).
FrameState frame_state(const ReferenceLine& r, const Pose& pose, double& t);

// The design's elements as they lie on the map: a curve at offset e from a
// reference that turns at curvature kappa is 1 - kappa e + e'^2 / 2 as long
// as its chainage (offset_length), and as much tighter (its turn, z'' over
// chainage, is the frame's). Arcs take their mean factor, transitions meet
// their neighbours' curvatures and keep their turn. At the frame's lengths
// every curve the design runs beside its reference turned its exit by
// e (1 - cos of the curve's angle): OSM-like truth seed 1096 at 0.3 m, 0.5 m
// off the reference in two curves of 86 degrees, drifted 1 m off on the map
// while 0.3 m in the frame. Without the e'^2 term a straight design across
// a wiggly reference (the first pass's, fitted at too low a noise) came
// out short by as much again as the wiggle's own length: sparse truth seed
// 1146 at 2 m, 4.7 m off its nodes in the frame and 19 m on the map.
// Chainages from the first element's s0, as on the map.
std::vector<FrameElement> on_map(const ReferenceLine& r, const FrameDesign& d);

// The design as an alignment from the start of its first element.
Alignment to_alignment(const ReferenceLine& r, const FrameDesign& d);

} // namespace railodd::geometry::fit
