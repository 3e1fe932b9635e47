#include "local_frame.hpp"

#include "railodd/util/errors.hpp"

#include <algorithm>
#include <cmath>
#include <tuple>

namespace railodd::ingest {

namespace {

BBox raw_bounds(const std::vector<Way>& ways) {
    BBox b{180, 90, -180, -90};
    for (const auto& way : ways) {
        for (const auto& part : way.parts) {
            for (const auto& node : part) {
                b.west = std::min(b.west, node.lonlat.lon);
                b.east = std::max(b.east, node.lonlat.lon);
                b.south = std::min(b.south, node.lonlat.lat);
                b.north = std::max(b.north, node.lonlat.lat);
            }
        }
    }
    return b;
}

} // namespace

LonLat centre_of(const std::vector<Way>& ways) {
    const BBox b = raw_bounds(ways);
    return {(b.west + b.east) / 2, (b.south + b.north) / 2};
}

BBox lonlat_bounds(const std::vector<Way>& ways, double margin_m) {
    const BBox b = raw_bounds(ways);
    // 10 % more than a degree of latitude's length: a conservative prefilter.
    const double dlat = margin_m / 111000.0 * 1.1;
    const double max_abs_lat = std::min(89.0, std::max(std::abs(b.south), std::abs(b.north)) + dlat);
    const double dlon = dlat / std::cos(max_abs_lat * M_PI / 180.0);
    return {b.west - dlon, b.south - dlat, b.east + dlon, b.north + dlat};
}

void project_ways(std::vector<Way>& ways, const LocalProjection& proj) {
    for (auto& way : ways) {
        for (auto& part : way.parts) {
            for (auto& node : part) {
                node.xy = proj.forward(node.lonlat);
            }
        }
    }
}

void check_frame_extent(const std::vector<Way>& ways, const std::string& file) {
    for (const auto& way : ways) {
        for (const auto& part : way.parts) {
            for (const auto& node : part) {
                const double d = std::hypot(node.xy.x, node.xy.y);
                if (!(d <= max_frame_radius_m)) {
                    throw InputError(file, "way " + std::to_string(way.id) + ": node " + std::to_string(node.id) +
                                               " lies " + std::to_string(static_cast<long long>(d / 1000.0)) +
                                               " km from the centre of the selected tracks; one local map frame "
                                               "covers at most 1000 km from its centre (select less with --bbox, "
                                               "--polygon or --relation, or convert in tiles with `railodd batch`)");
                }
            }
        }
    }
}

void finalize(IngestResult& result) {
    auto by_id = [](const auto& a, const auto& b) { return a.id < b.id; };
    std::stable_sort(result.tracks.begin(), result.tracks.end(), by_id);
    std::stable_sort(result.roads.begin(), result.roads.end(), by_id);
    std::stable_sort(result.features.begin(), result.features.end(), [](const Feature& a, const Feature& b) {
        return std::tie(a.osm_type, a.id) < std::tie(b.osm_type, b.id);
    });
    std::stable_sort(result.dropped.begin(), result.dropped.end(), [](const Dropped& a, const Dropped& b) {
        return std::tie(a.kind, a.osm_type, a.id) < std::tie(b.kind, b.osm_type, b.id);
    });
    std::stable_sort(result.repairs.begin(), result.repairs.end(), [](const Repair& a, const Repair& b) {
        return std::tie(a.kind, a.osm_type, a.id) < std::tie(b.kind, b.osm_type, b.id);
    });
    result.counts.output_track_ways = result.tracks.size();
    result.counts.output_road_ways = result.roads.size();
    result.counts.output_features = result.features.size();
}

} // namespace railodd::ingest
