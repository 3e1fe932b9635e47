#include "railodd/geometry/road_fit.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace railodd::geometry {

namespace {

struct Corner {
    double deflection = 0.0; // signed turn at the vertex, left positive
    double radius = 0.0;     // 0: no fillet
    double tangent = 0.0;    // distance from the vertex to each end of the fillet
};

std::vector<Point> distinct(const std::vector<Point>& in) {
    std::vector<Point> out;
    for (const auto& p : in) {
        if (out.empty() || std::hypot(p.x - out.back().x, p.y - out.back().y) > 1e-6) {
            out.push_back(p);
        }
    }
    return out;
}

double seg_length(const Point& a, const Point& b) { return std::hypot(b.x - a.x, b.y - a.y); }
double seg_heading(const Point& a, const Point& b) { return std::atan2(b.y - a.y, b.x - a.x); }

// The widest fillet that keeps within max_deviation of the vertex and leaves
// each adjacent segment at most half used.
Corner corner_at(const std::vector<Point>& p, std::size_t i, const RoadFitOptions& o) {
    Corner c;
    c.deflection = std::remainder(seg_heading(p[i], p[i + 1]) - seg_heading(p[i - 1], p[i]), 2 * std::numbers::pi);
    const double half = 0.5 * std::abs(c.deflection);
    if (half < 1e-9) {
        return {c.deflection, 0.0, 0.0}; // straight on
    }
    const double room = 0.5 * std::min(seg_length(p[i - 1], p[i]), seg_length(p[i], p[i + 1]));
    const double by_room = room / std::tan(half);
    const double by_deviation = o.max_deviation_m / (1.0 / std::cos(half) - 1.0);
    c.radius = std::min({o.max_radius_m, by_room, by_deviation});
    c.tangent = c.radius * std::tan(half);
    return c;
}

} // namespace

Alignment fillet_polyline(const std::vector<Point>& points, const RoadFitOptions& o) {
    const std::vector<Point> p = distinct(points);
    Alignment a;
    if (p.size() < 2) {
        a.start = {p.empty() ? 0.0 : p[0].x, p.empty() ? 0.0 : p[0].y, 0.0, 0.0};
        a.primitives.push_back(make_line(0.0));
        return a;
    }
    std::vector<Corner> corners(p.size());
    for (std::size_t i = 1; i + 1 < p.size(); ++i) {
        corners[i] = corner_at(p, i, o);
    }
    a.start = {p[0].x, p[0].y, seg_heading(p[0], p[1]), 0.0};
    for (std::size_t i = 0; i + 1 < p.size(); ++i) {
        const double line = seg_length(p[i], p[i + 1]) - corners[i].tangent - corners[i + 1].tangent;
        a.primitives.push_back(make_line(std::max(0.0, line)));
        const Corner& c = corners[i + 1];
        if (i + 2 < p.size() && c.radius > 0.0) {
            a.primitives.push_back(make_arc(c.radius * std::abs(c.deflection), std::copysign(1.0 / c.radius, c.deflection)));
        }
    }
    return a;
}

FittedNetwork fit_road_graph(const TrackGraph& roads, const RoadFitOptions& o) {
    FittedNetwork net;
    for (const auto& e : roads.edges) {
        std::vector<Point> pts;
        for (const auto& n : e.nodes) {
            pts.push_back({n.xy.x, n.xy.y});
        }
        FittedEdge f;
        f.edge = e.id;
        f.chain = net.chains.size();
        f.alignment = fillet_polyline(pts, o);
        f.quality = measure_fit(f.alignment, pts);
        net.edges.push_back(std::move(f));
        Chain c;
        c.items.push_back({e.id, false});
        c.start.vertex = e.from;
        c.end.vertex = e.to;
        net.chains.push_back(std::move(c));
    }
    return net;
}

} // namespace railodd::geometry
