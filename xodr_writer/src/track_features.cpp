// Railway signals and buffer stops on the track roads. The signal's category
// (main, distant, shunting, speed_limit, ...) and system come from OSM's
// railway:signal:<category>=<system> tags; see docs/xodr.md "Signals".
#include "feature_context.hpp"

#include <array>

namespace railodd::xodr {

namespace {

// Most significant first: a combined signal also carries main/distant tags.
constexpr std::array<const char*, 12> categories{
    "combined", "main", "distant", "shunting", "speed_limit", "speed_limit_distant",
    "crossing", "crossing_distant", "minor", "stop", "whistle", "ring"};

// Whether the alignment runs the same way as the OSM way at the feature's node.
bool way_runs_along(const geometry::GraphEdge& e, bool alignment_reversed, std::int64_t node_id) {
    for (std::size_t i = 0; i < e.nodes.size(); ++i) {
        if (e.nodes[i].id != node_id) {
            continue;
        }
        for (const auto& span : e.ways) {
            if (span.first <= i && i <= span.last) {
                return span.reversed == alignment_reversed;
            }
        }
    }
    return true;
}

std::string country_of(const std::string& system) {
    // "DE-ESO:hp" -> "DE"; systems without a country prefix give none.
    if (system.size() >= 3 && system[2] == '-' && std::isupper(static_cast<unsigned char>(system[0])) &&
        std::isupper(static_cast<unsigned char>(system[1]))) {
        return system.substr(0, 2);
    }
    return {};
}

Signal make_signal(const ingest::Feature& f, bool along) {
    Signal sg;
    sg.name = ingest::tag_or(f.tags, "ref", ingest::tag_or(f.tags, "railway:signal:main:ref"));
    sg.type = "-1";
    for (const char* c : categories) {
        const std::string key = std::string("railway:signal:") + c;
        const std::string system = ingest::tag_or(f.tags, key);
        if (system.empty() || system == "no") {
            continue;
        }
        sg.type = c;
        sg.subtype = system;
        sg.country = country_of(system);
        const std::string form = ingest::tag_or(f.tags, key + ":form");
        sg.dynamic = form == "light" || form == "semaphore";
        const std::string speed = ingest::tag_or(f.tags, key + ":speed");
        char* end = nullptr;
        const double v = std::strtod(speed.c_str(), &end);
        if (end != speed.c_str() && v > 0.0) {
            sg.value = v;
            sg.unit = "km/h";
        }
        break;
    }
    const std::string dir = ingest::tag_or(f.tags, "railway:signal:direction", "forward");
    sg.orientation = dir == "both" ? "none" : ((dir == "forward") == along ? "+" : "-");
    const std::string side = ingest::tag_or(f.tags, "railway:signal:position");
    // Mapped on the track node: the side tag places it; 2.5 m clears the structure gauge.
    const bool left = side == "left" ? along : (side == "right" ? !along : false);
    sg.t = side == "left" || side == "right" ? (left ? 2.5 : -2.5) : 0.0;
    sg.height = 0.0;
    sg.user_data.push_back({"osm", f.osm_type + ":" + std::to_string(f.id)});
    return sg;
}

} // namespace

void add_track_features(FeatureContext& ctx) {
    const auto& features = ctx.in.ingest.features;
    for (const auto& a : ctx.in.geometry.attachment.attached) {
        const ingest::Feature& f = features[a.feature];
        if (f.kind != "signal" && f.kind != "buffer_stop") {
            continue;
        }
        const auto loc = ctx.on_track(a.edge, a.s);
        if (!loc) {
            ctx.build.features_not_written.emplace_back(a.feature, "its track was not written (zero length)");
            continue;
        }
        Road& road = ctx.build.map.roads[loc->road];
        if (f.kind == "signal") {
            const bool along = way_runs_along(ctx.in.geometry.tracks.edges[a.edge], ctx.in.geometry.fitted_tracks.edges[a.edge].reversed, f.id);
            Signal sg = make_signal(f, along);
            sg.id = ctx.ids.signal();
            sg.s = loc->s;
            if (!f.on_track) {
                sg.t = a.offset;
            }
            road.signals.push_back(std::move(sg));
            ++ctx.build.signals;
        } else {
            Object o;
            o.id = ctx.ids.object();
            o.name = "buffer stop";
            o.type = "barrier";
            o.subtype = "buffer_stop";
            o.s = loc->s;
            o.length = 1.0;
            o.width = 3.0;
            o.height = 1.2;
            o.user_data.push_back({"osm", f.osm_type + ":" + std::to_string(f.id)});
            road.objects.push_back(std::move(o));
        }
    }
}

} // namespace railodd::xodr
