// Per-segment facts of the track graph shared by the crossing searches.
#include "crossing_context.hpp"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <stdexcept>
#include <string>
#include <tuple>

namespace railodd::geometry::detail {

namespace {

bool is_structure(const ingest::Tags& tags, const std::string& key) {
    const auto it = tags.find(key);
    return it != tags.end() && it->second != "no";
}

// OSM layer values are small integers; anything unreadable counts as ground.
int layer_of(const ingest::Tags& tags) {
    const std::string v = ingest::tag_or(tags, "layer", "0");
    char* end = nullptr;
    const long layer = std::strtol(v.c_str(), &end, 10);
    return end == v.c_str() || std::abs(layer) > 100 ? 0 : static_cast<int>(layer);
}

bool is_level_crossing(const ingest::Feature& f) {
    return f.osm_type == "node" && (f.kind == "level_crossing" || f.kind == "crossing");
}

} // namespace

Level level_of(const ingest::Tags& tags) {
    const Structure structure = is_structure(tags, "bridge")   ? Structure::bridge
                                : is_structure(tags, "tunnel") ? Structure::tunnel
                                                               : Structure::none;
    return {structure, layer_of(tags)};
}

Level common_level(const Level& a, const Level& b) {
    return {a.structure == b.structure ? a.structure : Structure::none, a.layer == b.layer ? a.layer : std::nullopt};
}

bool grade_separated(const Level& a, const Level& b) {
    return a.structure != b.structure || (a.layer && b.layer && *a.layer != *b.layer);
}

CrossingContext::CrossingContext(const TrackGraph& graph, const std::vector<ingest::Way>& track_ways,
                                 const std::vector<ingest::Feature>& features)
    : graph_(graph) {
    for (const auto& e : graph.edges) {
        auto& s = node_s_.emplace_back(e.nodes.size(), 0.0);
        for (std::size_t k = 0; k < e.nodes.size(); ++k) {
            if (k > 0) {
                s[k] = s[k - 1] + std::hypot(e.nodes[k].xy.x - e.nodes[k - 1].xy.x, e.nodes[k].xy.y - e.nodes[k - 1].xy.y);
                segments_.push_back({e.nodes[k - 1].xy, e.nodes[k].xy, e.nodes[k - 1].id, e.nodes[k].id});
                segment_refs_.push_back({e.id, k - 1});
            }
            edge_nodes_.push_back({e.nodes[k].id, e.id, k});
        }
    }
    std::sort(edge_nodes_.begin(), edge_nodes_.end(), [](const EdgeNode& x, const EdgeNode& y) {
        return std::tie(x.node, x.edge, x.index) < std::tie(y.node, y.edge, y.index);
    });
    index_ways(track_ways);
    for (const auto& f : features) {
        if (is_level_crossing(f)) {
            markers_.push_back({f.position.xy.x, f.position.xy.y, f.id});
        }
    }
    std::sort(markers_.begin(), markers_.end(),
              [](const Marker& a, const Marker& b) { return std::tie(a.x, a.id) < std::tie(b.x, b.id); });
}

void CrossingContext::index_ways(const std::vector<ingest::Way>& track_ways) {
    std::vector<std::pair<std::int64_t, Level>> levels;
    for (const auto& w : track_ways) {
        levels.emplace_back(w.id, level_of(w.tags));
    }
    std::sort(levels.begin(), levels.end(), [](const auto& a, const auto& b) { return a.first < b.first; });
    for (const auto& e : graph_.edges) {
        auto& per_segment = segment_level_.emplace_back(e.nodes.size() - 1);
        for (const auto& span : e.ways) {
            const auto it = std::lower_bound(levels.begin(), levels.end(), span.way_id,
                                             [](const auto& l, std::int64_t id) { return l.first < id; });
            if (it == levels.end() || it->first != span.way_id) {
                throw std::invalid_argument("find_crossings: edge " + std::to_string(e.id) + " names way " +
                                            std::to_string(span.way_id) + ", which is not among the track ways");
            }
            std::fill(per_segment.begin() + static_cast<std::ptrdiff_t>(span.first),
                      per_segment.begin() + static_cast<std::ptrdiff_t>(span.last), it->second);
        }
    }
}

Level CrossingContext::track_level(std::size_t edge, std::size_t segment) const {
    return segment_level_[edge][segment];
}

double CrossingContext::s_at(std::size_t edge, std::size_t segment, ingest::XY p) const {
    const ingest::XY a = graph_.edges[edge].nodes[segment].xy;
    return node_s_[edge][segment] + std::hypot(p.x - a.x, p.y - a.y);
}

Branch CrossingContext::branch(std::size_t edge, std::size_t index, int step) const {
    const auto& nodes = graph_.edges[edge].nodes;
    const auto& other = nodes[step < 0 ? index - 1 : index + 1];
    return {edge, other.id, unit(nodes[index].xy, other.xy)};
}

std::int64_t CrossingContext::level_crossing_near(std::int64_t node, ingest::XY p) const {
    const auto lo = std::lower_bound(markers_.begin(), markers_.end(), p.x - level_crossing_link_m,
                                     [](const Marker& m, double x) { return m.x < x; });
    std::int64_t best = 0;
    double best_d = level_crossing_link_m;
    for (auto it = lo; it != markers_.end() && it->x <= p.x + level_crossing_link_m; ++it) {
        if (it->id == node) {
            return node;
        }
        const double d = std::hypot(it->x - p.x, it->y - p.y);
        if (d < best_d || (d == best_d && best != 0 && it->id < best)) {
            best_d = d;
            best = it->id;
        }
    }
    return best;
}

} // namespace railodd::geometry::detail
