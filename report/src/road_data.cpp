// Roads for the page: each reference line sampled evenly in s, in WGS84, its
// elevation at the same samples and its curvature at the record joints (the
// curvature diagram's exact corners); and a grid over the rail roads to find
// the fitted point nearest a mapped node.
#include "parts.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace railodd::report::detail {

namespace {

// 10 m keeps a 150 m curve within 0.1 m of its chord, finer than a track's
// width at any zoom the page is read at.
constexpr double sample_step_m = 10.0;

// A length a hair over a multiple of the step counts as that multiple: the
// page convert writes from memory (20.000000000000004 m) and the one read
// back from map.xodr (written as 20) must sample a road alike.
std::size_t sample_count(double length) {
    return std::max<std::size_t>(2, static_cast<std::size_t>(std::ceil(length / sample_step_m - 1e-9)) + 1);
}

long long micro(double deg) { return std::llround(deg * 1e6); }

// Curvature at the joints of the records: pairs (s, k), linear between. A
// poly3 / paramPoly3 record's curvature is not linear: sampled at eighths.
std::vector<double> curvature_pairs(const xodr_check::MapRoad& road) {
    std::vector<double> k;
    double last_s = -1.0, last_k = std::numeric_limits<double>::quiet_NaN();
    const auto add = [&](double s, double kv) {
        kv = std::round(kv * 1e7) / 1e7;
        s = cm(s);
        if (s == last_s && kv == last_k) {
            return;
        }
        k.push_back(s);
        k.push_back(kv);
        last_s = s;
        last_k = kv;
    };
    for (const auto& g : road.geometries) {
        const bool linear = g.kind == xodr_check::GeometryKind::line || g.kind == xodr_check::GeometryKind::arc ||
                            g.kind == xodr_check::GeometryKind::spiral;
        const int steps = linear ? 1 : 8;
        for (int i = 0; i <= steps; ++i) {
            const double ds = g.length * i / steps;
            add(g.s + ds, xodr_check::evaluate(g, ds).curvature);
        }
    }
    return k;
}

} // namespace

RoadData::RoadData(const xodr_check::MapLines& map, const GeoFrame& frame) : map_(map), frame_(frame) {
    samples_.resize(map.roads.size());
    for (std::size_t i = 0; i < map.roads.size(); ++i) {
        const auto& road = map.roads[i];
        index_.emplace(road.id, static_cast<long>(i));
        const std::size_t n = sample_count(road.length);
        auto& smp = samples_[i];
        smp.x.reserve(n);
        smp.y.reserve(n);
        for (std::size_t j = 0; j < n; ++j) {
            const auto p = road.pose(road.length * static_cast<double>(j) / static_cast<double>(n - 1));
            smp.x.push_back(p.x);
            smp.y.push_back(p.y);
            if (road.rail) {
                grid_.add_point(p.x, p.y, {i, j});
            }
        }
    }
}

long RoadData::index_of(const std::string& id) const {
    const auto it = index_.find(id);
    return it == index_.end() ? -1 : it->second;
}

void RoadData::write_roads(JsonText& out) const {
    out.open('[');
    std::vector<long long> pts, z;
    for (std::size_t i = 0; i < map_.roads.size(); ++i) {
        const auto& road = map_.roads[i];
        const auto& smp = samples_[i];
        pts.clear();
        z.clear();
        long long plon = 0, plat = 0, pz = 0;
        for (std::size_t j = 0; j < smp.x.size(); ++j) {
            const LonLat ll = frame_.to_lonlat(smp.x[j], smp.y[j]);
            const long long lon = micro(ll.lon), lat = micro(ll.lat);
            pts.push_back(lon - plon);
            pts.push_back(lat - plat);
            plon = lon;
            plat = lat;
            if (!road.elevations.empty()) {
                const double s = road.length * static_cast<double>(j) / static_cast<double>(smp.x.size() - 1);
                const long long zc = std::llround(road.elevation(s) * 100.0);
                z.push_back(zc - pz);
                pz = zc;
            }
        }
        out.open('{').key("id").string(road.id).key("rail").boolean(road.rail).key("junction").string(road.junction);
        out.key("length").number(cm(road.length)).key("name").string(road.name).key("osm").string(road.osm_ids);
        out.key("pts").integers(pts).key("z");
        if (road.elevations.empty()) {
            out.value(nullptr);
        } else {
            out.integers(z);
        }
        out.key("k").numbers(curvature_pairs(road)).close('}');
    }
    out.close(']');
}

ojson RoadData::bounds_json() const {
    double w = 180, s = 90, e = -180, n = -90;
    for (std::size_t i = 0; i < samples_.size(); ++i) {
        for (std::size_t j = 0; j < samples_[i].x.size(); j += std::max<std::size_t>(1, samples_[i].x.size() - 1)) {
            const LonLat ll = frame_.to_lonlat(samples_[i].x[j], samples_[i].y[j]);
            w = std::min(w, ll.lon), e = std::max(e, ll.lon), s = std::min(s, ll.lat), n = std::max(n, ll.lat);
        }
    }
    return ojson::array({w, s, e, n});
}

namespace {

// The s of the point of segment (a, b) nearest to (x, y), as a fraction.
double segment_fraction(double ax, double ay, double bx, double by, double x, double y) {
    const double dx = bx - ax, dy = by - ay;
    const double len2 = dx * dx + dy * dy;
    return len2 > 0 ? std::clamp(((x - ax) * dx + (y - ay) * dy) / len2, 0.0, 1.0) : 0.0;
}

} // namespace

RoadHit RoadData::nearest_rail(double x, double y, double max_m) const {
    RoadHit best;
    double best_d2 = max_m * max_m;
    // A segment spans at most one cell more than its samples.
    const auto reach = static_cast<std::int64_t>(std::ceil(max_m / grid_.cell_size())) + 1;
    grid_.near(x, y, reach, [&](const std::pair<std::size_t, std::size_t>& at) {
        const auto [road, j] = at;
        const auto& smp = samples_[road];
        for (std::size_t k = j == 0 ? 0 : j - 1; k <= j && k + 1 < smp.x.size(); ++k) {
            const double f = segment_fraction(smp.x[k], smp.y[k], smp.x[k + 1], smp.y[k + 1], x, y);
            const double px = smp.x[k] + f * (smp.x[k + 1] - smp.x[k]);
            const double py = smp.y[k] + f * (smp.y[k + 1] - smp.y[k]);
            const double d2 = (px - x) * (px - x) + (py - y) * (py - y);
            if (d2 < best_d2 || (d2 == best_d2 && best.found && road < best.road)) {
                const double len = map_.roads[road].length;
                const double n1 = static_cast<double>(smp.x.size() - 1);
                best = {road, len * (static_cast<double>(k) + f) / n1, 0.0, 0.0, true};
                best_d2 = d2;
            }
        }
    });
    if (!best.found) {
        return best;
    }
    // Newton steps along the closed-form line: the chord is up to 0.1 m off.
    const auto& road = map_.roads[best.road];
    for (int it = 0; it < 3; ++it) {
        const auto p = road.pose(best.s);
        best.s = std::clamp(best.s + (x - p.x) * std::cos(p.hdg) + (y - p.y) * std::sin(p.hdg), 0.0, road.length);
    }
    const auto p = road.pose(best.s);
    best.distance = std::hypot(x - p.x, y - p.y);
    best.hdg = p.hdg;
    return best;
}

} // namespace railodd::report::detail
