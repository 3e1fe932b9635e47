// contactPoint consistency. A link's contactPoint names the end of the other
// road that touches this road's end, and the other road's link at that end,
// when it has one, names this road and this end back (or the junction this road
// belongs to). A junction connection's contactPoint names the connecting road's
// end at the incoming road, and the connecting road's own link at that end
// names the incoming road: readers that follow lane ids and links (CARLA)
// match connections on it. The distances themselves are the links check's
// (`link_gap`, `connection_gap`); here a contactPoint is wrong when the end it
// names is off and the road's other end lies nearer.
#include "checks.hpp"

#include <cmath>
#include <cstdio>
#include <string>

namespace railodd::xodr_check {

namespace {

double distance(const Pose& a, const Pose& b) { return std::hypot(a.x - b.x, a.y - b.y); }

const char* link_name(bool at_end) { return at_end ? "successor" : "predecessor"; }

std::string metres(double v) {
    char buf[32];
    std::snprintf(buf, sizeof buf, "%.3f m", v);
    return buf;
}

// "names road 7 end", "names junction 3", "is missing"
std::string describe(const Link& l) {
    if (!l.present) {
        return "is missing";
    }
    std::string d = "names " + l.element_type + " " + l.element_id;
    return l.contact.empty() ? d : d + " " + l.contact;
}

// Whether `road` takes part in junction `id`: one of its connecting roads, or
// named by one of its connections (1.8 direct junctions link both roads to it).
bool in_junction(const Document& doc, const Road& road, const std::string& id) {
    if (road.junction == id) {
        return true;
    }
    const auto it = doc.junction_index.find(id);
    if (it == doc.junction_index.end()) {
        return true; // a missing junction is link_target's finding
    }
    for (const Connection& c : doc.junctions[it->second].connections) {
        if (c.connecting == road.id || c.incoming == road.id) {
            return true;
        }
    }
    return false;
}

// The end `named` of the other road is off `here` while its other end lies nearer.
bool names_wrong_end(const Context& ctx, const Pose& here, RoadEnd named, double& off, double& other) {
    if (!named.road->has_geometry) {
        return false;
    }
    off = distance(here, named.road->pose(named.at_end));
    other = distance(here, named.road->pose(!named.at_end));
    return off > ctx.limits.gap_m && other < off;
}

void check_touching_end(Context& ctx, const RoadLink& l, double s) {
    double off = 0.0, other = 0.0;
    if (!l.road->has_geometry || !names_wrong_end(ctx, l.road->pose(l.at_end), l.theirs(), off, other)) {
        return;
    }
    ctx.error("road", l.road->id, s, "contact_point",
              std::string{link_name(l.at_end)} + " to road " + l.other->id + " has contactPoint '" +
                  end_name(l.other_at_end) + "', but that end lies " + metres(off) + " from " + end_label(l.mine()) +
                  " and its " + end_name(!l.other_at_end) + " " + metres(other) + " (limit " +
                  metres(ctx.limits.gap_m) + ")");
}

void check_link_back(Context& ctx, const RoadLink& l, double s) {
    const Link& back = link_at(*l.other, l.other_at_end);
    if (!back.present) {
        return;
    }
    if (back.element_type == "road" && back.element_id == l.road->id && back.contact == end_name(l.at_end)) {
        return;
    }
    if (back.element_type == "junction" && in_junction(ctx.doc, *l.road, back.element_id)) {
        return;
    }
    if (back.element_type != "road" && back.element_type != "junction") {
        return; // the other road's link_target finding
    }
    const std::string expected = back.element_type == "road" ? end_label(l.mine())
                                                             : "a junction road " + l.road->id + " belongs to";
    ctx.error("road", l.road->id, s, "link_reverse",
              std::string{link_name(l.at_end)} + " names " + end_label(l.theirs()) + ", but road " + l.other->id +
                  "'s " + link_name(l.other_at_end) + " " + describe(back) + ", not " + expected);
}

void check_connection(Context& ctx, const Junction& j, const Connection& con) {
    const Road* incoming = ctx.doc.road(con.incoming);
    const Road* connecting = ctx.doc.road(con.connecting);
    if (!incoming || !connecting || j.type == "virtual" || (con.contact != "start" && con.contact != "end")) {
        return; // junctions.cpp reports these
    }
    const RoadEnd conn{connecting, con.contact == "end"};
    bool inc_at_end = false;
    if (!junction_end(*incoming, j, connecting->pose(conn.at_end), inc_at_end)) {
        return; // connection_incoming_link
    }
    const RoadEnd inc{incoming, inc_at_end};
    double off = 0.0, other = 0.0;
    if (incoming->has_geometry && names_wrong_end(ctx, incoming->pose(inc_at_end), conn, off, other)) {
        ctx.error("junction", j.id, nan, "contact_point",
                  "connection " + con.id + ": contactPoint '" + con.contact + "' names " + end_label(conn) +
                      ", which lies " + metres(off) + " from " + end_label(inc) + ", but its " +
                      end_name(!conn.at_end) + " lies " + metres(other) + " from it");
    }
    if (j.type == "direct") {
        return; // the linked road links to the junction, not to the incoming road
    }
    const Link& own = link_at(*connecting, conn.at_end);
    if (own.present && own.element_type == "road" && own.element_id == incoming->id &&
        own.contact == end_name(inc_at_end)) {
        return;
    }
    ctx.error("junction", j.id, nan, "connection_link",
              "connection " + con.id + ": connecting road " + connecting->id + "'s " + link_name(conn.at_end) +
                  " (at its contactPoint " + con.contact + ") " + describe(own) + ", not " + end_label(inc) +
                  ": readers that match connections on the connecting road's links (CARLA) cannot follow it");
}

} // namespace

void check_contact_points(Context& ctx) {
    for (const RoadLink& l : road_to_road_links(ctx.doc)) {
        const double s = l.at_end ? l.road->length : 0.0;
        check_touching_end(ctx, l, s);
        check_link_back(ctx, l, s);
    }
    for (const Junction& j : ctx.doc.junctions) {
        for (const Connection& con : j.connections) {
            check_connection(ctx, j, con);
        }
    }
}

} // namespace railodd::xodr_check
