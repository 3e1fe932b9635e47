#pragma once
// Conversions from the geometry stage's types into OpenDRIVE records: planView
// from an alignment, elevation and superelevation cut to a road's s-range.
#include "railodd/geometry/cant.hpp"
#include "railodd/xodr/model.hpp"

#include <vector>

namespace railodd::xodr {

// One record per primitive, each starting at the exact chained pose.
std::vector<PlanGeometry> plan_view_of(const geometry::Alignment& alignment);

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
