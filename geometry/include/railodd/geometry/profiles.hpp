#pragma once
// Vertical profiles of every fitted track: elevation sampled along the fitted
// alignment (DEM, else OSM `ele`, else flat), with tunnels and bridges taken
// from the tags of the ways each edge came from.
#include "railodd/geometry/cant.hpp"
#include "railodd/geometry/track_fit.hpp"
#include "railodd/geometry/vertical_profile.hpp"

#include <nlohmann/json.hpp>

namespace railodd::geometry {

// One profile per fitted edge, in edge order. dem may be null.
std::vector<VerticalProfile> fit_profiles(const TrackGraph& graph, const FittedNetwork& net,
                                          const std::vector<ingest::Way>& ways, const ingest::LocalProjection& projection,
                                          const ElevationModel* dem);

// Cant of every fitted track from its ways' railway:cant and maxspeed tags
// (estimated from speed and radius where untagged, if asked).
std::vector<std::vector<CantStretch>> fit_cants(const TrackGraph& graph, const FittedNetwork& net,
                                                const std::vector<ingest::Way>& ways, const CantOptions& options);

// report.json's "cant" section: tagged and estimated curves, maximum cant.
nlohmann::ordered_json cants_report(const std::vector<std::vector<CantStretch>>& cants);

// report.json's "vertical" section: sources, maximum gradient, stretches over 40 per mille.
nlohmann::ordered_json profiles_report(const TrackGraph& graph, const std::vector<VerticalProfile>& profiles);

} // namespace railodd::geometry
