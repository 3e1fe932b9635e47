// Stations and halts with their platforms. A platform belongs to the nearest
// station or halt within station_reach_m; one near none makes its own
// (small) station, named after it. A station with no mapped platform gets a
// platform of zero length where it was attached, marked as such, so that
// every mapped station appears (the schema needs at least one platform).
#include "feature_context.hpp"

#include <cmath>
#include <limits>
#include <map>

namespace railodd::xodr {

namespace {

constexpr double station_reach_m = 600.0;

std::string name_of(const ingest::Feature& f, const std::string& fallback) {
    return ingest::tag_or(f.tags, "name", ingest::tag_or(f.tags, "ref", fallback + " " + std::to_string(f.id)));
}

// The platform's stretch on the track, split over the roads it was written as.
std::vector<PlatformSegment> segments_of(const FeatureContext& ctx, const geometry::AttachedFeature& a) {
    std::vector<PlatformSegment> out;
    const std::string side = a.offset > 0.0 ? "left" : "right";
    for (const RoadPiece& p : ctx.build.rail.pieces[a.edge]) {
        const double s0 = std::max(a.s_start, p.s0), s1 = std::min(a.s_end, p.s1);
        if (s1 > s0 || (a.s_start == a.s_end && p.s0 <= a.s_start && a.s_start <= p.s1 && out.empty())) {
            out.push_back({ctx.build.map.roads[p.road].id, s0 - p.s0, std::max(s0, s1) - p.s0, side});
        }
    }
    return out;
}

void add_platform_object(FeatureContext& ctx, const geometry::AttachedFeature& a, const ingest::Feature& f) {
    for (const RoadPiece& p : ctx.build.rail.pieces[a.edge]) {
        const double s0 = std::max(a.s_start, p.s0), s1 = std::min(a.s_end, p.s1);
        if (s1 <= s0) {
            continue;
        }
        Object o;
        o.id = ctx.ids.object();
        o.name = name_of(f, "platform");
        o.type = "none";
        o.subtype = "platform";
        o.s = (s0 + s1) / 2.0 - p.s0;
        o.t = a.offset;
        o.length = s1 - s0;
        o.width = 3.0;  // OSM outlines rarely give it: a typical platform's
        o.height = 0.76; // EU standard platform height (TSI PRM: 550 or 760 mm)
        o.user_data.push_back({"osm", f.osm_type + ":" + std::to_string(f.id)});
        ctx.build.map.roads[p.road].objects.push_back(std::move(o));
    }
}

} // namespace

void add_stations(FeatureContext& ctx) {
    const auto& features = ctx.in.ingest.features;
    std::vector<const geometry::AttachedFeature*> stations, platforms;
    for (const auto& a : ctx.in.geometry.attachment.attached) {
        const std::string& kind = features[a.feature].kind;
        if (ctx.build.rail.pieces[a.edge].empty()) {
            if (kind == "station" || kind == "halt" || kind == "platform") {
                ctx.build.features_not_written.emplace_back(a.feature, "its track was not written (zero length)");
            }
            continue;
        }
        if (kind == "station" || kind == "halt") {
            stations.push_back(&a);
        } else if (kind == "platform") {
            platforms.push_back(&a);
        }
    }
    std::map<const geometry::AttachedFeature*, std::vector<const geometry::AttachedFeature*>> members;
    std::vector<const geometry::AttachedFeature*> orphans;
    for (const auto* p : platforms) {
        const auto& pp = features[p->feature].position.xy;
        const geometry::AttachedFeature* best = nullptr;
        double best_d = station_reach_m;
        for (const auto* s : stations) {
            const auto& sp = features[s->feature].position.xy;
            const double d = std::hypot(pp.x - sp.x, pp.y - sp.y);
            if (d < best_d) {
                best_d = d;
                best = s;
            }
        }
        if (best) {
            members[best].push_back(p);
        } else {
            orphans.push_back(p);
        }
    }
    auto emit = [&](const geometry::AttachedFeature* head, const std::vector<const geometry::AttachedFeature*>& plats) {
        const ingest::Feature& f = features[head->feature];
        Station st;
        st.id = ctx.ids.station();
        st.name = name_of(f, f.kind);
        st.type = f.kind == "halt" || f.kind == "platform" ? "small" : (plats.size() >= 6 ? "large" : "medium");
        st.user_data.push_back({"osm", f.osm_type + ":" + std::to_string(f.id)});
        for (const auto* p : plats) {
            Platform pl;
            pl.id = ctx.ids.other();
            pl.name = name_of(features[p->feature], "platform");
            pl.segments = segments_of(ctx, *p);
            add_platform_object(ctx, *p, features[p->feature]);
            st.platforms.push_back(std::move(pl));
            ++ctx.build.platforms;
        }
        if (st.platforms.empty()) {
            Platform pl;
            pl.id = ctx.ids.other();
            pl.name = "no platform mapped";
            geometry::AttachedFeature at = *head;
            at.s_start = at.s_end = at.s;
            pl.segments = segments_of(ctx, at);
            st.platforms.push_back(std::move(pl));
            st.user_data.push_back({"platform", "not mapped: zero-length segment at the station's place on the track"});
        }
        ctx.build.map.stations.push_back(std::move(st));
        ++ctx.build.stations;
    };
    for (const auto* s : stations) {
        emit(s, members[s]);
    }
    for (const auto* p : orphans) {
        emit(p, {p});
    }
}

} // namespace railodd::xodr
