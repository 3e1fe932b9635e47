#pragma once
// What the geometry stage produced: report.json's "geometry" section (per
// track residuals, primitive counts, link continuity) and a GeoJSON of the
// fitted centrelines sampled back to WGS84.
#include "railodd/geometry/indexed_alignment.hpp"
#include "railodd/geometry/track_fit.hpp"
#include "railodd/ingest/projection.hpp"

#include <nlohmann/json.hpp>

#include <ostream>
#include <string>
#include <vector>

namespace railodd::geometry {

// `indexed`, where given: net's alignments indexed at 2 m, one per fitted
// edge (convert made them to place the features), not indexed again here.
// two_threads: the design summary on a second thread, beside the tracks' figures.
nlohmann::ordered_json report_section(const TrackGraph& graph, const FittedNetwork& net,
                                      const std::vector<IndexedAlignment>* indexed = nullptr, bool two_threads = false);

void write_geojson(const TrackGraph& graph, const FittedNetwork& net, const ingest::LocalProjection& projection,
                   const char* layer, std::ostream& out);
std::string to_geojson(const TrackGraph& graph, const FittedNetwork& net, const ingest::LocalProjection& projection,
                       const char* layer);

} // namespace railodd::geometry
