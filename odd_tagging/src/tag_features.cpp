// Point and stretch features: switches, buffer stops, level and footpath
// crossings, diamond crossings, tunnels and bridges (with GNSS outage),
// stations, halts, platforms, signals and milestones.
#include "tag_context.hpp"

#include "railodd/odd/tag_values.hpp"

#include <array>
#include <cmath>
#include <set>

namespace railodd::odd {

namespace {

std::string id_of(const ingest::Feature& f) { return f.osm_type + ":" + std::to_string(f.id); }

std::vector<TaggedAttribute> switch_attributes(const TagContext& ctx, std::int64_t node, const std::string& direction) {
    std::vector<TaggedAttribute> a;
    const ingest::Feature* f = ctx.feature_at_node(node);
    const Element* el = ctx.taxonomy().find("Scenery/Track layout/Switch");
    const std::string type = f ? ingest::tag_or(f->tags, "railway:switch", "default") : "default";
    const Attribute* ta = ctx.taxonomy().attribute(*el, "type");
    a.push_back({"type", ta && ta->has_value(type) ? type : std::string{"default"}});
    if (!direction.empty()) {
        a.push_back({"direction", direction});
    }
    const std::string side = f ? ingest::tag_or(f->tags, "railway:turnout_side") : "";
    if (side == "left" || side == "right") {
        a.push_back({"turnout_side", side});
    }
    return a;
}

struct SwitchAt {
    std::size_t edge = 0;
    double s = 0.0;
    std::int64_t node_id = 0;
    std::string node; // "node:ID"
    std::string direction;
};

// Written switches sit at s of their main-track connecting road; vertices of
// kind switch that got no <switch> (an untied branch) are tagged at the
// vertex. Every switch of the layout once, whichever batch holds its edge.
std::vector<SwitchAt> switches_of(TagContext& ctx) {
    std::map<std::size_t, std::pair<std::size_t, double>> road_to_edge; // road index -> (edge, s0)
    for (std::size_t e = 0; e < ctx.map().rail.pieces.size(); ++e) {
        for (const auto& p : ctx.map().rail.pieces[e]) {
            road_to_edge[p.road] = {e, p.s0};
        }
    }
    for (const auto& [e, p] : ctx.map().rail.copies) {
        road_to_edge[p.road] = {e, p.s0};
    }
    std::map<std::string, std::size_t> road_index;
    for (std::size_t i = 0; i < ctx.map().map.roads.size(); ++i) {
        road_index[ctx.map().map.roads[i].id] = i;
    }
    std::vector<SwitchAt> out;
    std::set<std::string> done;
    for (const auto& road : ctx.map().map.roads) {
        for (const auto& sw : road.switches) {
            const auto [edge, s0] = road_to_edge.at(road_index.at(sw.main_track.road_id));
            const std::string node = sw.user_data.empty() ? "" : sw.user_data.front().value;
            if (done.count(node)) {
                continue; // a slip with two <switch> at one vertex is one switch of the layout
            }
            // Running along the main track road with increasing s from the
            // switch point passes the points from the toe.
            out.push_back({edge, s0 + sw.main_track.s, std::stoll(node.substr(node.find(':') + 1)), node,
                           sw.main_track.dir == "+" ? "facing" : "trailing"});
            done.insert(node);
        }
    }
    const auto& g = ctx.geo().geometry.tracks;
    for (const auto& v : g.vertices) {
        const std::string node = "node:" + std::to_string(v.node_id);
        if (v.kind != geometry::VertexKind::switch_ || done.count(node) || v.edges.empty()) {
            continue;
        }
        const std::size_t e = v.edges.front();
        const auto& fe = ctx.geo().geometry.fitted_tracks.edges[e];
        const bool at_start = (fe.reversed ? g.edges[e].to : g.edges[e].from) == static_cast<std::size_t>(&v - g.vertices.data());
        out.push_back({e, at_start ? 0.0 : ctx.alignment(e).length(), v.node_id, node, ""});
    }
    return out;
}

void tag_switches(TagContext& ctx) {
    const auto& switches = ctx.prepared<std::vector<SwitchAt>>("switches", [&] { return switches_of(ctx); });
    for (const SwitchAt& sw : switches) {
        if (ctx.in_batch(sw.edge)) {
            ctx.tag("Scenery/Track layout/Switch", sw.edge, sw.s, sw.s, switch_attributes(ctx, sw.node_id, sw.direction),
                    {sw.node}, "osm+derived");
        }
    }
}

// Where road users cross: the crossing road's id and s in map.xodr and its
// lanes there (scenarios put road users on them, not beside the track).
void add_crossing_road(const TagContext& ctx, const geometry::RoadRailCrossing& c, std::vector<TaggedAttribute>& a) {
    const auto road = xodr::crossing_road(ctx.map(), c.road_way_id, c.point);
    if (!road) {
        return;
    }
    a.push_back({"crossing_road_id", road->road_id});
    a.push_back({"crossing_road_s", road->s});
    a.push_back({"crossing_road_length", road->length});
    const std::pair<const char*, int> lanes[] = {{"crossing_road_forward_lane", road->forward_lane},
                                                 {"crossing_road_backward_lane", road->backward_lane},
                                                 {"crossing_road_forward_walk", road->forward_walk},
                                                 {"crossing_road_backward_walk", road->backward_walk}};
    for (const auto& [name, lane] : lanes) {
        if (lane != 0) {
            a.push_back({name, static_cast<double>(lane)});
        }
    }
}

void tag_crossings(TagContext& ctx) {
    static const std::set<std::string> foot{"footway", "path", "cycleway", "pedestrian", "steps", "bridleway"};
    using Roads = std::map<std::int64_t, const ingest::Way*>;
    const Roads& roads = ctx.prepared<Roads>("crossing_roads", [&] {
        Roads r;
        for (const auto& w : ctx.geo().ingest.roads) {
            r[w.id] = &w;
        }
        return r;
    });
    for (const auto& c : ctx.geo().geometry.crossings.road_rail) {
        if (c.grade_separated || !ctx.in_batch(c.edge)) {
            continue;
        }
        const double s = ctx.alignment(c.edge).project(c.point.x, c.point.y).s;
        const auto rw = roads.find(c.road_way_id);
        const std::string highway = rw == roads.end() ? "" : ingest::tag_or(rw->second->tags, "highway");
        const bool footpath = foot.count(highway) > 0;
        std::vector<TaggedAttribute> a;
        std::vector<std::string> ids{"way:" + std::to_string(c.road_way_id)};
        if (const ingest::Feature* f = c.level_crossing_node ? ctx.feature_at_node(c.level_crossing_node) : nullptr) {
            ids.push_back(id_of(*f));
            const auto barrier = parse_crossing_barrier(ingest::tag_or(f->tags, "crossing:barrier"));
            if (barrier.ok()) {
                a.push_back({"barrier", std::string{to_string(*barrier.value)}});
            }
            for (const char* key : {"lights", "bell"}) {
                const auto b = parse_bool(ingest::tag_or(f->tags, std::string{"crossing:"} + (key[0] == 'l' ? "light" : "bell")));
                if (b.ok()) {
                    a.push_back({key, *b.value});
                }
            }
        }
        add_crossing_road(ctx, c, a);
        if (!footpath) {
            const Element* el = ctx.taxonomy().find("Scenery/Crossings/Level crossing");
            const Attribute* rc = ctx.taxonomy().attribute(*el, "road_class");
            a.push_back({"road_class", rc && rc->has_value(highway) ? highway : std::string{"other"}});
            a.push_back({"angle", c.angle_deg});
            a.push_back({"road_line_deg", c.road_line_deg}); // for placing road users on the road (scenarios)
        }
        ctx.tag(footpath ? "Scenery/Crossings/Footpath crossing" : "Scenery/Crossings/Level crossing", c.edge, s, s, a, ids,
                "osm+derived");
    }
    for (const auto& c : ctx.geo().geometry.crossings.tracks) {
        if (c.grade_separated || !ctx.in_batch(c.edge_a)) {
            continue;
        }
        const double s = ctx.alignment(c.edge_a).project(c.point.x, c.point.y).s;
        std::vector<std::string> ids = ctx.way_ids(c.edge_a, s, s);
        if (c.shared_node) {
            ids.push_back("node:" + std::to_string(c.shared_node));
        }
        ctx.tag("Scenery/Track layout/Diamond crossing", c.edge_a, s, s, {{"crossing_angle", c.angle_deg}}, ids, "osm+derived");
    }
}

void tag_structures(TagContext& ctx) {
    for (std::size_t e = ctx.first(); e < ctx.last(); ++e) {
        for (const WayRange& r : ctx.ways(e)) {
            const bool tunnel = ingest::tag_or(r.way->tags, "tunnel", "no") != "no";
            const bool bridge = !tunnel && ingest::tag_or(r.way->tags, "bridge", "no") != "no";
            if ((!tunnel && !bridge) || r.s1 - r.s0 <= 1e-6) {
                continue;
            }
            const std::vector<std::string> ids{"way:" + std::to_string(r.way->id)};
            ctx.tag(tunnel ? "Scenery/Structures/Tunnel" : "Scenery/Structures/Bridge", e, r.s0, r.s1,
                    {{"length", r.s1 - r.s0}}, ids, "osm");
            if (tunnel) {
                ctx.tag("Connectivity/Positioning/GNSS", e, r.s0, r.s1,
                        {{"availability", std::string{"unavailable"}}, {"cause", std::string{"tunnel"}}}, ids, "derived");
            }
        }
    }
}

} // namespace

void tag_point_features(TagContext& ctx); // tag_point_features.cpp

void tag_features(TagContext& ctx) {
    tag_switches(ctx);
    tag_crossings(ctx);
    tag_structures(ctx);
    tag_point_features(ctx);
}

} // namespace railodd::odd
