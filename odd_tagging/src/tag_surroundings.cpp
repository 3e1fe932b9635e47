// Surroundings: roads running alongside the track. Every track is probed
// every 25 m for the nearest road sample within reach whose heading is
// roughly parallel; stretches of one distance class and road class become
// Parallel road elements (the road's OSM way ids with the track's).
#include "tag_context.hpp"

#include "railodd/util/cell_grid.hpp"

#include <cmath>
#include <limits>
#include <map>
#include <set>

namespace railodd::odd {

namespace {

constexpr double sample_m = 10.0;
constexpr double probe_m = 25.0;
constexpr double reach_m = 50.0;    // the taxonomy's farthest class starts at 30 m
constexpr double max_skew = 0.26;   // |sin| of 15 degrees
constexpr double cell_m = reach_m;

struct RoadSample {
    double x, y, hdg;
    std::string road_class;
    std::int64_t way;
};

using Grid = util::CellGrid<RoadSample>;

Grid road_grid(const TagContext& ctx, const Attribute* classes) {
    std::map<std::int64_t, const ingest::Way*> ways;
    for (const auto& w : ctx.geo().ingest.roads) {
        ways[w.id] = &w;
    }
    Grid grid(cell_m);
    const auto& g = ctx.geo().geometry.roads;
    for (std::size_t e = 0; e < g.edges.size(); ++e) {
        const auto& a = ctx.geo().geometry.fitted_roads.edges[e].alignment;
        const double len = geometry::length(a);
        const auto& span = g.edges[e].ways.front();
        const auto w = ways.find(span.way_id);
        const std::string highway = w == ways.end() ? "" : ingest::tag_or(w->second->tags, "highway");
        const std::string cls = classes && classes->has_value(highway) ? highway : "other";
        for (double s = 0.0; s <= len; s += sample_m) {
            const auto p = geometry::evaluate(a, s);
            grid.add_point(p.x, p.y, {p.x, p.y, p.hdg, cls, span.way_id});
        }
    }
    return grid;
}

const RoadSample* nearest(const Grid& grid, const geometry::Pose& p, double& dist) {
    const RoadSample* best = nullptr;
    dist = std::numeric_limits<double>::infinity();
    grid.near(p.x, p.y, 1, [&](const RoadSample& r) {
        const double d = std::hypot(r.x - p.x, r.y - p.y);
        if (d < dist && d <= reach_m && std::abs(std::sin(r.hdg - p.hdg)) <= max_skew) {
            dist = d;
            best = &r;
        }
    });
    return best;
}

} // namespace

void tag_surroundings(TagContext& ctx) {
    const char* const path = "Scenery/Surroundings/Parallel road";
    const Element* el = ctx.taxonomy().find(path);
    const Attribute* classes = ctx.taxonomy().attribute(*el, "road_class");
    const Attribute* distance = ctx.taxonomy().attribute(*el, "distance");
    const Grid& grid = ctx.prepared<Grid>("surroundings", [&] { return road_grid(ctx, classes); });
    if (grid.empty()) {
        return;
    }
    for (std::size_t e = ctx.first(); e < ctx.last(); ++e) {
        const auto& ia = ctx.alignment(e);
        const int k = std::max(1, static_cast<int>(std::ceil(ia.length() / probe_m)));
        std::string key;        // distance class + road class of the open run
        double start = 0.0, closest = 0.0;
        std::string road_class;
        std::set<std::int64_t> road_ways;
        for (int i = 0; i <= k; ++i) {
            double d = 0.0;
            const RoadSample* r = i < k ? nearest(grid, ia.evaluate(ia.length() * (i + 0.5) / k), d) : nullptr;
            const std::string now = r ? classify(*distance, d) + "/" + r->road_class : "";
            const double boundary = ia.length() * i / k;
            if (now != key) {
                if (!key.empty()) {
                    auto ids = ctx.way_ids(e, start, boundary);
                    for (std::int64_t w : road_ways) {
                        ids.push_back("way:" + std::to_string(w));
                    }
                    ctx.tag(path, e, start, boundary, {{"distance", closest}, {"road_class", road_class}}, ids, "derived");
                }
                key = now;
                start = boundary;
                closest = d;
                road_ways.clear();
            }
            if (r) {
                closest = std::min(closest, d);
                road_class = r->road_class;
                road_ways.insert(r->way);
            }
        }
    }
}

} // namespace railodd::odd
