#pragma once
// Conversions from the geometry stage's types into OpenDRIVE records: planView
// from an alignment, elevation and superelevation cut to a road's s-range.
#include "railodd/geometry/cant.hpp"
#include "railodd/xodr/model.hpp"

#include <vector>

namespace railodd::xodr {

// No planView record is shorter than this where it can be helped.
inline constexpr double min_record_length_m = 0.01;

// One record per primitive, each starting at the exact chained pose; then
// merge_short_records(). An alignment without primitives gets one line of
// length 0 at its start.
// `rail`: curvature must stay continuous (a road's may jump where a merge needs it).
std::vector<PlanGeometry> plan_view_of(const geometry::Alignment& alignment, bool rail);

// Records under min_length merged into their neighbours, curvature kept
// continuous at every joint and the total length unchanged: a run of short
// records whose curvature nets out (zero-length records, a millimetre
// spiral-arc-spiral corner) is taken up by a line or arc beside it along its
// own circle; a run whose curvature changes (a short transition) is
// lengthened to min_length, the length taken from a line or arc beside it.
// Each record keeps its start pose, so only the joint beside the run moves,
// by about a curvature times min_length squared; every merge is checked
// against the continuity limits and undone if it breaks them. On roads that
// are not rail a spiral beside a run may also take it at its own rate.
// Left as they are: records shorter than min_length in all, and runs no
// neighbour can take within the limits.
void merge_short_records(std::vector<PlanGeometry>& records, double min_length, bool rail);

// The polynomials of [s0, s1] re-expanded about the new origin s0 (Taylor
// shift), so the profile of a piece of a track is exactly the track's.
std::vector<geometry::ElevationPoly> cut_polys(const std::vector<geometry::ElevationPoly>& polys, double s0,
                                               double s1);

// Superelevation records of a cant stretch list on [0, length], linear over
// each stretch (asin of cant/spacing is linear to 1e-4 relative at 160 mm).
std::vector<Superelevation> superelevation_of(const std::vector<geometry::CantStretch>& cant, double length,
                                              double rail_spacing_m);

// Same cut as cut_polys for superelevation records.
std::vector<Superelevation> cut_superelevation(const std::vector<Superelevation>& records, double s0, double s1);

} // namespace railodd::xodr
