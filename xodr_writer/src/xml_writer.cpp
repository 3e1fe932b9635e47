#include "railodd/xodr/xml_writer.hpp"

#include "xml_support.hpp"

#include <sstream>

namespace railodd::xodr {

namespace {

using xml::attr;
using xml::user_data;

const char* contact(Contact c) {
    return c == Contact::start ? "start" : "end";
}

void cubic(pugi::xml_node n, double s, double a, double b, double c, double d, const char* s_name = "s") {
    attr(n, s_name, s);
    attr(n, "a", a);
    attr(n, "b", b);
    attr(n, "c", c);
    attr(n, "d", d);
}

void write_link(pugi::xml_node road, const Road& r) {
    if (r.predecessor.type == ElementType::none && r.successor.type == ElementType::none) {
        return;
    }
    pugi::xml_node link = road.append_child("link");
    for (const auto& [name, l] : {std::pair{"predecessor", &r.predecessor}, std::pair{"successor", &r.successor}}) {
        if (l->type == ElementType::none) {
            continue;
        }
        pugi::xml_node n = link.append_child(name);
        attr(n, "elementType", l->type == ElementType::road ? "road" : "junction");
        attr(n, "elementId", l->id);
        if (l->type == ElementType::road) {
            attr(n, "contactPoint", contact(l->contact));
        }
    }
}

void write_plan_view(pugi::xml_node road, const Road& r) {
    pugi::xml_node pv = road.append_child("planView");
    for (const auto& g : r.plan_view) {
        pugi::xml_node n = pv.append_child("geometry");
        attr(n, "s", g.s);
        attr(n, "x", g.x);
        attr(n, "y", g.y);
        attr(n, "hdg", g.hdg);
        attr(n, "length", g.length);
        switch (g.kind) {
        case PlanGeometry::Kind::line:
            n.append_child("line");
            break;
        case PlanGeometry::Kind::arc:
            attr(n.append_child("arc"), "curvature", g.curv_start);
            break;
        case PlanGeometry::Kind::spiral: {
            pugi::xml_node sp = n.append_child("spiral");
            attr(sp, "curvStart", g.curv_start);
            attr(sp, "curvEnd", g.curv_end);
            break;
        }
        case PlanGeometry::Kind::param_poly3: {
            pugi::xml_node pp = n.append_child("paramPoly3");
            const char* names[] = {"aU", "bU", "cU", "dU", "aV", "bV", "cV", "dV"};
            for (int i = 0; i < 4; ++i) {
                attr(pp, names[i], g.u[i]);
            }
            for (int i = 0; i < 4; ++i) {
                attr(pp, names[4 + i], g.v[i]);
            }
            attr(pp, "pRange", "arcLength");
            break;
        }
        }
    }
}

void write_profiles(pugi::xml_node road, const Road& r) {
    if (!r.elevation.empty()) {
        pugi::xml_node ep = road.append_child("elevationProfile");
        for (const auto& e : r.elevation) {
            cubic(ep.append_child("elevation"), e.s, e.a, e.b, e.c, e.d);
        }
    }
    if (!r.superelevation.empty()) {
        pugi::xml_node lp = road.append_child("lateralProfile");
        for (const auto& e : r.superelevation) {
            cubic(lp.append_child("superelevation"), e.s, e.a, e.b, e.c, e.d);
        }
    }
}

void write_lane(pugi::xml_node parent, const Lane& l) {
    pugi::xml_node n = parent.append_child("lane");
    attr(n, "id", std::to_string(l.id));
    attr(n, "type", l.type);
    attr(n, "level", "false");
    if (l.link.predecessor || l.link.successor) {
        pugi::xml_node link = n.append_child("link");
        if (l.link.predecessor) {
            attr(link.append_child("predecessor"), "id", std::to_string(*l.link.predecessor));
        }
        if (l.link.successor) {
            attr(link.append_child("successor"), "id", std::to_string(*l.link.successor));
        }
    }
    cubic(n.append_child("width"), 0.0, l.width, 0.0, 0.0, 0.0, "sOffset");
    if (!l.road_mark.empty()) {
        pugi::xml_node m = n.append_child("roadMark");
        attr(m, "sOffset", 0.0);
        attr(m, "type", l.road_mark);
        attr(m, "color", "standard");
    }
}

void write_lanes(pugi::xml_node road, const Road& r) {
    pugi::xml_node lanes = road.append_child("lanes");
    cubic(lanes.append_child("laneOffset"), 0.0, r.lane_offset, 0.0, 0.0, 0.0);
    for (const auto& ls : r.lane_sections) {
        pugi::xml_node sec = lanes.append_child("laneSection");
        attr(sec, "s", ls.s);
        if (!ls.left.empty()) {
            pugi::xml_node left = sec.append_child("left");
            for (auto it = ls.left.rbegin(); it != ls.left.rend(); ++it) {
                write_lane(left, *it); // outermost first, as in the standard's examples
            }
        }
        pugi::xml_node centre = sec.append_child("center").append_child("lane");
        attr(centre, "id", "0");
        attr(centre, "type", "none");
        attr(centre, "level", "false");
        if (!ls.right.empty()) {
            pugi::xml_node right = sec.append_child("right");
            for (const auto& l : ls.right) {
                write_lane(right, l);
            }
        }
    }
}

} // namespace

namespace {

void write_road(pugi::xml_node root, const Road& r, Revision revision, const ExtraUserData& extra) {
    pugi::xml_node road = root.append_child("road");
    attr(road, "name", r.name);
    attr(road, "length", r.length());
    attr(road, "id", r.id);
    attr(road, "junction", r.junction);
    if (!r.rule.empty()) {
        attr(road, "rule", r.rule);
    }
    write_link(road, r);
    if (!r.type.empty()) {
        pugi::xml_node t = road.append_child("type");
        attr(t, "s", 0.0);
        attr(t, "type", r.type);
    }
    write_plan_view(road, r);
    write_profiles(road, r);
    write_lanes(road, r);
    xml::write_objects(road, r, revision);
    xml::write_signals(road, r, revision);
    xml::write_railroad(road, r);
    user_data(road, r.user_data);
    if (extra) {
        user_data(road, extra(r));
    }
}

void write_header(pugi::xml_node root, const Header& h, Revision revision) {
    pugi::xml_node n = root.append_child("header");
    attr(n, "revMajor", "1");
    attr(n, "revMinor", std::to_string(static_cast<int>(revision)));
    attr(n, "name", h.name);
    attr(n, "version", "1.0");
    if (!h.date.empty()) {
        attr(n, "date", h.date);
    }
    attr(n, "north", h.north);
    attr(n, "south", h.south);
    attr(n, "east", h.east);
    attr(n, "west", h.west);
    attr(n, "vendor", h.vendor);
    n.append_child("geoReference").append_child(pugi::node_cdata).set_value(h.geo_reference.c_str());
}

} // namespace

namespace {

// One child of <OpenDRIVE>, built in a small document of its own and printed
// at depth 1: the whole map never exists as one DOM (on a national network
// that would take gigabytes), and the bytes are those the full DOM prints.
template <class Build>
void write_element(std::ostream& out, Build build) {
    pugi::xml_document doc;
    pugi::xml_node root = doc.append_child("OpenDRIVE");
    build(root);
    for (pugi::xml_node n : root.children()) {
        n.print(out, "  ", pugi::format_default, pugi::encoding_utf8, 1);
    }
}

} // namespace

void write_xodr(const Map& map, Revision revision, std::ostream& out, const ExtraUserData& extra) {
    out << "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n<OpenDRIVE>\n";
    write_element(out, [&](pugi::xml_node root) { write_header(root, map.header, revision); });
    for (const auto& r : map.roads) {
        write_element(out, [&](pugi::xml_node root) { write_road(root, r, revision, extra); });
    }
    for (const auto& j : map.junctions) {
        write_element(out, [&](pugi::xml_node root) { xml::write_junction(root, j, revision); });
    }
    for (const auto& s : map.stations) {
        write_element(out, [&](pugi::xml_node root) { xml::write_station(root, s); });
    }
    out << "</OpenDRIVE>\n";
}

std::string write_xodr(const Map& map, Revision revision) {
    std::ostringstream out;
    write_xodr(map, revision, out);
    return std::move(out).str();
}

} // namespace railodd::xodr
