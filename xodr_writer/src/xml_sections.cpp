// Objects, signals, the railroad element, junctions and stations.
#include "xml_support.hpp"

namespace railodd::xodr::xml {

namespace {

void write_object(pugi::xml_node parent, const Object& o) {
    pugi::xml_node n = parent.append_child("object");
    attr(n, "id", o.id);
    attr(n, "name", o.name);
    attr(n, "type", o.type);
    if (!o.subtype.empty()) {
        attr(n, "subtype", o.subtype);
    }
    attr(n, "s", o.s);
    attr(n, "t", o.t);
    attr(n, "zOffset", o.z_offset);
    attr(n, "hdg", o.hdg);
    attr(n, "orientation", o.orientation);
    if (o.length > 0.0) {
        attr(n, "length", o.length);
    }
    if (o.width > 0.0) {
        attr(n, "width", o.width);
    }
    if (o.height > 0.0) {
        attr(n, "height", o.height);
    }
    user_data(n, o.user_data);
}

void write_structure(pugi::xml_node parent, const Structure& st) {
    pugi::xml_node n = parent.append_child(st.kind == Structure::Kind::tunnel ? "tunnel" : "bridge");
    attr(n, "s", st.s);
    attr(n, "length", st.length);
    attr(n, "id", st.id);
    attr(n, "name", st.name);
    attr(n, "type", st.type);
    user_data(n, st.user_data);
}

} // namespace

void write_objects(pugi::xml_node road, const Road& r, Revision) {
    if (r.objects.empty() && r.structures.empty()) {
        return;
    }
    pugi::xml_node objects = road.append_child("objects");
    for (const auto& o : r.objects) {
        write_object(objects, o);
    }
    // The schema wants every tunnel before the first bridge.
    for (const auto kind : {Structure::Kind::tunnel, Structure::Kind::bridge}) {
        for (const auto& st : r.structures) {
            if (st.kind == kind) {
                write_structure(objects, st);
            }
        }
    }
}

void write_signals(pugi::xml_node road, const Road& r, Revision) {
    if (r.signals.empty()) {
        return;
    }
    pugi::xml_node signals = road.append_child("signals");
    for (const auto& sg : r.signals) {
        pugi::xml_node n = signals.append_child("signal");
        attr(n, "s", sg.s);
        attr(n, "t", sg.t);
        attr(n, "id", sg.id);
        attr(n, "name", sg.name);
        attr(n, "dynamic", sg.dynamic ? "yes" : "no");
        attr(n, "orientation", sg.orientation);
        attr(n, "zOffset", sg.z_offset);
        if (!sg.country.empty()) {
            attr(n, "country", sg.country);
        }
        attr(n, "type", sg.type);
        attr(n, "subtype", sg.subtype);
        if (sg.value) {
            attr(n, "value", *sg.value);
            attr(n, "unit", sg.unit);
        }
        if (sg.height > 0.0) {
            attr(n, "height", sg.height);
        }
        if (sg.width > 0.0) {
            attr(n, "width", sg.width);
        }
        user_data(n, sg.user_data);
    }
}

void write_railroad(pugi::xml_node road, const Road& r) {
    if (r.switches.empty()) {
        return;
    }
    pugi::xml_node rr = road.append_child("railroad");
    for (const auto& sw : r.switches) {
        pugi::xml_node n = rr.append_child("switch");
        attr(n, "name", sw.name);
        attr(n, "id", sw.id);
        attr(n, "position", sw.position);
        for (const auto& [name, t] : {std::pair{"mainTrack", &sw.main_track}, std::pair{"sideTrack", &sw.side_track}}) {
            pugi::xml_node tn = n.append_child(name);
            attr(tn, "id", t->road_id);
            attr(tn, "s", t->s);
            attr(tn, "dir", t->dir);
        }
        user_data(n, sw.user_data);
    }
}

void write_junction(pugi::xml_node root, const Junction& j, Revision revision) {
    pugi::xml_node n = root.append_child("junction");
    attr(n, "name", j.name);
    attr(n, "id", j.id);
    if (j.type != "default" || revision == Revision::v1_8) {
        attr(n, "type", j.type);
    }
    for (const auto& c : j.connections) {
        pugi::xml_node cn = n.append_child("connection");
        attr(cn, "id", c.id);
        attr(cn, "incomingRoad", c.incoming_road);
        attr(cn, "connectingRoad", c.connecting_road);
        attr(cn, "contactPoint", c.contact == Contact::start ? "start" : "end");
        for (const auto& l : c.lane_links) {
            pugi::xml_node ln = cn.append_child("laneLink");
            attr(ln, "from", std::to_string(l.from));
            attr(ln, "to", std::to_string(l.to));
        }
    }
    for (std::size_t i = 0; i < j.road_sections.size(); ++i) {
        const auto& rs = j.road_sections[i];
        pugi::xml_node sn = n.append_child("roadSection");
        attr(sn, "id", std::to_string(i));
        attr(sn, "roadId", rs.road_id);
        attr(sn, "sStart", rs.s_start);
        attr(sn, "sEnd", rs.s_end);
    }
    for (const auto& p : j.priorities) {
        pugi::xml_node pn = n.append_child("priority");
        attr(pn, "high", p.high);
        attr(pn, "low", p.low);
    }
    user_data(n, j.user_data);
}

void write_station(pugi::xml_node root, const Station& s) {
    pugi::xml_node n = root.append_child("station");
    attr(n, "name", s.name);
    attr(n, "id", s.id);
    attr(n, "type", s.type);
    for (const auto& p : s.platforms) {
        pugi::xml_node pn = n.append_child("platform");
        attr(pn, "name", p.name);
        attr(pn, "id", p.id);
        for (const auto& seg : p.segments) {
            pugi::xml_node sn = pn.append_child("segment");
            attr(sn, "roadId", seg.road_id);
            attr(sn, "sStart", seg.s_start);
            attr(sn, "sEnd", seg.s_end);
            attr(sn, "side", seg.side);
        }
    }
    user_data(n, s.user_data);
}

} // namespace railodd::xodr::xml
