#pragma once
// How much the fitted network reads like a railway design, measured on the
// fit alone (no ground truth): the share of length in transitions and arcs,
// elements per kilometre, curvature sign changes, and whether tracks running
// side by side (double track, 3-6 m apart, mapped as separate ways with
// separate noise but built to one design) have the same curvature.
// report.json's geometry.summary.design (docs/geometry.md).
#include "railodd/geometry/alignment.hpp"
#include "railodd/geometry/indexed_alignment.hpp"

#include <cstddef>
#include <vector>

namespace railodd::geometry {

struct DesignSummary {
    double length_km = 0.0;
    double spiral_share = 0.0; // of the length
    double arc_share = 0.0;
    double elements_per_km = 0.0;
    // Joints between two elements inside a road, per km: where a road ends
    // (a switch, a crossing, a tag change) is no joint (issue 37 asks at
    // most 4 per km).
    double joints_per_km = 0.0;
    // Elements under 1 m, as a share of all (issue 37 asks under 0.5 %):
    // mostly corners on nodes a few metres apart (docs/BENCHMARKS.md).
    double short_element_share = 0.0;
    double sign_changes_per_km = 0.0; // of curvature (|k| > 1/20,000 m), sampled every 5 m
    // Curved points (|k| > 1/5,000 m, every 10 m) with a parallel track 3-6 m
    // beside them (within 0.05 rad of their direction, keeping that offset
    // within 0.5 m 20 m either way: not a turnout's leg or a crossover
    // passing), and the relative difference of the two curvatures (the
    // neighbour's taken at the foot, corrected for the offset of concentric
    // curves: k / (1 - k d)).
    std::size_t parallel_pairs = 0;
    double parallel_difference_p50 = 0.0;
    double parallel_difference_p95 = 0.0;
    double parallel_share_over_10pct = 0.0;
};

// two_threads: half the work on a second thread (the figures do not depend on it).
DesignSummary summarise_design(const std::vector<Alignment>& alignments, bool two_threads = false);

// Curvature sign changes along one alignment: the sign of curvatures beyond
// 1/20,000 m, sampled every 5 m, changing (straights between do not count
// as a sign). Also the ground truth's count (synthetic/alignment_truth).
std::size_t curvature_sign_changes(const IndexedAlignment& alignment);
// The same on alignments already indexed (at 2 m).
DesignSummary summarise_design(const std::vector<IndexedAlignment>& tracks, bool two_threads = false);

} // namespace railodd::geometry
