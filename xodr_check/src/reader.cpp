// OpenDRIVE XML to the checker's model. Values are taken as written; a number
// that does not parse is a finding, not a silent zero (pugixml's as_double
// would hide exactly the writer bugs this library is for).
#include "model.hpp"

#include "railodd/util/errors.hpp"

#include <pugixml.hpp>

#include <cmath>
#include <limits>
#include <cstdlib>
#include <cstring>
#include <string>

namespace railodd::xodr_check {

namespace {

class Reader {
public:
    explicit Reader(Document& doc) : doc_(doc) {}

    // Findings below are about this object.
    void at(const std::string& object, const std::string& id) {
        object_ = object;
        id_ = id;
    }

    double num(const pugi::xml_node& n, const char* name, double fallback, bool required = true) {
        const pugi::xml_attribute a = n.attribute(name);
        if (!a) {
            if (required) {
                bad(n, name, "is missing");
            }
            return fallback;
        }
        const char* text = a.value();
        char* end = nullptr;
        const double v = std::strtod(text, &end);
        while (end && (*end == ' ' || *end == '\t')) {
            ++end;
        }
        if (end == text || (end && *end != '\0') || !std::isfinite(v)) {
            bad(n, name, std::string{"is not a number: '"} + text + "'");
            return fallback;
        }
        return v;
    }

    int integer(const pugi::xml_node& n, const char* name, int fallback = 0, bool required = true) {
        const double v = num(n, name, fallback, required);
        // A value no int holds is reported, not converted: the conversion
        // would be undefined (found by fuzz_xodr_reader with id="-2e109").
        if (!(std::abs(v) <= static_cast<double>(std::numeric_limits<int>::max()))) {
            bad(n, name, "is out of range: '" + std::string{n.attribute(name).value()} + "'");
            return fallback;
        }
        if (v != std::floor(v)) {
            bad(n, name, "is not an integer");
        }
        return static_cast<int>(v);
    }

    void unknown(const std::string& what, double s) {
        doc_.findings.push_back({Severity::error, object_, id_, s, "geometry_kind", what});
    }

private:
    void bad(const pugi::xml_node& n, const char* name, const std::string& problem) {
        doc_.findings.push_back(
            {Severity::error, object_, id_, nan, "attribute", std::string{"<"} + n.name() + "> @" + name + " " + problem});
    }

