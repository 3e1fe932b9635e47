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

// The design as an alignment from the start of its first element.
Alignment to_alignment(const ReferenceLine& r, const FrameDesign& d);

} // namespace railodd::geometry::fit
