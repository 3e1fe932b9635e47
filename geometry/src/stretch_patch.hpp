#pragma once
// A chain whose railway fit misses a few nodes by far more than their noise
// (a kink in the mapping, a tram corner, a stray the fit could not tell
// from the track) is cut there: the stretch round the missed nodes is built
// by the clothoid corners (corner_fit.hpp) and the nodes between such
// stretches are fitted again on their own, so a miss neither turns the
// whole chain into corners nor leaves the rest of the design pulled aside
// (chain_fit.cpp decides when).
#include "railodd/geometry/corner_fit.hpp"

#include <cstddef>
#include <optional>
#include <utility>
#include <vector>

namespace railodd::geometry {

// Node ranges [a, b] round each node that `fit` passes further than `limit`
// from: `reach` nodes either side, run on to the chain's end, or merged
// with the next range, where fewer than `min_run` nodes would lie between
// (too few to fit again). Nodes flagged in `skip` (strays the fit left out)
// are not judged. Ascending.
std::vector<std::pair<std::size_t, std::size_t>> missed_stretches(const Alignment& fit, const std::vector<Point>& points,
                                                                  const std::vector<char>& skip, double limit,
                                                                  std::size_t min_run, std::size_t reach = 2);

// The node runs between the stretches (each shares its end nodes with the
// stretches beside it), in order: what is fitted again.
std::vector<std::pair<std::size_t, std::size_t>> runs_between(
    const std::vector<std::pair<std::size_t, std::size_t>>& stretches, std::size_t nodes);

// The stretches with the runs whose fit failed (`ok[i]` 0 for runs[i])
// taken into them, merged where they touch: a failed run is built by
// corners with the stretches beside it, not the whole chain. Ascending.
std::vector<std::pair<std::size_t, std::size_t>> with_failed_runs(
    std::vector<std::pair<std::size_t, std::size_t>> stretches,
    const std::vector<std::pair<std::size_t, std::size_t>>& runs, const std::vector<char>& ok);

// The chain assembled from the fits of the runs (runs_between, in order)
// and the corner construction across each stretch, from the pose where the
// fit before it ends (the chain's start tie, or free, at the chain's start)
// to the pose where the fit after it begins. G2 throughout. Empty where a
// stretch's corners pass further than `limit` from the polyline through its
// nodes: from a pose in a curve, the construction's first straight can meet
// the polyline far off across a long gap (sparse truth seed 1058 at 0.3 m:
// 59 m off between nodes 350 m apart).
std::optional<Alignment> assemble_patched(const std::vector<Point>& points,
                                          const std::vector<std::pair<std::size_t, std::size_t>>& stretches,
                                          const std::vector<Alignment>& run_fits, const std::optional<Pose>& start,
                                          const std::optional<Pose>& end, const CornerFitOptions& options,
                                          double limit);

} // namespace railodd::geometry
