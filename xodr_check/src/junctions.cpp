// Junction connections: the named roads exist, the connecting road belongs to
// the junction, the incoming road links to the junction, the two touch at the
// contact point, and lane links name lanes that exist at the touching ends.
#include "checks.hpp"

#include <cmath>
#include <string>

namespace railodd::xodr_check {

namespace {

bool links_to(const Link& l, const std::string& junction_id) {
    return l.present && l.element_type == "junction" && l.element_id == junction_id;
}

} // namespace

bool junction_end(const Road& incoming, const Junction& j, const Pose& contact, bool& at_end) {
    const bool start = links_to(incoming.predecessor, j.id);
    const bool end = links_to(incoming.successor, j.id);
    if (start && end && incoming.has_geometry) {
        const auto dist = [&](const Pose& p) { return std::hypot(p.x - contact.x, p.y - contact.y); };
        at_end = dist(incoming.end) < dist(incoming.start);
        return true;
    }
    at_end = end;
    return start || end;
}

namespace {

void check_lane_links(Context& ctx, const Junction& j, const Connection& con, RoadEnd incoming, RoadEnd connecting) {
    const LaneSection* from = incoming.road->section(incoming.at_end);
    const LaneSection* to = connecting.road->section(connecting.at_end);
    for (const LaneLink& ll : con.lane_links) {
        if (!from || !from->has_lane(ll.from)) {
            ctx.error("junction", j.id, nan, "lane_link",
                      "connection " + con.id + ": laneLink from=" + std::to_string(ll.from) +
                          " is not a lane of incoming road " + incoming.road->id + " at its " +
                          (incoming.at_end ? "end" : "start"));
        }
        if (!to || !to->has_lane(ll.to)) {
            ctx.error("junction", j.id, nan, "lane_link",
                      "connection " + con.id + ": laneLink to=" + std::to_string(ll.to) + " is not a lane of road " +
                          connecting.road->id + " at its " + con.contact);
        }
    }
}

const Road* named_road(Context& ctx, const Junction& j, const Connection& con, const std::string& id,
                       const char* role) {
    const Road* r = ctx.doc.road(id);
    if (!r) {
        ctx.error("junction", j.id, nan, "connection_road",
                  "connection " + con.id + ": " + role + " '" + id + "' does not exist");
    }
    return r;
}

void check_connection(Context& ctx, const Junction& j, const Connection& con) {
    const Road* incoming = named_road(ctx, j, con, con.incoming, "incomingRoad");
    const char* role = j.type == "direct" ? "linkedRoad" : "connectingRoad";
    const Road* connecting = named_road(ctx, j, con, con.connecting, role);
    if (!incoming || !connecting || j.type == "virtual") {
        return; // virtual junctions join roads mid-way: nothing to touch-test
    }
    if (j.type != "direct" && connecting->junction != j.id) {
        ctx.error("junction", j.id, nan, "connection_junction",
                  "connection " + con.id + ": connecting road " + connecting->id + " has junction=\"" +
                      connecting->junction + "\", not \"" + j.id + "\"");
    }
    if (con.contact != "start" && con.contact != "end") {
        ctx.error("junction", j.id, nan, "connection_contact",
                  "connection " + con.id + ": contactPoint '" + con.contact + "' (expected start or end)");
        return;
    }
    const RoadEnd conn_end{connecting, con.contact == "end"};
    bool at_end = false;
    if (!junction_end(*incoming, j, connecting->pose(conn_end.at_end), at_end)) {
        ctx.error("junction", j.id, nan, "connection_incoming_link",
                  "connection " + con.id + ": incoming road " + incoming->id +
                      " links to junction " + j.id + " at neither end");
        return;
    }
    const RoadEnd inc_end{incoming, at_end};
    compare_contact(ctx, "junction", j.id, nan, "connection", conn_end, inc_end);
    check_lane_links(ctx, j, con, inc_end, conn_end);
}

// 1.8 crossing junctions list the crossing roads' sections instead of connections.
void check_road_sections(Context& ctx, const Junction& j) {
    for (const RoadSection& rs : j.road_sections) {
        const Road* r = ctx.doc.road(rs.road_id);
        if (!r) {
            ctx.error("junction", j.id, nan, "crossing_road", "roadSection names road '" + rs.road_id + "', which does not exist");
            continue;
        }
        for (const double s : {rs.s_start, rs.s_end}) {
            if (!std::isnan(s) && (s < -ctx.limits.length_m || s > r->length + ctx.limits.length_m)) {
                ctx.error("junction", j.id, s, "crossing_road",
                          "roadSection s=" + std::to_string(s) + " lies outside road " + r->id + " [0, " +
                              std::to_string(r->length) + "]");
            }
        }
    }
}

} // namespace

void check_junctions(Context& ctx) {
    for (const Junction& j : ctx.doc.junctions) {
        ++ctx.result.summary.junctions;
        ctx.result.summary.connections += j.connections.size();
        for (const Connection& con : j.connections) {
            check_connection(ctx, j, con);
        }
        check_road_sections(ctx, j);
    }
}

} // namespace railodd::xodr_check
