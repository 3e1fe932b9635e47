// Road centrelines: the corner construction (corner_fit.hpp) on each road
// edge, free at both ends.
#include "railodd/geometry/road_fit.hpp"

#include "railodd/geometry/corner_fit.hpp"

namespace railodd::geometry {

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
        f.alignment = corner_polyline(pts, std::nullopt, std::nullopt, {o.max_radius_m, o.max_deviation_m});
        f.quality = measure_fit(f.alignment, pts);
        net.edges.push_back(std::move(f));
        Chain c;
        c.items.push_back({e.id, false});
        c.start.vertex = e.from;
        c.end.vertex = e.to;
        net.chains.push_back(std::move(c));
        net.corner_chains.push_back(net.chains.size() - 1);
    }
    return net;
}

} // namespace railodd::geometry
