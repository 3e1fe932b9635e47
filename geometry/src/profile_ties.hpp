#pragma once
// Heights where tracks meet. Each track's profile is fitted on its own (DEM,
// else OSM `ele`), so at a vertex the ends of the tracks differ: by
// centimetres between DEM fits, by hundreds of metres where one track carries
// ele=447 and its neighbour has no data at all. Every reader shows that as a
// step. Here each vertex gets one height and one grade (the mean of the
// measured ends meeting there), vertices without any measured track are
// interpolated over the network (harmonic in the track lengths; 0 where a
// network has no data), and every track is bent to meet its vertices by a
// cubic Hermite correction over its whole length. Tracks without data become
// that cubic, source "interpolated".
#include "railodd/geometry/track_fit.hpp"
#include "railodd/geometry/vertical_profile.hpp"

#include <vector>

namespace railodd::geometry {

struct ProfileTies {
    std::size_t vertices = 0;      // vertices where two or more track ends meet
    double max_height_step_m = 0.0; // largest difference between ends at a vertex before the ties
    std::size_t interpolated = 0;  // tracks without data given interpolated heights
};

// profiles[e] belongs to graph edge e (net.edges[e].alignment).
ProfileTies tie_profiles(const TrackGraph& graph, const FittedNetwork& net, std::vector<VerticalProfile>& profiles);

} // namespace railodd::geometry
