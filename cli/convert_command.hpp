#pragma once
// railodd convert INPUT -o OUTDIR: ingest, fit the geometry and write the
// OpenDRIVE map of one route.
#include "command.hpp"

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace railodd::cli {

struct ConvertOptions {
    std::string input;
    std::string outdir;
    std::string date; // the map's header date; empty: the data's own
    std::string bbox;
    std::string polygon;
    std::optional<std::int64_t> relation;
    std::string field_mapping;
    std::vector<std::string> dem; // elevation rasters (GeoTIFF, HGT, VRT; several tiles)
    double road_corridor_m = 300.0;
    double node_noise_m = 0.0; // 0: estimated per chain from its nodes (report.json geometry.summary.node_noise)
    std::string fit_method = "design"; // design (the design search) or windowed (geometry::FitMethod)
    bool independent_tracks = false; // no parallel track's design offered to a track's fit
    double feature_distance_m = 50.0;
    double station_distance_m = 500.0;
    unsigned threads = 0; // 0: libosmium's default pool size
    bool no_timings = false;
    bool no_report = false; // report.html not written
    bool debug_outputs = false; // ingest.geojson, geometry.geojson, roads.geojson written
    bool odd_user_data = false; // every profile element also a <userData code="odd"> on its road in map.xodr
    bool estimate_cant = false; // equilibrium cant where railway:cant is not mapped
    bool strict = false;        // input defects that are repaired otherwise (duplicate node ids) refuse the input
    std::string odr_version = "1.7";
    std::string taxonomy; // ODD taxonomy; empty: data/odd/railway_odd.yaml
    std::string from;     // --from/--to: odd_profile.* along the route between two stations
    std::string to;
};

class ConvertCommand : public Command {
public:
    CLI::App* add(CLI::App& parent) override;
    void setup() override;
    int run() override;

private:
    ConvertOptions opt_;
};

} // namespace railodd::cli
