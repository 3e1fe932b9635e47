#pragma once
// Track centerlines from other GIS vector sources (GeoJSON, GeoPackage,
// Shapefile, ... through GDAL/OGR), turned into the same track ways as OSM
// input by a YAML field mapping (see docs/field-mapping.md).
#include "railodd/ingest/selection.hpp"
#include "railodd/ingest/types.hpp"

#include <filesystem>

namespace railodd::ingest {

// True for file suffixes read through OGR rather than libosmium.
bool is_vector_source(const std::filesystem::path& file);

IngestResult read_vector(const std::filesystem::path& file, const std::filesystem::path& mapping,
                         const Selection& selection);

} // namespace railodd::ingest
