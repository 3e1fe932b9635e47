#pragma once
// The local picture at one node shared by several ways: which branches form a
// route through it, and on which side of another route a branch leaves. Used
// to tell a road crossing a track from a road touching it at a shared node.
#include "railodd/ingest/projection.hpp"

#include <cstddef>
#include <cstdint>
#include <limits>
#include <optional>
#include <vector>

namespace railodd::geometry::detail {

// No node has this id: marks a branch made up to extend a lone one straight.
constexpr std::int64_t no_node = std::numeric_limits<std::int64_t>::min();

// One way leaving the node: towards `neighbour`, in unit direction `dir`.
struct Branch {
    std::size_t owner = 0;  // the caller's index of the way (or edge) it belongs to
    std::int64_t neighbour = no_node;
    ingest::XY dir;
};

// Two branches forming a route through the node, or one (the way ends here).
struct Route {
    std::size_t a = 0;
    std::optional<std::size_t> b;
};

// Pairs branches greedily: branches of the same owner first (a way passing
// through), then the most nearly opposite. Routes come best first; lone
// branches last. Deterministic for a given branch order.
std::vector<Route> pair_routes(const std::vector<Branch>& branches);

// The straight continuation of a lone branch.
Branch opposite(const Branch& b);

enum class Side { left, right, along };

// Side of `b` for a path arriving from `back` and leaving towards `fwd`;
// `along` when b shares a neighbour node with the path or runs exactly on it.
Side side_of(const Branch& back, const Branch& fwd, const Branch& b);

// Unit vector from `from` to `to`; (0, 0) when they coincide.
ingest::XY unit(ingest::XY from, ingest::XY to);

// Acute angle between two lines given by direction vectors: degrees, [0, 90].
double line_angle_deg(ingest::XY u, ingest::XY v);

// The line through v measured counterclockwise from the direction u, in
// degrees in [0, 180) (a line has no direction, so 180 is 0).
double line_direction_deg(ingest::XY u, ingest::XY v);

} // namespace railodd::geometry::detail
