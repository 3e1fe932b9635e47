#pragma once
// The railway's design read from mapped nodes by an L0-penalised
// segmentation: optimal partitioning (Jackson et al. 2005) in the continuous
// form of CPOP (Fearnhead, Maidstone & Letchford 2019), lifted from
// piecewise-linear means to the G2 design of a railway, searched
// sequentially with a beam. It works in a developed frame (reference_line.hpp):
// a node is a chainage t along a reference line and a lateral coordinate z
// whose second derivative along t is the design's curvature, so a design is a
// C2 piecewise cubic z(t) whose curvature z'' is continuous and piecewise
// linear: zero on a line, constant on an arc, linear on a transition.
#include <cstddef>
#include <limits>
#include <memory>
#include <optional>
#include <utility>
#include <vector>

namespace railodd::geometry::fit {

enum class ElementKind : unsigned char { line, transition, arc };

class GuideCurvature; // design_guide.hpp

struct FrameNode {
    double t = 0.0; // chainage along the reference
    double z = 0.0; // developed lateral coordinate
    double w = 1.0; // weight of its squared residual: 1 / sigma^2 times its robust factor
};

// State of the design at a chainage: lateral coordinate, heading (radians,
// relative to the reference's start heading) and curvature.
struct FrameState {
    double z = 0.0;
    double dz = 0.0;
    double k = 0.0;
};

struct FrameElement {
    ElementKind kind = ElementKind::line;
    double s0 = 0.0, s1 = 0.0; // chainages of its ends
    double k0 = 0.0, k1 = 0.0; // curvature at its ends
};

struct DesignDpOptions {
    double s0 = 0.0, s1 = 0.0; // the design spans [s0, s1]
    double knot_step_m = 5.0;  // candidate knots every this far
    // L0 penalty per parameter, in units of the cost (sum w r^2): every
    // element has its length, an arc also its curvature (a transition's
    // slope follows from the curvatures at its ends).
    double parameter_penalty = 10.0;
    double min_line_m = 10.0, min_transition_m = 10.0, min_arc_m = 10.0;
    double curvature_weight = 0.0; // cost per metre per (1/m)^2: a weak pull to straight
    // Design prior: a transition's length against the one its curve's
    // radius calls for (transition_length_for); cost per squared log ratio.
    double transition_prior = 0.0;
    std::size_t beam = 48;  // live hypotheses kept
    std::size_t spawn = 3;  // parent elements each new element may follow at a knot, and histories kept per element
    double prune_margin = -1.0; // hypotheses this far above the best are dropped; < 0: 4 penalties + 20
    std::optional<FrameState> start, end; // tied ends
    // The kinds of the elements beyond tied ends inside a chain (a span
    // searched again, research_span): the first and last elements follow and
    // precede them by the design rules, two transitions meeting at zero
    // curvature. Without, a span after a transition into a curve opened with
    // a transition from the curve's curvature, which the splice forbids
    // (OSM-like truth seed 1041 at 2 m: its window cost 183 more spliced, and
    // a reverse curve's 333 m straight stayed missing, 7.9 m off).
    std::optional<ElementKind> before, after;
    bool refine = true; // the local search after the beam (refine_structure)
    // A parallel track's curvature the design is pulled to, where there is
    // one beside the chain (design_guide.hpp).
    std::shared_ptr<const GuideCurvature> guide;
    std::vector<double> knots; // candidate knots besides the grid's (where no node came, too)
};

struct FrameDesign {
    FrameState start;
    std::vector<FrameElement> elements;
    double cost = 0.0; // data cost plus penalties
    double data_cost = 0.0;
};

// Transition length (m) a railway designer gives a curve of this curvature:
// design speed from 150 mm cant plus 100 mm deficiency, about 0.45 m per km/h.
double transition_length_for(double curvature);

// Local search from a structure: knots moved, elements of another kind,
// split or merged away while the exact cost falls (design_refine.cpp), on
// the elements that reach into `span` (chainages; all by default). Nodes in
// any order.
FrameDesign refine_structure(const std::vector<FrameNode>& nodes, const std::vector<FrameElement>& structure,
                             const DesignDpOptions& options,
                             std::pair<double, double> span = {-std::numeric_limits<double>::infinity(),
                                                               std::numeric_limits<double>::infinity()});

// The structure searched again (design_dp) over chainages [lo, hi], tied to
// the design's state where the span ends inside the chain, spliced in and
// refined a span's length each way (design_window.cpp): the local search
// alone cannot leave a structure several elements deep. Only refined where
// the span holds no node or the splice breaks a design rule.
FrameDesign research_span(const std::vector<FrameNode>& nodes, const FrameDesign& design, const DesignDpOptions& options,
                          double lo, double hi);

// Every run of a few elements searched again in turn (research_span), each
// result taken where the cost with the strays' term (stray_cost) falls: a
// large-neighbourhood search after the beam. Nodes in any order.
FrameDesign research_windows(const std::vector<FrameNode>& nodes, FrameDesign design, const DesignDpOptions& options);

// The nodes in order of chainage (stable: nodes at one chainage keep theirs).
std::vector<FrameNode> by_chainage(std::vector<FrameNode> nodes);

// Each node's z less the design's at its chainage (the first and last
// elements extended beyond their ends), in the nodes' order: one sweep.
std::vector<double> frame_residuals(const FrameDesign& design, const std::vector<FrameNode>& nodes);

// How far strays lie from the track, as mappers leave them: mostly a few
// metres, seldom tens (the truth bench draws 3-10 m). At 20 m a Cologne
// branch still left out a node on the line of its neighbours, 27 m off.
constexpr double stray_scale_m = 10.0;

// The nodes left out (weight 0) as strays, each its offset from the design
// squared in units of the stray scale: a mixture's outlier term, which the
// cost of a design (its data cost and penalties) leaves out. Without it a
// design could leave out the one node that held it to the track and swing
// free (Cologne: branches between two switches whose ties disagree with
// their nodes by 5-9 degrees, the designs 68 and 27 m off a node on the
// line of its neighbours; sparse truth seed 1178 at 0.3 m, a window
// searched again swung 30 m across two strays left out on a straight).
double stray_cost(const FrameDesign& design, const std::vector<FrameNode>& nodes);

// The design's state at chainage t (the first and last elements extended).
FrameState design_state(const FrameDesign& design, double t);

// The state u past the start of element e, from its start state.
FrameState state_along(const FrameElement& e, const FrameState& start, double u);

// Nodes in any order; at least one. Throws std::invalid_argument for an
// empty range or no nodes.
FrameDesign design_dp(const std::vector<FrameNode>& nodes, const DesignDpOptions& options);

// The cost of one given structure (kinds and knots), solved exactly: what
// the search approximates. Elements' curvatures are ignored (solved for).
FrameDesign solve_structure(const std::vector<FrameNode>& nodes, const std::vector<FrameElement>& structure,
                            const DesignDpOptions& options);

} // namespace railodd::geometry::fit
