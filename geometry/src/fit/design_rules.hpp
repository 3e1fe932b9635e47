#pragma once
// The railway's design rules and the costs of a design's ends, shared by the
// search (design_dp.cpp), the exact solve of a structure
// (design_structure.cpp) and its local costs (design_local.cpp): which
// element may follow which, how long each must be, what an element costs,
// and how a chain starts and ends (tied to a pose, or free with its
// curvature held weakly to zero).
#include "design_dp.hpp"
#include "design_quadratic.hpp"

#include <cstddef>
#include <vector>

namespace railodd::geometry::fit::design {

constexpr ElementKind kinds[3] = {ElementKind::line, ElementKind::transition, ElementKind::arc};

// A tie holds the scaled position, heading and curvature to about a tenth
// of a millimetre (a larger weight's constants swamp the nodes' cost in the
// windows' sums, design_local.hpp). A branch starts with its through
// track's curvature at the switch: a turnout's curve that starts there
// without a transition is drawn with a short one (10 m into R 300 m lies
// 14 mm inside the curve), and every link stays G2.
constexpr double tie_weight = 1e6;

Vec4 scaled(const FrameState& s);

// A line and an arc are entered and left through transitions; two
// transitions meet at zero curvature (a reverse curve) or at an arc.
bool may_follow(ElementKind before, ElementKind after);

// Whether a span's first (last) element may be `kind` beside the element
// of kind `beyond` past its tied end (DesignDpOptions::before, after): by
// the design rules, or as that element's continuation, a line or an arc
// going on past the tie (research_span merges the two; `continues`).
bool continues(ElementKind beyond, ElementKind kind);
bool may_adjoin(ElementKind beyond, ElementKind kind);

// An element's shortest length, unless it ends the chain.
double min_length(ElementKind kind, const DesignDpOptions& o);

// The L0 penalty of an element: one parameter for its length, one more for
// an arc's curvature, and one more for a transition at a free chain end
// (its curvature there is free: a chain that is not tied starts and ends
// straight or in a curve, seldom inside a transition).
double element_penalty(ElementKind kind, const DesignDpOptions& o, bool at_free_end);

// The penalty of a chain's first element: none where it continues the
// element before a span.
double first_penalty(ElementKind kind, const DesignDpOptions& o, bool at_free_end);

// A free chain end's curvature held weakly to zero (sd 1/500 m): a chain
// cut inside a curve keeps it for little, while a hook across the gap to
// the next node, which the nodes cannot see, costs as much as an element.
// u: the end's scaled distance from the element's start.
void add_free_end(Quad& f, double u);

// The cost of a chain's first element of `kind` before any node: its
// start tied, or free.
Quad first_element(ElementKind kind, const DesignDpOptions& o);

// The nodes [first, last) into the cost of an element starting at s0.
void add_nodes(Quad& f, const std::vector<FrameNode>& n, std::size_t first, std::size_t last, double s0);

// The cost of a chain whose last element, of `kind`, has the cost f and is
// u (scaled) long: its end tied, or free; its penalty taken back where it
// continues the element after a span. The last element's start state in
// *start (where given).
double close_chain(Quad f, double u, ElementKind kind, const DesignDpOptions& o, Vec4* start = nullptr);

} // namespace railodd::geometry::fit::design
