// What the fit made of the mapped nodes. Every mapped track node (from
// ingest.geojson) is measured against the nearest fitted rail road: the
// residual histogram and the node overlay; and the curvature the nodes
// themselves say, as the curvature diagram's background: the circle through
// a node and the nodes about 40 m before and after it along its way (closer
// nodes make the curvature of mapping noise: 0.3 m over 10 m reads as R 80 m).
#include "parts.hpp"

#include "railodd/util/beside.hpp"
#include "railodd/util/errors.hpp"

#include <algorithm>
#include <future>
#include <set>

namespace railodd::report::detail {

namespace {

constexpr double window_m = 40.0;
constexpr double far_m = 50.0; // a node farther from every rail road belongs to a track not in the map
constexpr double bin_m = 0.05;
constexpr std::size_t max_bins = 100; // 5 m; the last bin holds everything beyond

struct Way {
    std::vector<double> x, y;
};

void add_line(const ojson& coords, const GeoFrame& frame, std::vector<Way>& ways) {
    Way w;
    for (const auto& c : coords) {
        double x = 0, y = 0;
        frame.to_local({c.at(0).get<double>(), c.at(1).get<double>()}, x, y);
        w.x.push_back(x);
        w.y.push_back(y);
    }
    ways.push_back(std::move(w));
}

// The track ways of ingest.geojson (a clipped way is a MultiLineString).
std::vector<Way> track_ways(const std::filesystem::path& file, const GeoFrame& frame) {
    const ojson j = read_json_file(file, "mapped tracks, GeoJSON");
    if (!j.contains("features") || !j["features"].is_array()) {
        throw InputError(file.string(), "not a GeoJSON FeatureCollection (no \"features\" array)");
    }
    std::vector<Way> ways;
    reading_json(file, [&] {
        for (const auto& f : j["features"]) {
            if (f.value("properties", ojson::object()).value("layer", "") != "track" || !f.contains("geometry")) {
                continue;
            }
            const auto& g = f["geometry"];
            const std::string type = g.value("type", "");
            if (type == "LineString") {
                add_line(g.at("coordinates"), frame, ways);
            } else if (type == "MultiLineString") {
                for (const auto& part : g.at("coordinates")) {
                    add_line(part, frame, ways);
                }
            }
        }
    });
    return ways;
}

std::vector<Way> given_ways(const std::vector<std::vector<std::array<double, 2>>>& lines) {
    std::vector<Way> ways(lines.size());
    for (std::size_t i = 0; i < lines.size(); ++i) {
        for (const auto& p : lines[i]) {
            ways[i].x.push_back(p[0]);
            ways[i].y.push_back(p[1]);
        }
    }
    return ways;
}

// Signed curvature of the circle through a, b, c (+ left turn).
double menger(double ax, double ay, double bx, double by, double cx, double cy) {
    const double cross = (bx - ax) * (cy - by) - (by - ay) * (cx - bx);
    const double d = std::hypot(bx - ax, by - ay) * std::hypot(cx - bx, cy - by) * std::hypot(cx - ax, cy - ay);
    return d > 0 ? 2.0 * cross / d : 0.0;
}

// Every way's nodes on their nearest rail roads, for the residuals and the
// curvature both: half the ways on a second thread, or in turn (each query
// reads the roads only, so no hit depends on the split).
std::vector<std::vector<RoadHit>> nearest_hits(const std::vector<Way>& ways, const RoadData& roads, bool two_threads) {
    std::vector<std::vector<RoadHit>> hits(ways.size());
    const auto run = [&](std::size_t lo, std::size_t hi) {
        for (std::size_t k = lo; k < hi; ++k) {
            hits[k].reserve(ways[k].x.size());
            for (std::size_t i = 0; i < ways[k].x.size(); ++i) {
                hits[k].push_back(roads.nearest_rail(ways[k].x[i], ways[k].y[i], far_m));
            }
        }
    };
    const std::size_t half = ways.size() / 2;
    std::future<void> second = std::async(util::beside(two_threads), run, half, ways.size());
    run(0, half);
    second.get();
    return hits;
}

// Node curvature along one way, placed on the nearest rail road and signed
// along the road's growing s.
void way_curvature(const Way& w, const std::vector<RoadHit>& hits, std::vector<double>& out) {
    std::vector<double> along(w.x.size(), 0.0);
    for (std::size_t i = 1; i < w.x.size(); ++i) {
        along[i] = along[i - 1] + std::hypot(w.x[i] - w.x[i - 1], w.y[i] - w.y[i - 1]);
    }
    std::size_t a = 0, c = 0;
    for (std::size_t i = 0; i < w.x.size(); ++i) {
        while (a + 1 < i && along[i] - along[a + 1] >= window_m) ++a;
        while (c < w.x.size() && along[c] - along[i] < window_m) ++c;
        if (c >= w.x.size() || along[i] - along[a] < window_m) {
            continue;
        }
        const RoadHit& hit = hits[i];
        if (!hit.found) {
            continue;
        }
        double k = menger(w.x[a], w.y[a], w.x[i], w.y[i], w.x[c], w.y[c]);
        const double dx = w.x[c] - w.x[a], dy = w.y[c] - w.y[a];
        if (dx * std::cos(hit.hdg) + dy * std::sin(hit.hdg) < 0) {
            k = -k; // the way runs against the road
        }
        out.push_back(static_cast<double>(hit.road));
        out.push_back(cm(hit.s));
        out.push_back(std::round(k * 1e7) / 1e7);
    }
}

double quantile(std::vector<double> v, double q) {
    if (v.empty()) {
        return 0.0;
    }
    const std::size_t i = std::min(v.size() - 1, static_cast<std::size_t>(q * static_cast<double>(v.size())));
    std::nth_element(v.begin(), v.begin() + static_cast<long>(i), v.end());
    return v[i];
}

// Residuals of every distinct node; the overlay's points and the histogram.
void residuals(const std::vector<Way>& ways, const std::vector<std::vector<RoadHit>>& hits, const GeoFrame& frame,
               NodeFit& nf) {
    ojson& fit = nf.fit;
    auto& pts = nf.node_pts;
    auto& node_res = nf.node_res;
    std::set<std::pair<long long, long long>> seen;
    std::vector<double> res;
    std::vector<std::size_t> counts(max_bins, 0);
    long long plon = 0, plat = 0;
    std::size_t far = 0;
    for (std::size_t k = 0; k < ways.size(); ++k) {
        const Way& w = ways[k];
        for (std::size_t i = 0; i < w.x.size(); ++i) {
            const LonLat ll = frame.to_lonlat(w.x[i], w.y[i]);
            const long long lon = std::llround(ll.lon * 1e6), lat = std::llround(ll.lat * 1e6);
            if (!seen.insert({lon, lat}).second) {
                continue;
            }
            const RoadHit& hit = hits[k][i];
            if (!hit.found) {
                ++far;
                continue;
            }
            res.push_back(hit.distance);
            ++counts[std::min(max_bins - 1, static_cast<std::size_t>(hit.distance / bin_m))];
            pts.push_back(lon - plon);
            pts.push_back(lat - plat);
            plon = lon;
            plat = lat;
            node_res.push_back(std::llround(hit.distance * 100.0));
        }
    }
    fit["nodes"] = res.size();
    fit["nodes_far"] = far;
    fit["far_m"] = far_m;
    fit["residual_p50_m"] = cm(quantile(res, 0.5));
    fit["residual_p95_m"] = cm(quantile(res, 0.95));
    fit["residual_max_m"] = cm(res.empty() ? 0.0 : *std::max_element(res.begin(), res.end()));
    fit["histogram"] = {{"bin_m", bin_m}, {"counts", counts}};
}

// report.json's per-track figures, flagged where the residuals are more than
// the noise explains.
void track_figures(const ojson& geometry, ojson& fit) {
    fit["noise"] = geometry.value("summary", ojson::object()).value("node_noise", ojson::object());
    fit["flag_rule"] = "p95 residual over 2.5 noise sigmas, or the largest over 5";
    Array tracks;
    for (const auto& t : geometry.value("tracks", ojson::array())) {
        const double sigma = t.value("noise_sigma_m", 0.0);
        const bool flagged = sigma > 0 && (t.value("p95_m", 0.0) > 2.5 * sigma || t.value("max_m", 0.0) > 5 * sigma);
        std::string ways;
        for (const auto& w : t.value("osm_ways", ojson::array())) {
            ways += (ways.empty() ? "way:" : ",way:") + w.dump();
        }
        tracks.push_back({{"edge", t.value("edge", 0)}, {"osm_ways", ways}, {"length_m", t.value("length_m", 0.0)},
                          {"nodes", t.value("nodes", 0)}, {"rms_m", t.value("rms_m", 0.0)},
                          {"p95_m", t.value("p95_m", 0.0)}, {"max_m", t.value("max_m", 0.0)},
                          {"noise_sigma_m", sigma}, {"flagged", flagged}});
    }
    fit["tracks"] = ojson(std::move(tracks));
}

} // namespace

NodeFit node_fit(const std::filesystem::path& map_dir, const ojson& geometry, const RoadData& roads,
                 const GeoFrame& frame, const std::vector<std::vector<std::array<double, 2>>>* track_nodes,
                 bool two_threads) {
    NodeFit nf;
    nf.fit = {{"available", false}};
    track_figures(geometry, nf.fit);
    const auto file = map_dir / "ingest.geojson";
    if (!track_nodes && !std::filesystem::is_regular_file(file)) {
        nf.fit["reason"] = "ingest.geojson is not in " + map_dir.string() +
                           ": the mapped nodes are not known (convert with --debug-outputs writes it; convert's own "
                           "report.html has them)";
        return nf;
    }
    const std::vector<Way> ways = track_nodes ? given_ways(*track_nodes) : track_ways(file, frame);
    nf.fit["available"] = true;
    const std::vector<std::vector<RoadHit>> hits = nearest_hits(ways, roads, two_threads);
    residuals(ways, hits, frame, nf);
    for (std::size_t k = 0; k < ways.size(); ++k) {
        way_curvature(ways[k], hits[k], nf.curvature);
    }
    return nf;
}

} // namespace railodd::report::detail
