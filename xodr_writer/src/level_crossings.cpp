// Level crossings (road and track at grade). The track carries a
// level-crossing signal at the crossing point; the road carries one per
// driving direction ahead of the track and, where OSM maps barriers, a
// barrier object on each approach. With OpenDRIVE 1.8 a junction of type
// "crossing" also names both roads' s-ranges, the track having priority; for
// 1.6/1.7 the road and the track simply overlap there.
#include "feature_context.hpp"

#include "railodd/geometry/indexed_alignment.hpp"

#include <cmath>
#include <limits>

namespace railodd::xodr {

namespace {

constexpr double approach_m = 5.0; // road signals / barriers this far before the track axis
constexpr double on_road_m = 1.0;  // the crossing point lies on a road's reference line within this

struct RoadHit {
    const BuiltRoad* road = nullptr;
    double s = 0.0;
};

RoadHit find_road(const std::vector<BuiltRoad>& roads, std::int64_t way_id, const ingest::XY& p) {
    RoadHit best;
    double best_d = std::numeric_limits<double>::infinity();
    for (const auto& br : roads) {
        if (std::find(br.way_ids.begin(), br.way_ids.end(), way_id) == br.way_ids.end()) {
            continue;
        }
        const auto pr = geometry::project_point(br.alignment, p.x, p.y);
        // Past a cut-back end the projection clamps to the end: not on this road.
        if (pr.distance < best_d && pr.distance < on_road_m) {
            best_d = pr.distance;
            best = {&br, pr.s};
        }
    }
    return best;
}

const Road& road_by_id(const Map& map, const std::string& id) {
    for (const auto& r : map.roads) {
        if (r.id == id) {
            return r;
        }
    }
    throw std::logic_error("road " + id + " not in the map");
}

double right_width(const Road& r) {
    double w = 0.0;
    for (const auto& l : r.lane_sections.front().right) {
        w += l.width;
    }
    return w + r.lane_offset;
}

double left_width(const Road& r) {
    double w = 0.0;
    for (const auto& l : r.lane_sections.front().left) {
        w += l.width;
    }
    return w - r.lane_offset;
}

std::string tags_of(const ingest::IngestResult& in, std::int64_t node, const char* key) {
    for (const auto& f : in.features) {
        if (f.id == node && f.osm_type == "node") {
            return ingest::tag_or(f.tags, key);
        }
    }
    return {};
}

void add_road_side(FeatureContext& ctx, Road& road, double s, const geometry::RoadRailCrossing& c,
                   const std::vector<UserData>& trace) {
    const double len = road.length();
    const std::string barrier = c.level_crossing_node ? tags_of(ctx.in.ingest, c.level_crossing_node, "crossing:barrier") : "";
    const bool lights = c.level_crossing_node && tags_of(ctx.in.ingest, c.level_crossing_node, "crossing:light") == "yes";
    const double rw = right_width(road) + 0.5, lw = left_width(road) + 0.5;
    for (const bool forward : {true, false}) {
        const double at = std::clamp(forward ? s - approach_m : s + approach_m, 0.0, len);
        Signal sg;
        sg.id = ctx.ids.signal();
        sg.name = "level crossing";
        sg.s = at;
        sg.t = forward ? -rw : lw; // on the driver's right
        sg.orientation = forward ? "+" : "-";
        sg.dynamic = lights;
        sg.type = "level_crossing";
        sg.subtype = lights ? "lights" : "-1";
        sg.height = 2.0;
        sg.user_data = trace;
        road.signals.push_back(std::move(sg));
        if (!barrier.empty() && barrier != "no") {
            Object o;
            o.id = ctx.ids.object();
            o.name = "level crossing barrier";
            o.type = "barrier";
            o.subtype = barrier;
            o.s = at;
            o.t = forward ? -rw / 2.0 : lw / 2.0;
            o.hdg = M_PI / 2.0;
            o.length = forward ? rw : lw;
            o.width = 0.1;
            o.height = 1.0;
            o.user_data = trace;
            road.objects.push_back(std::move(o));
        }
    }
}

// The lane section holding s.
const LaneSection& section_at(const Road& r, double s) {
    const LaneSection* at = &r.lane_sections.front();
    for (const auto& ls : r.lane_sections) {
        if (ls.s <= s + 1e-9) {
            at = &ls;
        }
    }
    return *at;
}

// The innermost lane of a type on one side (0: none).
int innermost(const std::vector<Lane>& side, const char* type) {
    for (const auto& l : side) {
        if (l.type == type) {
            return l.id;
        }
    }
    return 0;
}

} // namespace

std::optional<CrossingRoad> crossing_road(const MapBuild& build, std::int64_t way_id, const ingest::XY& point) {
    const RoadHit hit = find_road(build.roads, way_id, point);
    if (!hit.road) {
        return std::nullopt;
    }
    const Road& road = road_by_id(build.map, hit.road->road_id);
    const LaneSection& ls = section_at(road, hit.s);
    // Right-hand traffic drives the right (negative) lanes in +s, left-hand
    // traffic the left ones.
    const bool lht = road.rule == "LHT";
    const auto& fwd = lht ? ls.left : ls.right;
    const auto& bwd = lht ? ls.right : ls.left;
    CrossingRoad c;
    c.road_id = road.id;
    c.s = hit.s;
    c.length = road.length();
    c.forward_lane = innermost(fwd, "driving");
    c.backward_lane = innermost(bwd, "driving");
    c.forward_walk = innermost(fwd, "sidewalk");
    c.backward_walk = innermost(bwd, "sidewalk");
    return c;
}

void add_level_crossings(FeatureContext& ctx) {
    for (const auto& c : ctx.in.geometry.crossings.road_rail) {
        if (c.grade_separated) {
            continue;
        }
        const geometry::IndexedAlignment ia(ctx.in.geometry.fitted_tracks.edges[c.edge].alignment, 2.0);
        const auto loc = ctx.on_track(c.edge, ia.project(c.point.x, c.point.y).s);
        if (!loc) {
            continue; // the track was not written: listed in tracks_not_written
        }
        const RoadHit hit = find_road(ctx.build.roads, c.road_way_id, c.point);
        std::vector<UserData> trace{{"osm", "way:" + std::to_string(c.road_way_id) +
                                                (c.level_crossing_node ? ",node:" + std::to_string(c.level_crossing_node) : "")}};
        Road& track = ctx.build.map.roads[loc->road];
        Signal sg;
        sg.id = ctx.ids.signal();
        sg.name = "level crossing";
        sg.s = loc->s;
        sg.orientation = "none";
        sg.type = "level_crossing";
        sg.user_data = trace;
        track.signals.push_back(std::move(sg));
        ++ctx.build.level_crossings;
        if (!hit.road) {
            // The crossing lies where the road was cut back for a junction of
            // roads: its connecting roads fan out there, none is "the" road.
            ctx.build.level_crossings_without_road.push_back(
                {c.road_way_id, c.level_crossing_node, "inside a road junction: road-side signals not placed"});
            continue;
        }
        Road& road = ctx.build.map.roads.at(static_cast<std::size_t>(
            &road_by_id(ctx.build.map, hit.road->road_id) - ctx.build.map.roads.data()));
        add_road_side(ctx, road, hit.s, c, trace);
        if (ctx.revision == Revision::v1_8) {
            const double half_road = (right_width(road) + left_width(road)) / 2.0 + 1.0;
            const double half_track = 2.5;
            Junction j;
            j.id = ctx.ids.junction();
            j.name = "level crossing";
            j.type = "crossing";
            j.road_sections.push_back({track.id, std::max(0.0, loc->s - half_road), std::min(track.length(), loc->s + half_road)});
            j.road_sections.push_back({road.id, std::max(0.0, hit.s - half_track), std::min(road.length(), hit.s + half_track)});
            j.priorities.push_back({track.id, road.id});
            j.user_data = trace;
            ctx.build.map.junctions.push_back(std::move(j));
        }
    }
}

} // namespace railodd::xodr