    Document& doc_;
    std::string object_;
    std::string id_;
};

Link read_link(const pugi::xml_node& n) {
    Link l;
    if (!n) {
        return l;
    }
    l.present = true;
    l.element_type = n.attribute("elementType").value();
    l.element_id = n.attribute("elementId").value();
    l.contact = n.attribute("contactPoint").value();
    return l;
}

GeometryRecord read_geometry(Reader& r, const pugi::xml_node& g, bool& known) {
    GeometryRecord rec;
    rec.s = r.num(g, "s", 0.0);
    rec.x = r.num(g, "x", 0.0);
    rec.y = r.num(g, "y", 0.0);
    rec.hdg = r.num(g, "hdg", 0.0);
    rec.length = r.num(g, "length", 0.0);
    known = true;
    if (const auto n = g.child("line")) {
        rec.kind = GeometryKind::line;
    } else if (const auto n = g.child("arc")) {
        rec.kind = GeometryKind::arc;
        rec.curvature = r.num(n, "curvature", 0.0);
    } else if (const auto n = g.child("spiral")) {
        rec.kind = GeometryKind::spiral;
        rec.curv_start = r.num(n, "curvStart", 0.0);
        rec.curv_end = r.num(n, "curvEnd", 0.0);
    } else if (const auto n = g.child("poly3")) {
        rec.kind = GeometryKind::poly3;
        rec.a = r.num(n, "a", 0.0), rec.b = r.num(n, "b", 0.0);
        rec.c = r.num(n, "c", 0.0), rec.d = r.num(n, "d", 0.0);
    } else if (const auto n = g.child("paramPoly3")) {
        rec.kind = GeometryKind::param_poly3;
        rec.au = r.num(n, "aU", 0.0), rec.bu = r.num(n, "bU", 0.0);
        rec.cu = r.num(n, "cU", 0.0), rec.du = r.num(n, "dU", 0.0);
        rec.av = r.num(n, "aV", 0.0), rec.bv = r.num(n, "bV", 0.0);
        rec.cv = r.num(n, "cV", 0.0), rec.dv = r.num(n, "dV", 0.0);
        const std::string range = n.attribute("pRange").value();
        if (range != "" && range != "arcLength" && range != "normalized") {
            r.unknown("paramPoly3 @pRange '" + range + "' is neither arcLength nor normalized", rec.s);
        }
        rec.normalized = range == "normalized";
    } else {
        const auto child = g.first_child();
        r.unknown(std::string{"<geometry> holds no line/arc/spiral/poly3/paramPoly3 but <"} +
                      (child ? child.name() : "") + ">",
                  rec.s);
        known = false;
    }
    return rec;
}

// One a + b t + c t^2 + d t^3 record starting at its attribute `at`.
Elevation cubic(Reader& r, const pugi::xml_node& n, const char* at) {
    return {r.num(n, at, 0.0), r.num(n, "a", 0.0), r.num(n, "b", 0.0), r.num(n, "c", 0.0), r.num(n, "d", 0.0)};
}

void read_lanes(Reader& r, const pugi::xml_node& lanes, Road& road) {
    for (const auto o : lanes.children("laneOffset")) {
        road.lane_offsets.push_back(cubic(r, o, "s"));
    }
    for (const auto sec : lanes.children("laneSection")) {
        LaneSection ls;
        ls.s = r.num(sec, "s", 0.0);
        for (const char* side : {"left", "center", "right"}) {
            for (const auto lane : sec.child(side).children("lane")) {
                Lane l{r.integer(lane, "id"), lane.attribute("type").value(), {}};
                for (const auto w : lane.children("width")) {
                    l.widths.push_back(cubic(r, w, "sOffset"));
                }
                ls.lanes.push_back(std::move(l));
            }
        }
        road.sections.push_back(std::move(ls));
    }
    bool any = false;
    bool all_rail = true;
    for (const auto& ls : road.sections) {
        for (const auto& l : ls.lanes) {
            if (l.id == 0) {
                continue; // the centre lane carries no traffic
            }
            any = true;
            all_rail = all_rail && (l.type == "rail" || l.type == "tram");
        }
    }
    road.rail = any && all_rail;
}

// Signals and objects by their s; tunnels, bridges and object repeats also by
// their extent along s. An <object>'s own @length is its bounding box along
// its local u axis, not a distance along the road, so it is not used.
void read_points(Reader& r, const pugi::xml_node& road_node, Road& road) {
    const auto add = [&](const pugi::xml_node& n, const std::string& kind, const std::string& id, bool along_s) {
        road.points.push_back({kind, id, r.num(n, "s", 0.0), along_s ? r.num(n, "length", 0.0, false) : 0.0});
    };
    for (const auto n : road_node.child("signals").children()) {
        if (std::strcmp(n.name(), "signal") == 0 || std::strcmp(n.name(), "signalReference") == 0) {
            add(n, n.name(), n.attribute("id").value(), false);
        }
    }
    for (const auto n : road_node.child("objects").children()) {
        const std::string name = n.name();
        const std::string id = n.attribute("id").value();
        if (name == "object" || name == "objectReference") {
            add(n, name, id, false);
            for (const auto rep : n.children("repeat")) {
                add(rep, name + " " + id + " repeat", "", true);
            }
        } else if (name == "tunnel" || name == "bridge") {
            add(n, name, id, true);
        }
    }
}

void read_switches(Reader& r, const pugi::xml_node& railroad, Road& road) {
    for (const auto sw : railroad.children("switch")) {
        Switch s;
        s.id = sw.attribute("id").value();
        for (auto [name, track] : {std::pair{"mainTrack", &s.main}, std::pair{"sideTrack", &s.side}}) {
            if (const auto t = sw.child(name)) {
                *track = {true, t.attribute("id").value(), r.num(t, "s", 0.0)};
            }
        }
        road.switches.push_back(std::move(s));
    }
}

Road read_road(Reader& r, const pugi::xml_node& n) {
    Road road;
    road.id = n.attribute("id").value();
    r.at("road", road.id);
    road.junction = n.attribute("junction").as_string("-1");
    road.name = n.attribute("name").value();
    for (const auto u : n.children("userData")) {
        if (std::strcmp(u.attribute("code").value(), "osm") == 0) {
            road.osm_ids = u.attribute("value").value();
        }
    }
    road.length = r.num(n, "length", 0.0);
    road.predecessor = read_link(n.child("link").child("predecessor"));
    road.successor = read_link(n.child("link").child("successor"));
    for (const auto g : n.child("planView").children("geometry")) {
        bool known = false;
        GeometryRecord rec = read_geometry(r, g, known);
        if (known) {
            road.geometries.push_back(rec);
        }
    }
    for (const auto e : n.child("elevationProfile").children("elevation")) {
        road.elevations.push_back(cubic(r, e, "s"));
    }
    read_lanes(r, n.child("lanes"), road);
    read_points(r, n, road);
    read_switches(r, n.child("railroad"), road);
    return road;
}

Junction read_junction(Reader& r, const pugi::xml_node& n) {
    Junction j;
    j.id = n.attribute("id").value();
    r.at("junction", j.id);
    j.type = n.attribute("type").as_string("default");
    for (const auto c : n.children("connection")) {
        Connection con;
        con.id = c.attribute("id").value();
        con.incoming = c.attribute("incomingRoad").value();
        con.connecting = c.attribute(j.type == "direct" ? "linkedRoad" : "connectingRoad").value();
        con.contact = c.attribute("contactPoint").value();
        for (const auto ll : c.children("laneLink")) {
            con.lane_links.push_back({r.integer(ll, "from"), r.integer(ll, "to")});
        }
        j.connections.push_back(std::move(con));
    }
    for (const auto rs : n.children("roadSection")) {
        j.road_sections.push_back({rs.attribute("roadId").value(), r.num(rs, "sStart", nan, false),
                                   r.num(rs, "sEnd", nan, false)});
    }
    return j;
}

Station read_station(Reader& r, const pugi::xml_node& n) {
    Station st;
    st.id = n.attribute("id").value();
    r.at("station", st.id);
    for (const auto p : n.children("platform")) {
        for (const auto seg : p.children("segment")) {
            st.segments.push_back({seg.attribute("roadId").value(), r.num(seg, "sStart", 0.0), r.num(seg, "sEnd", 0.0)});
        }
    }
    return st;
}

void index_ids(Document& doc) {
    for (std::size_t i = 0; i < doc.roads.size(); ++i) {
        if (!doc.road_index.emplace(doc.roads[i].id, i).second) {
            doc.findings.push_back({Severity::error, "road", doc.roads[i].id, nan, "duplicate_id",
                                    "road id '" + doc.roads[i].id + "' is used by more than one road"});
        }
    }
    for (std::size_t i = 0; i < doc.junctions.size(); ++i) {
        if (!doc.junction_index.emplace(doc.junctions[i].id, i).second) {
            doc.findings.push_back({Severity::error, "junction", doc.junctions[i].id, nan, "duplicate_id",
                                    "junction id '" + doc.junctions[i].id + "' is used by more than one junction"});
        }
    }
}

} // namespace

Document read_document(const std::string& xml, const std::string& name) {
    pugi::xml_document xdoc;
    const pugi::xml_parse_result parsed = xdoc.load_buffer(xml.data(), xml.size());
    if (!parsed) {
        throw InputError(name, std::string{"not well-formed XML at byte "} + std::to_string(parsed.offset) + ": " +
                                   parsed.description());
    }
    const pugi::xml_node root = xdoc.child("OpenDRIVE");
    if (!root) {
        throw InputError(name, "not an OpenDRIVE document (no <OpenDRIVE> root element)");
    }
    Document doc;
    doc.file = name;
    Reader r(doc);
    r.at("file", name);
    const pugi::xml_node header = root.child("header");
    if (!header) {
        doc.findings.push_back({Severity::error, "file", name, nan, "header", "<header> is missing"});
    }
    doc.rev_major = r.integer(header, "revMajor", 1, bool(header));
    doc.rev_minor = r.integer(header, "revMinor", 0, bool(header));
    doc.geo_reference = header.child("geoReference").child_value();
    for (const auto n : root.children("road")) {
        doc.roads.push_back(read_road(r, n));
    }
    for (const auto n : root.children("junction")) {
        doc.junctions.push_back(read_junction(r, n));
    }
    for (const auto n : root.children("station")) {
        doc.stations.push_back(read_station(r, n));
    }
    index_ids(doc);
    return doc;
}

} // namespace railodd::xodr_check
