// Generates the three sample files from the design, in a fixed order of
// random draws, so every run yields the same bytes.
#include "railodd/sample/sample_route.hpp"

#include "context_features.hpp"
#include "dem_writer.hpp"
#include "osm_builder.hpp"
#include "osm_xml.hpp"
#include "route_design.hpp"
#include "terrain.hpp"
#include "track_nodes.hpp"
#include "truth_json.hpp"

#include "railodd/util/output_stage.hpp"

#include <algorithm>

namespace railodd::sample {

namespace {

constexpr std::uint64_t seed = 20240607;
constexpr double noise_sigma = 0.3; // m, per axis: careful tracing on good imagery
constexpr double dem_margin = 1000.0;

constexpr const char* osm_name = "sample_route.osm";
constexpr const char* dem_name = "sample_route_dem.tif";
constexpr const char* truth_name = "sample_route_truth.json";

DemGrid grid_around(const OsmData& osm) {
    double min_lon = osm.nodes.front().lon, max_lon = min_lon;
    double min_lat = osm.nodes.front().lat, max_lat = min_lat;
    for (const auto& n : osm.nodes) {
        min_lon = std::min(min_lon, n.lon);
        max_lon = std::max(max_lon, n.lon);
        min_lat = std::min(min_lat, n.lat);
        max_lat = std::max(max_lat, n.lat);
    }
    return dem_grid(min_lon, min_lat, max_lon, max_lat, dem_margin);
}

} // namespace

SampleFiles write_sample_route(const std::filesystem::path& dir) {
    const RouteDesign design = make_route_design();
    const ingest::LocalProjection projection({design.origin_lon, design.origin_lat});
    Rng rng(seed);
    OsmBuilder builder(projection, rng, noise_sigma);
    const DrawnTracks tracks = draw_tracks(design, builder, rng);
    draw_context(design, tracks, builder, rng);
    const OsmData& osm = builder.data();

    const DemGrid grid = grid_around(osm);
    const std::vector<float> elevations = sample_terrain(Terrain(design), grid, projection);

    OutputStage stage(dir);
    stage.write_text(osm_name, to_osm_xml(osm));
    write_dem(stage.staged_path(dem_name), grid, elevations);
    stage.write_text(truth_name, truth_json({design, osm, projection, grid, noise_sigma}));
    stage.commit();
    return {dir / osm_name, dir / dem_name, dir / truth_name};
}

} // namespace railodd::sample
