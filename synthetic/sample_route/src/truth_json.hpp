#pragma once
// sample_route_truth.json: the design behind the OSM file (alignments in the
// local frame, gradient profile, clean node positions, where every way and
// feature lies along its track) for tests that score fitted output.
#include "dem_writer.hpp"
#include "osm_model.hpp"
#include "route_design.hpp"

#include "railodd/ingest/projection.hpp"

#include <string>

namespace railodd::sample {

struct TruthContext {
    const RouteDesign& design;
    const OsmData& osm;
    const ingest::LocalProjection& projection;
    const DemGrid& dem;
    double noise_sigma;
};

std::string truth_json(const TruthContext& context);

} // namespace railodd::sample
