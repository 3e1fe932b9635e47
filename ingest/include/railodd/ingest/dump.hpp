#pragma once
// What the ingest stage produced, as report.json sections and as GeoJSON.
#include "railodd/ingest/types.hpp"

#include <nlohmann/json.hpp>

#include <ostream>
#include <string>

namespace railodd::ingest {

// {"input": {...}, "output": {...}, "projection": {...}, "dropped": [...], "repairs": [...]}
nlohmann::ordered_json report_sections(const IngestResult& result);

// Tracks, roads and features in WGS84, one GeoJSON Feature each with its OSM id and tags.
void write_geojson(const IngestResult& result, std::ostream& out);
std::string to_geojson(const IngestResult& result);

} // namespace railodd::ingest
