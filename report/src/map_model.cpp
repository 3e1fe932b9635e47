// The map as convert holds it (xodr::Map, before it is printed) turned into
// the drawable lines the report reads from a map.xodr: convert's page is made
// without parsing the file it has just written (a DOM of a national map is
// about three times the file).
#include "parts.hpp"

#include "railodd/xodr/model.hpp"

namespace railodd::report::detail {

namespace {

xodr_check::GeometryRecord record_of(const xodr::PlanGeometry& g) {
    xodr_check::GeometryRecord r;
    r.s = g.s;
    r.x = g.x;
    r.y = g.y;
    r.hdg = g.hdg;
    r.length = g.length;
    switch (g.kind) {
    case xodr::PlanGeometry::Kind::line: r.kind = xodr_check::GeometryKind::line; break;
    case xodr::PlanGeometry::Kind::arc:
        r.kind = xodr_check::GeometryKind::arc;
        r.curvature = g.curv_start;
        break;
    case xodr::PlanGeometry::Kind::spiral:
        r.kind = xodr_check::GeometryKind::spiral;
        r.curv_start = g.curv_start;
        r.curv_end = g.curv_end;
        break;
    case xodr::PlanGeometry::Kind::param_poly3:
        r.kind = xodr_check::GeometryKind::param_poly3;
        r.au = g.u[0], r.bu = g.u[1], r.cu = g.u[2], r.du = g.u[3];
        r.av = g.v[0], r.bv = g.v[1], r.cv = g.v[2], r.dv = g.v[3];
        r.normalized = false; // pRange="arcLength"
        break;
    }
    return r;
}

} // namespace

xodr_check::MapLines map_lines_of(const xodr::Map& map, const std::string& name) {
    xodr_check::MapLines lines;
    lines.file = name;
    lines.geo_reference = map.header.geo_reference;
    lines.roads.reserve(map.roads.size());
    for (const auto& road : map.roads) {
        xodr_check::MapRoad m;
        m.id = road.id;
        m.name = road.name;
        m.junction = road.junction;
        m.length = road.length();
        m.rail = road.rail;
        for (const auto& u : road.user_data) {
            if (u.code == "osm") {
                m.osm_ids = u.value;
            }
        }
        for (const auto& g : road.plan_view) {
            m.geometries.push_back(record_of(g));
        }
        for (const auto& e : road.elevation) {
            m.elevations.push_back({e.s, e.a, e.b, e.c, e.d});
        }
        lines.roads.push_back(std::move(m));
    }
    return lines;
}

} // namespace railodd::report::detail
