// Road-to-road and road-to-junction links: the target exists, and two linked
// roads meet at the contact point with continuous heading (and curvature on
// rail roads). Each physical link is compared once even when both roads name it.
#include "checks.hpp"

#include <cmath>
#include <numbers>
#include <set>
#include <string>
#include <utility>
#include <vector>

namespace railodd::xodr_check {

void compare_contact(Context& ctx, const std::string& object, const std::string& id, double s,
                     const std::string& prefix, RoadEnd a, RoadEnd b) {
    if (!a.road->has_geometry || !b.road->has_geometry) {
        return; // already reported as planview_empty
    }
    const Pose& pa = a.road->pose(a.at_end);
    const Pose& pb = b.road->pose(b.at_end);
    // One road's end meeting the other's start continues in the same direction;
    // start-start and end-end meet head to head, with the second road reversed.
    const bool same_direction = a.at_end != b.at_end;
    const std::string what = " at road " + a.road->id + " " + end_name(a.at_end) + " / road " + b.road->id + " " +
                             end_name(b.at_end);
    const std::string at = place(object, id, s) + what;
    auto& sum = ctx.result.summary;
    ++sum.links_checked;

    const double gap = std::hypot(pa.x - pb.x, pa.y - pb.y);
    sum.gap_m.update(gap, at);
    if (gap > ctx.limits.gap_m) {
        ctx.error(object, id, s, prefix + "_gap", "position gap " + measured(gap, ctx.limits.gap_m, "m") + what);
    }
    const double other_hdg = same_direction ? pb.hdg : pb.hdg + std::numbers::pi;
    const double turn = std::abs(angle_diff(pa.hdg, other_hdg));
    sum.heading_jump_rad.update(turn, at);
    if (turn > ctx.limits.heading_rad) {
        ctx.error(object, id, s, prefix + "_heading",
                  std::string{"heading mismatch ("} + (same_direction ? "same" : "opposite") + " direction) " +
                      measured(turn, ctx.limits.heading_rad, "rad") + what);
    }
    if (a.road->rail && b.road->rail) {
        const double other_k = same_direction ? pb.curvature : -pb.curvature;
        const double jump = std::abs(pa.curvature - other_k);
        sum.rail_curvature_jump.update(jump, at);
        if (jump > ctx.limits.rail_curvature_per_m) {
            ctx.error(object, id, s, prefix + "_curvature",
                      "curvature jump between rail roads " + measured(jump, ctx.limits.rail_curvature_per_m, "1/m") +
                          what);
        }
    }
}

namespace {

using EndKey = std::pair<std::string, bool>; // road id, at_end

void check_link(Context& ctx, const Road& road, const Link& link, bool at_end,
                std::set<std::pair<EndKey, EndKey>>& compared) {
    const double s = at_end ? road.length : 0.0;
    const std::string which = at_end ? "successor" : "predecessor";
    if (link.element_type == "junction") {
        if (!ctx.doc.junction_index.count(link.element_id)) {
            ctx.error("road", road.id, s, "link_target",
                      which + " names junction '" + link.element_id + "', which does not exist");
        }
        return;
    }
    if (link.element_type != "road") {
        ctx.error("road", road.id, s, "link_target",
                  which + " has elementType '" + link.element_type + "' (expected road or junction)");
        return;
    }
    const Road* other = ctx.doc.road(link.element_id);
    if (!other) {
        ctx.error("road", road.id, s, "link_target", which + " names road '" + link.element_id + "', which does not exist");
        return;
    }
    if (link.contact != "start" && link.contact != "end") {
        ctx.error("road", road.id, s, "link_contact",
                  which + " to road " + other->id + " has contactPoint '" + link.contact + "' (expected start or end)");
        return;
    }
    const EndKey mine{road.id, at_end};
    const EndKey theirs{other->id, link.contact == "end"};
    const auto key = mine < theirs ? std::pair{mine, theirs} : std::pair{theirs, mine};
    if (!compared.insert(key).second) {
        return; // the other road's link named the same two ends
    }
    compare_contact(ctx, "road", road.id, s, "link", RoadEnd{&road, at_end}, RoadEnd{other, theirs.second});
}

} // namespace

std::vector<RoadLink> road_to_road_links(const Document& doc) {
    std::vector<RoadLink> out;
    for (const Road& road : doc.roads) {
        for (const bool at_end : {false, true}) {
            const Link& l = link_at(road, at_end);
            const Road* other = l.present && l.element_type == "road" ? doc.road(l.element_id) : nullptr;
            if (other && (l.contact == "start" || l.contact == "end")) {
                out.push_back({&road, at_end, &l, other, l.contact == "end"});
            }
        }
    }
    return out;
}

void check_road_links(Context& ctx) {
    std::set<std::pair<EndKey, EndKey>> compared;
    for (const Road& road : ctx.doc.roads) {
        if (road.predecessor.present) {
            check_link(ctx, road, road.predecessor, false, compared);
        }
        if (road.successor.present) {
            check_link(ctx, road, road.successor, true, compared);
        }
    }
}

} // namespace railodd::xodr_check
