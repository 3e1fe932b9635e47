#include "local_frame.hpp"

#include "railodd/util/errors.hpp"

#include <algorithm>
#include <cmath>
#include <map>
#include <numeric>
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
    // Tracks across the antimeridian span nearly 360 degrees in [-180, 180]:
    // measured in [0, 360) they are narrow, and their centre is there.
    double west = 360, east = 0;
    for (const auto& way : ways) {
        for (const auto& part : way.parts) {
            for (const auto& node : part) {
                const double lon = node.lonlat.lon < 0 ? node.lonlat.lon + 360 : node.lonlat.lon;
                west = std::min(west, lon);
                east = std::max(east, lon);
            }
        }
    }
    double lon = (b.west + b.east) / 2;
    if (east - west < b.east - b.west) {
        lon = (west + east) / 2;
        lon = lon >= 180 ? lon - 360 : lon;
    }
    return {lon, (b.south + b.north) / 2};
}

void drop_duplicate_tracks(std::vector<Way>& tracks, std::vector<Dropped>& dropped) {
    // The same nodes in the same or the reverse order: one track mapped twice.
    std::map<std::vector<std::int64_t>, std::int64_t> seen;
    std::vector<std::size_t> order(tracks.size());
    std::iota(order.begin(), order.end(), 0);
    std::sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return tracks[a].id < tracks[b].id; });
    std::vector<bool> drop(tracks.size(), false);
    for (std::size_t i : order) {
        std::vector<std::int64_t> key;
        for (const auto& part : tracks[i].parts) {
            if (!key.empty()) {
                key.push_back(0); // between parts, so that the reverse reads alike
            }
            for (const auto& n : part) key.push_back(n.id);
        }
        std::vector<std::int64_t> rev(key.rbegin(), key.rend());
        const auto& k = std::min(key, rev);
        const auto [it, fresh] = seen.emplace(k, tracks[i].id);
        if (!fresh) {
            drop[i] = true;
            const bool ogr = tracks[i].origin == Origin::ogr;
            dropped.push_back({"track", ogr ? "ogr_feature" : "way", tracks[i].id,
                               std::string{"duplicate: the same nodes as "} + (ogr ? "feature " : "way ") +
                                   std::to_string(it->second) + " (mapped twice)"});
        }
    }
    std::size_t kept = 0;
    for (std::size_t i = 0; i < tracks.size(); ++i) {
        if (!drop[i]) {
            if (kept != i) { // a vector moved onto itself would be emptied
                tracks[kept] = std::move(tracks[i]);
            }
            ++kept;
        }
    }
    tracks.resize(kept);
}

BBox lonlat_bounds(const std::vector<Way>& ways, double margin_m) {
    const BBox b = raw_bounds(ways);
    // 10 % more than a degree of latitude's length: a conservative prefilter.
    const double dlat = margin_m / 111000.0 * 1.1;
    const double max_abs_lat = std::max(std::abs(b.south), std::abs(b.north)) + dlat;
    // Near a pole, or across the antimeridian, every longitude.
    if (max_abs_lat >= 89.0 || b.east - b.west > 180.0) {
        return {-180.0, std::max(-90.0, b.south - dlat), 180.0, std::min(90.0, b.north + dlat)};
    }
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
