// Per-road checks of the plan view (record continuity, s chaining, total
// length) and of the elevation profile.
#include "checks.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>

namespace railodd::xodr_check {

std::string measured(double value, double limit, const char* unit) {
    char buf[96];
    std::snprintf(buf, sizeof buf, "%.6g %s (limit %g %s)", value, unit, limit, unit);
    return buf;
}

std::string place(const std::string& object, const std::string& id, double s) {
    std::string p = object + " " + id;
    if (!std::isnan(s)) {
        char buf[48];
        std::snprintf(buf, sizeof buf, " s=%.3f", s);
        p += buf;
    }
    return p;
}

namespace {

std::string record_name(const Road& road, std::size_t i) {
    return "record " + std::to_string(i) + " (" + kind_name(road.geometries[i].kind) + ")";
}

// The joint between records i-1 and i: where one ends the next must begin,
// with the same heading and, on rail roads, the same curvature.
void check_joint(Context& ctx, const Road& road, std::size_t i) {
    const GeometryRecord& prev = road.geometries[i - 1];
    const GeometryRecord& next = road.geometries[i];
    const Pose a = evaluate(prev, prev.length);
    const Pose b = evaluate(next, 0.0);
    const std::string between = " between " + record_name(road, i - 1) + " and " + record_name(road, i);
    const std::string at = place("road", road.id, next.s);
    auto& sum = ctx.result.summary;

    const double gap = std::hypot(a.x - b.x, a.y - b.y);
    sum.gap_m.update(gap, at);
    if (gap > ctx.limits.gap_m) {
        ctx.error("road", road.id, next.s, "geometry_gap", "position gap " + measured(gap, ctx.limits.gap_m, "m") + between);
    }
    const double turn = std::abs(angle_diff(a.hdg, b.hdg));
    sum.heading_jump_rad.update(turn, at);
    if (turn > ctx.limits.heading_rad) {
        ctx.error("road", road.id, next.s, "geometry_heading",
                  "heading jump " + measured(turn, ctx.limits.heading_rad, "rad") + between);
    }
    if (road.rail) {
        const double jump = std::abs(a.curvature - b.curvature);
        sum.rail_curvature_jump.update(jump, at);
        if (jump > ctx.limits.rail_curvature_per_m) {
            ctx.error("road", road.id, next.s, "geometry_curvature",
                      "curvature jump on a rail road " + measured(jump, ctx.limits.rail_curvature_per_m, "1/m") +
                          between);
        }
    }
    const double expected_s = prev.s + prev.length;
    const double s_tol = ctx.limits.s_chain_relative * std::max(1.0, std::abs(next.s));
    if (std::abs(expected_s - next.s) > s_tol) {
        ctx.error("road", road.id, next.s, "geometry_s_chain",
                  "s + length of " + record_name(road, i - 1) + " is " + std::to_string(expected_s) +
                      " but the next record starts at s=" + std::to_string(next.s));
    }
}

void check_records(Context& ctx, const Road& road) {
    for (std::size_t i = 0; i < road.geometries.size(); ++i) {
        const GeometryRecord& g = road.geometries[i];
        Summary& sum = ctx.result.summary;
        ++sum.geometries_by_kind[kind_name(g.kind)];
        sum.short_records += g.length < 0.01 ? 1 : 0;
        if (g.length < sum.shortest_record_m) {
            sum.shortest_record_m = g.length;
            sum.shortest_record_at = "road " + road.id + " s=" + std::to_string(g.s);
        }
        if (!(g.length > 0.0)) {
            ctx.error("road", road.id, g.s, "geometry_length", record_name(road, i) + " has length " +
                                                                   std::to_string(g.length) + " (must be > 0)");
        }
        if (g.kind == GeometryKind::param_poly3 && g.length > 0.0) {
            // Consumers map s to p linearly; a curve much longer or shorter than
            // @length stretches every s position along it.
            const double curve = curve_length(g);
            const double tol = ctx.limits.length_m + 1e-6 * g.length;
            if (std::abs(curve - g.length) > tol) {
                ctx.warning("road", road.id, g.s, "parampoly3_length",
                            record_name(road, i) + " curve length differs from @length by " +
                                measured(std::abs(curve - g.length), tol, "m"));
            }
        }
        if (i > 0) {
            check_joint(ctx, road, i);
        }
    }
}

void check_plan_view(Context& ctx, const Road& road) {
    if (road.geometries.empty()) {
        ctx.error("road", road.id, nan, "planview_empty", "the plan view has no evaluable <geometry> record");
        return;
    }
    const double s0 = road.geometries.front().s;
    if (std::abs(s0) > ctx.limits.s_chain_relative) {
        ctx.error("road", road.id, s0, "geometry_s_chain",
                  "the first record starts at s=" + std::to_string(s0) + ", not at 0");
    }
    check_records(ctx, road);
    double total = 0.0;
    for (const auto& g : road.geometries) {
        total += g.length;
    }
    const double diff = std::abs(total - road.length);
    if (diff > ctx.limits.length_m) {
        ctx.error("road", road.id, nan, "road_length",
                  "record lengths add up to " + std::to_string(total) + " m but @length is " +
                      std::to_string(road.length) + " m: difference " + measured(diff, ctx.limits.length_m, "m"));
    }
}

} // namespace

void check_plan_views(Context& ctx) {
    for (const Road& road : ctx.doc.roads) {
        check_plan_view(ctx, road);
    }
}

void check_elevations(Context& ctx) {
    for (const Road& road : ctx.doc.roads) {
        const auto& el = road.elevations;
        for (std::size_t i = 0; i < el.size(); ++i) {
            if (el[i].s < -ctx.limits.length_m || el[i].s > road.length + ctx.limits.length_m) {
                ctx.error("road", road.id, el[i].s, "elevation_s",
                          "elevation record " + std::to_string(i) + " starts outside [0, " +
                              std::to_string(road.length) + "]");
            }
            if (i == 0) {
                continue;
            }
            if (el[i].s < el[i - 1].s) {
                ctx.error("road", road.id, el[i].s, "elevation_s", "elevation records are not in increasing s");
                continue;
            }
            const double gap = std::abs(el[i - 1].at(el[i].s) - el[i].a);
            ctx.result.summary.elevation_gap_m.update(gap, place("road", road.id, el[i].s));
            if (gap > ctx.limits.elevation_gap_m) {
                ctx.error("road", road.id, el[i].s, "elevation_gap",
                          "elevation jumps by " + measured(gap, ctx.limits.elevation_gap_m, "m") +
                              " between records " + std::to_string(i - 1) + " and " + std::to_string(i));
            }
        }
    }
}

} // namespace railodd::xodr_check
