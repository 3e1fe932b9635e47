#pragma once
// One chain's centreline from its mapped nodes and tied end poses: the
// railway fit where it follows the nodes, the corner construction where it
// does not, and both spliced where only some stretches go wrong (next to a
// tied end, or round a few nodes). Whatever is chosen is G2 and meets the
// tied poses exactly.
#include "railodd/geometry/fit_alignment.hpp"

#include <cstddef>
#include <optional>
#include <vector>

namespace railodd::geometry {

enum class ChainMethod {
    railway, // fit_alignment as it is
    spliced, // fit_alignment with the stretch next to a tied end rebuilt by corners
    patched, // corners round the nodes fit_alignment strays from, fit_alignment again between (stretch_patch.hpp)
    corners, // the corner construction throughout
};

struct ChainFit {
    Alignment alignment;
    ChainMethod method = ChainMethod::railway;
    std::size_t spliced_ends = 0;
    std::size_t patched_stretches = 0;
    double noise_sigma_m = 0.0; // node scatter the railway fit assumed (FitQuality)
    std::size_t outliers = 0;   // nodes it left out as outliers
    // Nodes lie beyond the chain's limit, and the corners that would follow
    // them turn tighter than any track: the railway fit is kept.
    bool beyond_limit = false;
};

// guides: parallel tracks' fitted alignments; held: indices of points never
// taken for strays, ascending (fit_alignment.hpp).
ChainFit fit_chain_points(const std::vector<Point>& points, const std::optional<Pose>& start,
                          const std::optional<Pose>& end, const FitOptions& options,
                          const std::vector<IndexedAlignment>& guides = {}, const std::vector<std::size_t>& held = {});

} // namespace railodd::geometry
