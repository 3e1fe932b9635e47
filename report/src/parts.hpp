#pragma once
// The report's data builders, one per section of the page (internal).
#include "json_text.hpp"

#include "railodd/util/cell_grid.hpp"
#include "railodd/odd/profile.hpp"
#include "railodd/xodr_check/map_lines.hpp"

#include <array>
#include <cmath>
#include <cstddef>
#include <filesystem>
#include <map>
#include <memory>
#include <string>
#include <vector>

#include "railodd/util/json_input.hpp"
#include "railodd/util/json_shape.hpp"

#include <nlohmann/json.hpp>

namespace railodd::xodr {
struct Map;
}

namespace railodd::report::detail {

using ojson = nlohmann::ordered_json;
using railodd::read_json_file;
// With JSON_DIAGNOSTICS, ordered_json's push_back re-parents every element of
// the array (O(n) per call): large arrays are built as array_t and moved into
// a value once.
using Array = ojson::array_t;

// Lengths in the page: 1 cm is finer than anything drawn.
inline double cm(double v) { return std::round(v * 100.0) / 100.0; }

struct LonLat {
    double lon = 0.0;
    double lat = 0.0;
};

// The map's local frame (its geoReference) to WGS84 and back, with PROJ.
class GeoFrame {
public:
    GeoFrame(const std::string& proj_string, const std::string& file);
    ~GeoFrame();
    GeoFrame(const GeoFrame&) = delete;
    GeoFrame& operator=(const GeoFrame&) = delete;
    LonLat to_lonlat(double x, double y) const;
    void to_local(LonLat p, double& x, double& y) const;

private:
    struct Impl;
    std::unique_ptr<Impl> impl_;
};

// A point on a road's reference line nearest to a query.
struct RoadHit {
    std::size_t road = 0;
    double s = 0.0;
    double distance = 0.0;
    double hdg = 0.0;
    bool found = false;
};

// The map's roads sampled for the page, and a grid over the rail roads'
// samples for nearest-point queries (mapped nodes to the fitted line).
class RoadData {
public:
    RoadData(const xodr_check::MapLines& map, const GeoFrame& frame);
    void write_roads(JsonText& out) const;
    ojson bounds_json() const;
    // The nearest rail road point within max_m of (x, y), refined on the
    // road's closed-form line.
    RoadHit nearest_rail(double x, double y, double max_m) const;
    // Road index by OpenDRIVE id; -1 when absent.
    long index_of(const std::string& id) const;

private:
    struct Sampled {
        std::vector<double> x, y;
    };
    const xodr_check::MapLines& map_;
    const GeoFrame& frame_;
    std::vector<Sampled> samples_;
    std::map<std::string, long> index_;
    util::CellGrid<std::pair<std::size_t, std::size_t>> grid_{50.0}; // (road, vertex) of the rail roads' samples
};

// The map convert holds, as the lines read_map_lines() gives from its file.
xodr_check::MapLines map_lines_of(const xodr::Map& map, const std::string& name);


// The chart's chains: "all tracks end to end" and long chains joined at
// track ends; longest first after the first.
ojson chains_json(const odd::OddProfile& profile, const ojson& tracks);

// Mapped nodes against the fitted line: residuals, their histogram, node
// curvature; the per-track fit figures of report.json.
struct NodeFit {
    ojson fit;                      // the "fit" section but its node arrays
    std::vector<long long> node_pts; // delta-encoded 1e-6 degree
    std::vector<long long> node_res; // cm
    std::vector<double> curvature;   // road, s, k triples
};
// geometry: report.json's "geometry" section (the tracks' figures);
// two_threads: half the nodes' nearest-road queries on a second thread.
NodeFit node_fit(const std::filesystem::path& map_dir, const ojson& geometry, const RoadData& roads,
                 const GeoFrame& frame, const std::vector<std::vector<std::array<double, 2>>>* track_nodes, bool two_threads);

// The fields the page reads of each JSON input, and the types they must have.
const std::vector<JsonField>& convert_report_shape();
const std::vector<JsonField>& coverage_shape();
const std::vector<JsonField>& manifest_shape();
const std::vector<JsonField>& play_shape();

// A JSON object read with read_json_file and checked against `shape`.
ojson read_checked_json(const std::filesystem::path& file, const std::string& what,
                        const std::vector<JsonField>& shape);

// Coverage, manifest and play results of a scenario set.
ojson scenario_section(const std::filesystem::path& dir, const std::filesystem::path& play_file,
                       const RoadData& roads);

} // namespace railodd::report::detail
