#include "context_features.hpp"

#include "railodd/geometry/indexed_alignment.hpp"

#include <cmath>

namespace railodd::sample {

namespace {

struct Point {
    double x;
    double y;
};

Point beside(const geometry::IndexedAlignment& main, double s, double offset) {
    const geometry::Pose p = main.evaluate(s);
    return {p.x - offset * std::sin(p.hdg), p.y + offset * std::cos(p.hdg)};
}

// Parallel features are traced at mapper spacing too, but more regularly than
// tracks: platform edges and kerbs are easy to follow on imagery.
std::int64_t draw_parallel(const ParallelFeature& f, const geometry::IndexedAlignment& main,
                           OsmBuilder& b, Rng& rng) {
    const bool road = f.kind == "road";
    std::vector<double> chain{f.range.s_from};
    for (;;) {
        const double next = chain.back() + (road ? rng.uniform(60.0, 120.0) : rng.uniform(20.0, 45.0));
        if (next > f.range.s_to - (road ? 30.0 : 10.0)) {
            break;
        }
        chain.push_back(next);
    }
    chain.push_back(f.range.s_to);

    std::vector<std::int64_t> ids;
    for (const double s : chain) {
        const Point p = beside(main, s, f.offset);
        ids.push_back(b.add_node(p.x, p.y, {}, Placement{"main", s, f.offset}));
    }
    return b.add_way(std::move(ids), f.tags, f.kind, "main", f.range.s_from, f.range.s_to);
}

std::int64_t draw_crossing_road(const CrossingRoad& r, const geometry::IndexedAlignment& main,
                                std::int64_t level_crossing, OsmBuilder& b) {
    const geometry::Pose at = main.evaluate(r.s);
    const double dir = at.hdg + r.angle;
    const Point u{std::cos(dir), std::sin(dir)};
    const Point n{-u.y, u.x};
    std::vector<std::int64_t> ids;
    for (const double d : r.along) {
        if (d == 0.0 && r.level) {
            ids.push_back(level_crossing);
            continue;
        }
        const double side = r.bend * d * d;
        ids.push_back(b.add_node(at.x + d * u.x + side * n.x, at.y + d * u.y + side * n.y, {},
                                 std::nullopt));
    }
    return b.add_way(std::move(ids), r.tags, "road", "", r.s, r.s);
}

} // namespace

void draw_context(const RouteDesign& d, const DrawnTracks& tracks, OsmBuilder& b, Rng& rng) {
    const geometry::IndexedAlignment main(d.main.alignment);
    std::vector<std::int64_t> platforms;
    for (const auto& f : d.parallels) {
        const std::int64_t id = draw_parallel(f, main, b, rng);
        if (f.kind == "platform") {
            platforms.push_back(id);
        }
    }
    for (const auto& r : d.crossing_roads) {
        draw_crossing_road(r, main, tracks.level_crossing, b);
    }
    const Point st = beside(main, d.station_node.s, d.station_node.offset);
    b.add_node(st.x, st.y, d.station_node.tags,
               Placement{"main", d.station_node.s, d.station_node.offset});

    // PTv2 order: each stop followed by its platform, then the ways in travel order.
    std::vector<OsmMember> members;
    for (std::size_t i = 0; i < tracks.stops.size(); ++i) {
        members.push_back({"node", tracks.stops[i], "stop"});
        if (i < platforms.size()) {
            members.push_back({"way", platforms[i], "platform"});
        }
    }
    for (const std::int64_t w : tracks.main_ways) {
        members.push_back({"way", w, ""});
    }
    b.add_relation(std::move(members),
                   {{"type", "route"},
                    {"route", "train"},
                    {"public_transport:version", "2"},
                    {"ref", "RB 42"},
                    {"name", "RB 42: Sample Valley Railway"}});
}

} // namespace railodd::sample
