#pragma once
// Fitting the whole track graph. Edges that continue each other through a
// vertex (the straight route through a switch, both routes over a diamond
// crossing, a way split) are chained and fitted as one alignment, so position,
// heading and curvature are continuous across those links by construction.
// A branch leaving a switch starts (or ends) exactly with the pose and
// curvature of the chain it leaves, so its link is G2 as well.
#include "railodd/geometry/fit_alignment.hpp"
#include "railodd/geometry/track_graph.hpp"

#include <cstddef>
#include <string>
#include <vector>

namespace railodd::geometry {

struct ChainItem {
    std::size_t edge = 0;
    bool reversed = false; // the chain runs from the edge's `to` vertex to its `from` vertex
};

// How a chain end is attached: free (buffer stop, end of data, a junction
// without a through route) or tied to the chain passing through the vertex.
struct ChainEnd {
    std::size_t vertex = 0;
    bool tied = false;
    std::size_t to_chain = 0; // the chain it is tied to, if tied
};

struct Chain {
    std::vector<ChainItem> items;
    ChainEnd start, end;
};

struct FittedEdge {
    std::size_t edge = 0;
    std::size_t chain = 0;
    bool reversed = false; // alignment runs against the graph edge's node order
    Alignment alignment;
    FitQuality quality;    // the edge's mapped nodes against its alignment
};

struct LinkReport {
    std::size_t vertex = 0;
    std::size_t chain = 0;    // the branch
    std::size_t to_chain = 0; // the chain it leaves
    std::string kind;     // "through", "branch" or "free"
    double gap_m = 0.0;   // position mismatch at the link
    double heading_rad = 0.0;
    double curvature = 0.0;
};

struct FittedNetwork {
    std::vector<Chain> chains;
    std::vector<FittedEdge> edges; // one per graph edge, in edge order
    std::vector<LinkReport> branch_links;
    std::size_t untied_branch_ends = 0; // branch ends whose through chain was not fitted first (cycles)
    std::size_t degenerate_chains = 0;  // all nodes at one position: kept as zero-length lines
    // Chains built by the corner construction (corner_fit.hpp) throughout
    // because every railway fit strayed over 2 m from a mapped node; still G2,
    // links included.
    std::vector<std::size_t> corner_chains;
    // Chains kept as railway fits with nodes beyond that limit: the corners
    // that would follow them turn tighter than R 10 m (a branch drawn onto
    // its through track at an angle across the switch).
    std::vector<std::size_t> beyond_limit_chains;
    // Tied chain ends whose last ~40 m the corner construction rebuilt: the
    // railway fit missed the tied pose (no model of the last window could
    // meet it as a constraint), or followed the nodes better with that end
    // free (docs/geometry.md).
    std::size_t spliced_ends = 0;
    // Stretches round a few nodes a railway fit strayed from (beyond what
    // their noise explains, by 2 m) built by the corner construction, the
    // nodes between them fitted again as railway design (stretch_patch.hpp).
    std::size_t patched_stretches = 0;
    // Node scatter per chain (estimated from its nodes unless the options
    // gave one; 0 for degenerate chains) and the nodes left out as outliers.
    std::vector<double> chain_noise_sigma_m;
    std::size_t outlier_nodes = 0;
    // Chains reversed so that links run end -> start (chain_orientation.hpp),
    // and the links a wye or balloon loop leaves running end -> end or
    // start -> start.
    std::size_t reversed_chains = 0;
    std::size_t reversing_links = 0;
};

// Pairs edge ends at every vertex into through routes (deflection below
// max_deflection_rad) and builds the chains.
std::vector<Chain> build_chains(const TrackGraph& graph, double max_deflection_rad = 0.5);

FittedNetwork fit_track_graph(const TrackGraph& graph, const FitOptions& options);

} // namespace railodd::geometry
