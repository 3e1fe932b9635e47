#pragma once
// One pass of the design search over a chain (design_fit.cpp): the design in
// the pass's frame, the nodes as developed and weighted there, and what the
// pass was run with; and the test of which nodes it follows
// (design_nodes.cpp).
#include "design_dp.hpp"
#include "reference_line.hpp"

#include "railodd/geometry/alignment.hpp"
#include "railodd/geometry/fit_alignment.hpp"

#include <optional>
#include <vector>

namespace railodd::geometry::fit {

// The robust weights' cut, in units of the noise (Tukey's biweight's): a
// node further off the design than this many sigma is far (left out of the
// robust weights, suspect to the node tests).
constexpr double biweight_cut = 4.685;

struct DesignPass {
    FrameDesign design;
    Alignment alignment;
    std::vector<double> distance; // of every node to the design, in the frame
    std::vector<FrameNode> nodes; // in the pass's frame, weighted
    DesignDpOptions options;
    std::optional<ReferenceLine> frame;
    double sigma = 0.0;

    // `distance` measured again after the design or the nodes changed.
    void measure();
};

// Which nodes the design follows, settled by model selection (each change
// kept where the pass's cost falls, with one parameter per node left out and
// the strays' term, stray_cost); the pass and `weight` (per node: 0 left
// out) updated. A `held` node (per node, or empty) is never left out.
void settle_node_weights(DesignPass& pass, std::vector<double>& weight, const std::vector<char>& held);

// Which left-out nodes (weight 0) are strays (1). A chain whose left-out
// strays lie far off is still a railway fit: the strays are the mapping's
// fault (followed_max). A stray is one node, or two side by side, with two
// followed nodes on either side to show it out of line; a longer run left
// out is a stretch the design missed, and a node with fewer neighbours
// cannot be told from the track (Cologne: the middle node of three on a
// 676 m chain, tied at one end, left 17 m off). Those count. A tied end's
// pose (position and heading, as the network's fit of the track it leaves
// put them) witnesses as a node beside it does: a stray second node of a
// chain tied at its switch had one witness before it, and the chain went
// to corners through it (OSM-like truth routes at 0.1 m tied at both ends:
// 7.7 m off).
std::vector<char> strays(const std::vector<double>& weight, bool tied_start = false, bool tied_end = false);
// strays() of a fitted design `a`: a left-out node it passes within four
// sigma of `all` (its mapped node) counts as followed.
std::vector<char> fitted_strays(const Alignment& a, const std::vector<Point>& all, const std::vector<double>& weight,
                                double sigma, bool tied_start, bool tied_end);
// The furthest node the design follows: every node but the strays.
double followed_max(const Alignment& a, const std::vector<Point>& all, const std::vector<char>& stray);

} // namespace railodd::geometry::fit
