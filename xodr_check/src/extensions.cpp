// Rail extensions and road-placed elements: switches name existing tracks at
// an s on them, platform segments lie on their roads, signals and objects sit
// within their road's length.
#include "checks.hpp"

#include <string>

namespace railodd::xodr_check {

namespace {

bool within(double s, double length, double tol) { return s >= -tol && s <= length + tol; }

void check_switch_track(Context& ctx, const Road& road, const Switch& sw, const SwitchTrack& t, const char* role) {
    if (!t.present) {
        ctx.error("road", road.id, nan, "switch_track", "switch " + sw.id + " has no <" + role + ">");
        return;
    }
    const Road* track = ctx.doc.road(t.id);
    if (!track) {
        ctx.error("road", road.id, nan, "switch_track",
                  "switch " + sw.id + ": " + role + " names road '" + t.id + "', which does not exist");
        return;
    }
    if (!within(t.s, track->length, ctx.limits.length_m)) {
        ctx.error("road", road.id, t.s, "switch_track",
                  "switch " + sw.id + ": " + role + " s=" + std::to_string(t.s) + " lies outside road " + track->id +
                      " [0, " + std::to_string(track->length) + "]");
    }
}

void check_points(Context& ctx, const Road& road) {
    for (const RoadPoint& p : road.points) {
        const std::string label = p.id.empty() ? p.kind : p.kind + " " + p.id;
        const std::string check = p.kind.rfind("signal", 0) == 0 ? "signal_s" : "object_s";
        if (!within(p.s, road.length, ctx.limits.length_m)) {
            ctx.error("road", road.id, p.s, check,
                      label + " at s=" + std::to_string(p.s) + " lies outside the road [0, " +
                          std::to_string(road.length) + "]");
        } else if (p.length > 0 && !within(p.s + p.length, road.length, ctx.limits.length_m)) {
            ctx.error("road", road.id, p.s, check,
                      label + " ends at s=" + std::to_string(p.s + p.length) +
                          ", beyond the road's length " + std::to_string(road.length));
        }
    }
}

void check_station(Context& ctx, const Station& st) {
    for (const Segment& seg : st.segments) {
        const Road* r = ctx.doc.road(seg.road_id);
        if (!r) {
            ctx.error("station", st.id, nan, "station_segment",
                      "platform segment names road '" + seg.road_id + "', which does not exist");
            continue;
        }
        const double tol = ctx.limits.length_m;
        if (seg.s_start < 0.0 || seg.s_start > seg.s_end || seg.s_end > r->length + tol) {
            ctx.error("station", st.id, seg.s_start, "station_segment",
                      "platform segment on road " + r->id + " [" + std::to_string(seg.s_start) + ", " +
                          std::to_string(seg.s_end) + "] is not within 0 <= sStart <= sEnd <= " +
                          std::to_string(r->length));
        }
    }
}

} // namespace

void check_rail_extensions(Context& ctx) {
    for (const Road& road : ctx.doc.roads) {
        for (const Switch& sw : road.switches) {
            ++ctx.result.summary.switches;
            check_switch_track(ctx, road, sw, sw.main, "mainTrack");
            check_switch_track(ctx, road, sw, sw.side, "sideTrack");
        }
        check_points(ctx, road);
    }
    for (const Station& st : ctx.doc.stations) {
        ++ctx.result.summary.stations;
        check_station(ctx, st);
    }
}

} // namespace railodd::xodr_check
