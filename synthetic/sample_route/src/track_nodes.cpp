#include "track_nodes.hpp"

#include "node_layout.hpp"

#include "railodd/geometry/indexed_alignment.hpp"

#include <algorithm>
#include <optional>
#include <stdexcept>
#include <string>

namespace railodd::sample {

namespace {

struct DrawnNode {
    double s;
    std::int64_t id;
};

std::int64_t node_at(const std::vector<DrawnNode>& nodes, double s) {
    for (const auto& n : nodes) {
        if (n.s == s) {
            return n.id;
        }
    }
    throw std::logic_error("sample OSM: no main-line node at s " + std::to_string(s));
}

std::vector<DrawnNode> draw_main_nodes(const RouteDesign& d, OsmBuilder& b, Rng& rng) {
    const geometry::IndexedAlignment main(d.main.alignment);
    std::vector<double> fixed{0.0, main.length()};
    for (const auto& w : d.main_ways) {
        fixed.push_back(w.s_from);
    }
    for (const auto& p : d.main_points) {
        fixed.push_back(p.s);
    }
    // Switches also end ways, so some chainages are listed twice on purpose.
    std::sort(fixed.begin(), fixed.end());
    fixed.erase(std::unique(fixed.begin(), fixed.end()), fixed.end());

    std::vector<DrawnNode> nodes;
    for (const double s : mapper_chainages(d.main.alignment, fixed, rng)) {
        Tags tags;
        for (const auto& p : d.main_points) {
            if (p.s == s) {
                tags = p.tags;
            }
        }
        const geometry::Pose pose = main.evaluate(s);
        nodes.push_back({s, b.add_node(pose.x, pose.y, std::move(tags), Placement{"main", s, 0.0})});
    }
    return nodes;
}

// A branch track from a switch node on the main line; its last node is either
// another main-line switch (end_id) or a new node with end_tags.
std::int64_t draw_branch(const TrackDesign& track, const Tags& way_tags, std::int64_t start_id,
                         std::optional<std::int64_t> end_id, const Tags& end_tags, OsmBuilder& b,
                         Rng& rng) {
    const geometry::IndexedAlignment idx(track.alignment);
    const auto chain = mapper_chainages(track.alignment, {0.0, idx.length()}, rng);
    std::vector<std::int64_t> ids{start_id};
    for (std::size_t i = 1; i < chain.size(); ++i) {
        const bool last = i + 1 == chain.size();
        if (last && end_id) {
            ids.push_back(*end_id);
            break;
        }
        const geometry::Pose pose = idx.evaluate(chain[i]);
        ids.push_back(b.add_node(pose.x, pose.y, last ? end_tags : Tags{},
                                 Placement{track.name, chain[i], 0.0}));
    }
    return b.add_way(std::move(ids), way_tags, "track", track.name, 0.0, idx.length());
}

} // namespace

DrawnTracks draw_tracks(const RouteDesign& d, OsmBuilder& b, Rng& rng) {
    const auto nodes = draw_main_nodes(d, b, rng);
    DrawnTracks out;
    for (const auto& span : d.main_ways) {
        std::vector<std::int64_t> ids;
        for (const auto& n : nodes) {
            if (n.s >= span.s_from && n.s <= span.s_to) {
                ids.push_back(n.id);
            }
        }
        out.main_ways.push_back(b.add_way(std::move(ids), span.tags, "track", d.main.name,
                                          span.s_from, span.s_to));
    }
    for (const auto& n : nodes) {
        for (const auto& p : d.main_points) {
            if (p.s == n.s && (p.kind == "stop" || p.kind == "halt")) {
                out.stops.push_back(n.id);
            }
        }
    }
    out.level_crossing = node_at(nodes, d.level_crossing);

    draw_branch(d.loop, d.loop_tags, node_at(nodes, d.switch_loop_west),
                node_at(nodes, d.switch_loop_east), {}, b, rng);
    draw_branch(d.spur, d.spur_tags, node_at(nodes, d.switch_spur), std::nullopt,
                {{"railway", "buffer_stop"}}, b, rng);
    return out;
}

} // namespace railodd::sample
