#pragma once
// Reads railway tracks, railway point features, platforms, stations, the
// land-use areas around the tracks, the selected route relation and the
// roads in a corridor around the tracks from an OSM file (.osm, .osm.pbf,
// .osm.bz2, .osm.gz, .opl), streaming it in passes so that only the nodes of
// selected objects are ever held in memory.
#include "railodd/ingest/selection.hpp"
#include "railodd/ingest/types.hpp"

#include <filesystem>

namespace railodd::ingest {

struct IngestOptions {
    Selection selection;
    double road_corridor_m = 300.0;   // roads with a node this close to a track are read; 0: no roads
    double feature_distance_m = 50.0; // point features and platforms farther from every track are dropped
    double station_distance_m = 500.0; // station/halt nodes are often mapped at the building
    // Road ways are read in the tracks' pass while the file's roads reference at
    // most this many nodes (about 16 bytes each); beyond, in three corridor passes.
    std::size_t road_prefetch_refs = 4'000'000;
    // Land-use areas (closed ways and multipolygons) that may hold a track.
    bool land_use = true;
    // Land-use ways are read in the tracks' pass while they reference at most
    // this many nodes; beyond, in three more passes, the ones with a node
    // within land_use_search_m of the tracks' bounds.
    std::size_t land_use_prefetch_refs = 2'000'000;
    double land_use_search_m = 2000.0;
};

IngestResult read_osm(const std::filesystem::path& file, const IngestOptions& options);

} // namespace railodd::ingest
