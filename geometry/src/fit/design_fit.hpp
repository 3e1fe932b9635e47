#pragma once
// One chain's design, whole: a reference line, the design search in its
// frame (design_dp.hpp), then again with that design as the reference; the
// node noise re-estimated from each pass's residuals and the nodes
// reweighted robustly. See docs/geometry.md.
#include "design_dp.hpp"
#include "least_squares.hpp"
#include "railodd/geometry/fit_alignment.hpp"

#include <optional>
#include <vector>

namespace railodd::geometry::fit {

// The search's options as calibrated for a chain of n nodes (L0 penalty,
// curvature pull, transition prior); span, ties and knots left unset.
DesignDpOptions calibrated_options(std::size_t n);

// The search, then again with its own design's knots as candidates while
// that lowers the cost, starting from the last pass's (`seed`, where given);
// where a seed is given, its windows searched again (research_windows) and
// the seed's own structure refined as a rival.
// On the 5 m grid the true structure of a precise chain costs more than a
// wrong one (dense truth seed 1000 at 0.3 m: 1,370 against 1,197 at its own
// knots), and a search that can reach the last design's knots compares
// structures at their best.
FrameDesign search_design(const std::vector<FrameNode>& nodes, DesignDpOptions o, const std::vector<FrameElement>& seed);

// p: distinct nodes in order (at least 2). options.noise_sigma_m > 0 fixes
// the noise; else it is estimated. `guides`: parallel tracks fitted before,
// whose curvature the design is pulled to beside them (design_guide.hpp).
// `held` (per node, or empty): nodes never left out (fit_alignment.hpp).
FitResult fit_design(const std::vector<Point2>& p, const std::optional<Pose>& start, const std::optional<Pose>& end,
                     const FitOptions& options, const std::vector<IndexedAlignment>& guides,
                     const std::vector<char>& held = {});

} // namespace railodd::geometry::fit
