#include "truth_json.hpp"

#include "terrain.hpp"

#include <nlohmann/json.hpp>

#include <cmath>
#include <numbers>
#include <optional>
#include <string>

namespace railodd::sample {

namespace {

using json = nlohmann::ordered_json;

constexpr double profile_sample_step = 10.0;

std::optional<std::string> tag(const Tags& tags, const std::string& key) {
    for (const auto& [k, v] : tags) {
        if (k == key) {
            return v;
        }
    }
    return std::nullopt;
}

json tags_json(const Tags& tags) {
    json j = json::object();
    for (const auto& [k, v] : tags) {
        j[k] = v;
    }
    return j;
}

// Where a branch track meets the main line: its chainage there and the
// branch's own chainage at that point.
json junctions_json(const RouteDesign& d, const TrackDesign& t) {
    json j = json::array();
    const double end = geometry::length(t.alignment);
    if (&t == &d.loop) {
        j.push_back({{"track", "main"}, {"s", d.switch_loop_west}, {"at", 0.0}});
        j.push_back({{"track", "main"}, {"s", d.switch_loop_east}, {"at", end}});
    } else if (&t == &d.spur) {
        j.push_back({{"track", "main"}, {"s", d.switch_spur}, {"at", 0.0}});
    }
    return j;
}

json track_json(const RouteDesign& d, const TrackDesign& t) {
    json prims = json::array();
    const auto s0 = geometry::primitive_s(t.alignment);
    for (std::size_t i = 0; i < t.alignment.primitives.size(); ++i) {
        const auto& p = t.alignment.primitives[i];
        prims.push_back({{"kind", geometry::to_string(p.kind)},
                         {"s", s0[i]},
                         {"length", p.length},
                         {"curv_start", p.curv_start},
                         {"curv_end", p.curv_end}});
    }
    const auto& st = t.alignment.start;
    return {{"name", t.name},
            {"length", geometry::length(t.alignment)},
            {"start", {{"x", st.x}, {"y", st.y}, {"hdg", st.hdg}}},
            {"primitives", prims},
            {"junctions", junctions_json(d, t)}};
}

// Cant (mm) tagged on the main-line way that holds the whole arc, 0 if none.
double cant_of(const RouteDesign& d, const TrackDesign& t, double s_from, double s_to) {
    if (&t != &d.main) {
        return 0.0;
    }
    for (const auto& w : d.main_ways) {
        if (w.s_from <= s_from && w.s_to >= s_to) {
            return std::stod(tag(w.tags, "railway:cant").value_or("0"));
        }
    }
    return 0.0;
}

// One entry per arc, with the clothoids that lead into and out of it.
json curves_json(const RouteDesign& d, const TrackDesign& t) {
    json curves = json::array();
    const auto& p = t.alignment.primitives;
    const auto s0 = geometry::primitive_s(t.alignment);
    for (std::size_t i = 0; i < p.size(); ++i) {
        if (p[i].kind != geometry::PrimitiveKind::arc) {
            continue;
        }
        const bool in = i > 0 && p[i - 1].kind == geometry::PrimitiveKind::spiral;
        const bool out = i + 1 < p.size() && p[i + 1].kind == geometry::PrimitiveKind::spiral;
        const double k = p[i].curv_start;
        curves.push_back({{"track", t.name},
                          {"direction", k > 0.0 ? "left" : "right"},
                          {"radius", 1.0 / std::abs(k)},
                          {"s_from", s0[i]},
                          {"s_to", s0[i] + p[i].length},
                          {"transition_in", in ? p[i - 1].length : 0.0},
                          {"transition_out", out ? p[i + 1].length : 0.0},
                          {"cant_mm", cant_of(d, t, s0[i], s0[i] + p[i].length)}});
    }
    return curves;
}

json nodes_json(const OsmData& osm) {
    json nodes = json::array();
    for (const auto& n : osm.nodes) {
        json j = {{"id", n.id}, {"x", n.x}, {"y", n.y}};
        if (n.placement) {
            j["track"] = n.placement->track;
            j["s"] = n.placement->s;
            j["offset"] = n.placement->offset;
        }
        if (!n.tags.empty()) {
            j["tags"] = tags_json(n.tags);
        }
        nodes.push_back(std::move(j));
    }
    return nodes;
}

json ways_json(const OsmData& osm) {
    json ways = json::array();
    for (const auto& w : osm.ways) {
        json j = {{"id", w.id}, {"kind", w.kind}, {"nodes", w.nodes}, {"tags", tags_json(w.tags)}};
        if (!w.track.empty()) {
            j["track"] = w.track;
            j["s_from"] = w.s_from;
            j["s_to"] = w.s_to;
        }
        ways.push_back(std::move(j));
    }
    return ways;
}

json elevation_json(const VerticalProfile& profile, double length) {
    json pvis = json::array();
    for (const auto& p : profile.pvis()) {
        pvis.push_back({{"s", p.s}, {"z", p.z}});
    }
    json samples = json::array();
    const auto n = static_cast<int>(std::ceil(length / profile_sample_step));
    double max_grade = 0.0;
    for (int i = 0; i <= n; ++i) {
        const double s = std::min(i * profile_sample_step, length);
        max_grade = std::max(max_grade, std::abs(profile.grade(s)));
        samples.push_back({{"s", s}, {"z", profile.elevation(s)}, {"grade", profile.grade(s)}});
    }
    return {{"track", "main"},
            {"vertical_radius", profile.vertical_radius()},
            {"max_grade_permille", 1000.0 * max_grade},
            {"pvi", pvis},
            {"samples", samples}};
}

json point_json(const OsmNode& n) {
    json j = {{"id", n.id}, {"x", n.x}, {"y", n.y}};
    if (n.placement) {
        j["track"] = n.placement->track;
        j["s"] = n.placement->s;
        j["offset"] = n.placement->offset;
    }
    for (const char* key : {"ref", "name", "railway:signal:direction", "railway:position"}) {
        if (auto v = tag(n.tags, key)) {
            j[key] = *v;
        }
    }
    return j;
}

// Tagged nodes grouped by what they are.
json point_features_json(const RouteDesign& d, const OsmData& osm) {
    json f = {{"switches", json::array()},       {"signals", json::array()},
              {"level_crossings", json::array()}, {"stations", json::array()},
              {"stops", json::array()},          {"milestones", json::array()},
              {"buffer_stops", json::array()}};
    for (const auto& n : osm.nodes) {
        const auto railway = tag(n.tags, "railway");
        if (!railway) {
            continue;
        }
        json j = point_json(n);
        if (*railway == "switch") {
            const double s = n.placement ? n.placement->s : 0.0;
            j["branch"] = s == d.switch_spur ? "spur" : "loop";
            j["branch_end"] = s == d.switch_loop_east ? "end" : "start";
            f["switches"].push_back(std::move(j));
        } else if (*railway == "signal") {
            j["type"] = tag(n.tags, "railway:signal:main") ? "main" : "distant";
            f["signals"].push_back(std::move(j));
        } else if (*railway == "level_crossing") {
            f["level_crossings"].push_back(std::move(j));
        } else if (*railway == "station" || *railway == "halt") {
            j["type"] = *railway;
            f["stations"].push_back(std::move(j));
            if (*railway == "halt") {
                f["stops"].push_back(point_json(n));
            }
        } else if (*railway == "stop") {
            f["stops"].push_back(std::move(j));
        } else if (*railway == "milestone") {
            f["milestones"].push_back(std::move(j));
        } else if (*railway == "buffer_stop") {
            f["buffer_stops"].push_back(std::move(j));
        }
    }
    return f;
}

json way_features_json(const RouteDesign& d, const OsmData& osm) {
    json platforms = json::array();
    json tunnels = json::array();
    json bridges = json::array();
    json roads = json::array();
    for (const auto& w : osm.ways) {
        json j = {{"way", w.id}, {"s_from", w.s_from}, {"s_to", w.s_to}};
        if (w.kind == "platform") {
            j["name"] = tag(w.tags, "name").value_or("");
            for (const auto& p : d.parallels) {
                if (p.range.s_from == w.s_from) {
                    j["offset"] = p.offset;
                }
            }
            platforms.push_back(std::move(j));
        } else if (tag(w.tags, "tunnel")) {
            j["name"] = tag(w.tags, "tunnel:name").value_or("");
            tunnels.push_back(std::move(j));
        } else if (tag(w.tags, "bridge")) {
            j["name"] = tag(w.tags, "bridge:name").value_or("");
            bridges.push_back(std::move(j));
        }
    }
    constexpr double deg = 180.0 / std::numbers::pi;
    for (const auto& r : d.crossing_roads) {
        roads.push_back({{"name", tag(r.tags, "name").value_or("")},
                         {"highway", tag(r.tags, "highway").value_or("")},
                         {"crosses_main_at", r.s},
                         {"angle_deg", r.angle * deg},
                         {"level_crossing", r.level}});
    }
    return {{"platforms", platforms}, {"tunnels", tunnels}, {"bridges", bridges}, {"crossing_roads", roads}};
}

json dem_json(const DemGrid& g) {
    return {{"file", "sample_route_dem.tif"},
            {"crs", "EPSG:4326"},
            {"west", g.west},
            {"north", g.north},
            {"step_deg", g.step},
            {"cols", g.cols},
            {"rows", g.rows},
            {"nodata", dem_nodata},
            {"hill_height_m", Terrain::hill_height},
            {"valley_depth_m", Terrain::valley_depth},
            {"undulation_amplitude_m", Terrain::undulation_amplitude}};
}

} // namespace

std::string truth_json(const TruthContext& c) {
    const RouteDesign& d = c.design;
    json features = point_features_json(d, c.osm);
    features.update(way_features_json(d, c.osm));
    json curves = curves_json(d, d.main);
    for (const auto* t : {&d.loop, &d.spur}) {
        for (auto& e : curves_json(d, *t)) {
            curves.push_back(std::move(e));
        }
    }
    const json root = {
        {"generator", "railodd sample"},
        {"frame", {{"origin_lon", c.projection.origin().lon},
                   {"origin_lat", c.projection.origin().lat},
                   {"proj", c.projection.proj_string()},
                   {"units", "m"}}},
        {"noise_sigma_m", c.noise_sigma},
        {"tracks", {track_json(d, d.main), track_json(d, d.loop), track_json(d, d.spur)}},
        {"curves", curves},
        {"elevation", elevation_json(d.profile, geometry::length(d.main.alignment))},
        {"features", features},
        {"route_relation", c.osm.relations.empty() ? json() : json(c.osm.relations.front().id)},
        {"ways", ways_json(c.osm)},
        {"nodes", nodes_json(c.osm)},
        {"dem", dem_json(c.dem)},
    };
    return root.dump(1) + "\n";
}

} // namespace railodd::sample
