// Elevation continuity across links: where two roads meet (a road-to-road link
// or a junction connection's contact), their heights agree and so do their
// grades taken along the link. Start-start and end-end links meet head to
// head, so there one road's grade counts reversed. A road without an
// <elevationProfile> lies at height 0 with grade 0, as readers take it.
// Each pair of touching ends is compared once, even when both roads name it.
#include "checks.hpp"

#include <cmath>
#include <cstdio>
#include <set>
#include <string>
#include <utility>

namespace railodd::xodr_check {

namespace {

struct Height {
    double z = 0.0;
    double grade = 0.0; // dz/ds along the road's s
};

Height height_at(RoadEnd e) {
    const Road& r = *e.road;
    if (r.elevations.empty()) {
        return {};
    }
    const double s = e.at_end ? r.length : 0.0;
    // The last record starting at or before s (the first when none does).
    const Elevation* rec = &r.elevations.front();
    for (const Elevation& el : r.elevations) {
        if (el.s <= s) {
            rec = &el;
        }
    }
    const double t = s - rec->s;
    return {rec->at(s), rec->b + t * (2.0 * rec->c + 3.0 * t * rec->d)};
}

// The grade met when travelling out of road a through end `a` (and into the other road).
double grade_leaving(RoadEnd a, const Height& h) { return a.at_end ? h.grade : -h.grade; }

std::string value(const char* format, double v) {
    char buf[48];
    std::snprintf(buf, sizeof buf, format, v);
    return buf;
}

void compare_heights(Context& ctx, const std::string& object, const std::string& id, double s,
                     const std::string& prefix, RoadEnd a, RoadEnd b) {
    const Height ha = height_at(a);
    const Height hb = height_at(b);
    // Grades along the link, travelling from road a into road b.
    const double ga = grade_leaving(a, ha);
    const double gb = -grade_leaving(b, hb);
    const std::string ends = end_label(a) + " / " + end_label(b);
    const std::string at = place(object, id, s) + " at " + ends;
    auto& sum = ctx.result.summary;

    const double step = std::abs(ha.z - hb.z);
    sum.link_height_m.update(step, at);
    if (step > ctx.limits.link_height_m) {
        ctx.error(object, id, s, prefix + "_height",
                  "height step " + measured(step, ctx.limits.link_height_m, "m") + " at " + end_label(a) +
                      value(" (z=%.3f m)", ha.z) + " / " + end_label(b) + value(" (z=%.3f m)", hb.z));
    }
    const double kink = std::abs(ga - gb);
    sum.link_grade.update(kink, at);
    if (kink > ctx.limits.link_grade) {
        ctx.error(object, id, s, prefix + "_grade",
                  "grade change " + value("%.6g", kink) + value(" (limit %g)", ctx.limits.link_grade) + " at " + end_label(a) +
                      value(" (grade %+.5f)", ga) + " / " + end_label(b) + value(" (grade %+.5f)", gb) +
                      ", both taken along the link from road " + a.road->id + " into road " + b.road->id);
    }
}

using EndKey = std::pair<std::string, bool>; // road id, at_end

// True the first time this pair of ends is met.
bool first_time(std::set<std::pair<EndKey, EndKey>>& compared, RoadEnd a, RoadEnd b) {
    const EndKey ka{a.road->id, a.at_end};
    const EndKey kb{b.road->id, b.at_end};
    return compared.insert(ka < kb ? std::pair{ka, kb} : std::pair{kb, ka}).second;
}

void compare_connection(Context& ctx, const Junction& j, const Connection& con,
                        std::set<std::pair<EndKey, EndKey>>& compared) {
    const Road* incoming = ctx.doc.road(con.incoming);
    const Road* connecting = ctx.doc.road(con.connecting);
    if (!incoming || !connecting || j.type == "virtual" || (con.contact != "start" && con.contact != "end")) {
        return; // junctions.cpp reports these
    }
    const RoadEnd conn{connecting, con.contact == "end"};
    bool inc_at_end = false;
    if (!junction_end(*incoming, j, connecting->pose(conn.at_end), inc_at_end)) {
        return;
    }
    const RoadEnd inc{incoming, inc_at_end};
    if (first_time(compared, inc, conn)) {
        compare_heights(ctx, "junction", j.id, nan, "connection", inc, conn);
    }
}

} // namespace

void check_elevation_links(Context& ctx) {
    std::set<std::pair<EndKey, EndKey>> compared;
    for (const RoadLink& l : road_to_road_links(ctx.doc)) {
        if (first_time(compared, l.mine(), l.theirs())) {
            compare_heights(ctx, "road", l.road->id, l.at_end ? l.road->length : 0.0, "link", l.mine(), l.theirs());
        }
    }
    for (const Junction& j : ctx.doc.junctions) {
        for (const Connection& con : j.connections) {
            compare_connection(ctx, j, con, compared);
        }
    }
}

} // namespace railodd::xodr_check
