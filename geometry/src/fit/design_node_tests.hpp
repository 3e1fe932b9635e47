#pragma once
// Whether a node of a pass of the design search looks like a stray, in the
// pass's frame (design_node_tests.cpp says why each test is as it is).
// Beside a tied end, a point on the track past the tie stands in for the
// kept nodes the tests want beyond the first node.
#include "design_pass.hpp"

#include <array>
#include <cstddef>
#include <vector>

namespace railodd::geometry::fit {

// The pass's design spends two or more knots between node i's neighbours.
bool bent_to(const DesignPass& pass, std::size_t i);
// d bends at node i and back (a bump or an S), not only from one curve into the next.
bool bumps_at(const FrameDesign& d, const std::vector<FrameNode>& q, std::size_t i);
// Nodes [i, i + run) stand out as a spike (run 1) or a bump (run 2) among the kept nodes.
bool stands_out(const DesignPass& pass, std::size_t i, std::size_t run);
// Nodes first..last each lie further than `far` from the chord between the nodes either side.
bool off_chord(const DesignPass& pass, std::size_t first, std::size_t last, double far);
// Node i is one of the `reach` nodes next to a free end of the chain.
bool near_free_end(const DesignPass& pass, std::size_t i, std::size_t reach);
// Node i's distance from Lagrange's cubic through nodes k.
double cubic_residual(const std::vector<FrameNode>& q, const std::array<std::size_t, 4>& k, std::size_t i);
// Node i lies off the trend of its kept neighbours, by twice `far`.
bool off_trend(const DesignPass& pass, std::size_t i, double far);
// Left-out node i lies on the trend of the kept nodes beyond its two neighbours.
bool on_trend_beyond(const DesignPass& pass, std::size_t i, double far);
// Nodes a and a + 1 next to a free end's node make a bump the track comes back from.
bool bump_at_free_end(const DesignPass& pass, std::size_t a, double far);
// Nodes i and i + 1 each lie off the chord of the kept nodes around them, on opposite sides.
bool zigzag(const DesignPass& pass, std::size_t i, double far);

} // namespace railodd::geometry::fit
