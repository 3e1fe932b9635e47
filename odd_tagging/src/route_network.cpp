#include "route_network.hpp"

#include <algorithm>
#include <cmath>
#include <functional>
#include <optional>
#include <queue>
#include <set>

namespace railodd::odd::route_detail {

namespace {

// The ends of a chain's items at a vertex: its passage through it (or its end there).
std::vector<std::size_t> chain_ends_at(const Network& n, const geometry::Chain& chain, std::size_t vertex) {
    std::vector<std::size_t> ends;
    for (const auto& item : chain.items) {
        for (const std::size_t end : {n.entry_end(item), n.exit_end(item)}) {
            if (n.vertex_of(end) == vertex) {
                ends.push_back(end);
            }
        }
    }
    return ends;
}

// A branch tied to a through chain joins only the switch's stem: the through
// leg leaving the vertex opposite to the branch (the other leg leaves it in
// the branch's direction, and no train turns back through a switch).
void link_branch(Network& n, std::size_t branch, const geometry::Chain& through, std::size_t vertex) {
    const double h = n.outgoing_heading(branch);
    std::optional<std::size_t> stem;
    double most_opposite = infinity;
    for (const std::size_t leg : chain_ends_at(n, through, vertex)) {
        const double c = std::cos(n.outgoing_heading(leg) - h);
        if (leg != branch && c < most_opposite) {
            most_opposite = c;
            stem = leg;
        }
    }
    if (stem) {
        n.link(branch, *stem);
    }
}

} // namespace

Network build_network(const geometry::TrackGraph& graph, const geometry::FittedNetwork& fitted) {
    Network n{graph, fitted, {}, std::vector<std::vector<std::size_t>>(2 * fitted.edges.size())};
    for (const auto& e : fitted.edges) {
        n.lengths.push_back(geometry::length(e.alignment));
    }
    for (const auto& chain : fitted.chains) {
        if (chain.items.empty()) {
            continue;
        }
        for (std::size_t i = 1; i < chain.items.size(); ++i) {
            n.link(n.exit_end(chain.items[i - 1]), n.entry_end(chain.items[i]));
        }
        if (chain.start.tied && chain.start.to_chain < fitted.chains.size()) {
            link_branch(n, n.entry_end(chain.items.front()), fitted.chains[chain.start.to_chain], chain.start.vertex);
        }
        if (chain.end.tied && chain.end.to_chain < fitted.chains.size()) {
            link_branch(n, n.exit_end(chain.items.back()), fitted.chains[chain.end.to_chain], chain.end.vertex);
        }
    }
    return n;
}



void add_piece(Path& p, std::size_t edge, double s_from, double s_to) {
    p.pieces.push_back({edge, s_to < s_from, s_from, s_to, 0.0});
}

void finish(Path& p) {
    auto empty = [](const RoutePiece& r) { return std::abs(r.s_to - r.s_from) <= 1e-9; };
    if (!std::all_of(p.pieces.begin(), p.pieces.end(), empty)) {
        std::erase_if(p.pieces, empty);
    }
    double chainage = 0.0;
    for (auto& r : p.pieces) {
        r.chainage_start = chainage;
        chainage += std::abs(r.s_to - r.s_from);
    }
}

// Dijkstra over alignment ends ("left the edge here"), from a at its s to b at its s.
Path shortest_path(const Network& n, TrackPoint a, TrackPoint b) {
    std::vector<double> dist(n.moves.size(), infinity);
    std::vector<std::ptrdiff_t> pred(n.moves.size(), -1);
    using Item = std::pair<double, std::size_t>;
    std::priority_queue<Item, std::vector<Item>, std::greater<>> queue;
    for (const bool forward : {true, false}) {
        const std::size_t exit = end_index(a.edge, forward);
        dist[exit] = forward ? n.lengths[a.edge] - a.s : a.s;
        queue.push({dist[exit], exit});
    }
    double best = a.edge == b.edge ? std::abs(b.s - a.s) : infinity;
    std::ptrdiff_t best_exit = -1, best_entry = -1; // -1: along the shared edge directly
    while (!queue.empty()) {
        const auto [d, u] = queue.top();
        queue.pop();
        if (d > dist[u] || d >= best) {
            continue;
        }
        for (const std::size_t q : n.moves[u]) {
            const std::size_t f = edge_of(q);
            if (f == b.edge && d + std::abs(b.s - n.s_of(q)) < best) {
                best = d + std::abs(b.s - n.s_of(q));
                best_exit = static_cast<std::ptrdiff_t>(u);
                best_entry = static_cast<std::ptrdiff_t>(q);
            }
            const std::size_t w = q ^ 1U;
            if (d + n.lengths[f] < dist[w]) {
                dist[w] = d + n.lengths[f];
                pred[w] = static_cast<std::ptrdiff_t>(u);
                queue.push({dist[w], w});
            }
        }
    }
    Path path;
    path.length = best;
    if (best == infinity) {
        return path;
    }
    if (best_exit < 0) {
        add_piece(path, a.edge, a.s, b.s);
        finish(path);
        return path;
    }
    std::vector<std::size_t> exits;
    for (std::ptrdiff_t u = best_exit; u >= 0; u = pred[static_cast<std::size_t>(u)]) {
        exits.push_back(static_cast<std::size_t>(u));
    }
    std::reverse(exits.begin(), exits.end());
    add_piece(path, a.edge, a.s, n.s_of(exits.front()));
    for (std::size_t i = 1; i < exits.size(); ++i) {
        add_piece(path, edge_of(exits[i]), n.s_of(exits[i] ^ 1U), n.s_of(exits[i]));
    }
    add_piece(path, b.edge, n.s_of(static_cast<std::size_t>(best_entry)), b.s);
    finish(path);
    return path;
}

std::vector<std::string> route_way_ids(const geometry::TrackGraph& graph, const std::vector<RoutePiece>& pieces) {
    std::set<std::int64_t> ways;
    for (const auto& p : pieces) {
        for (const auto& span : graph.edges[p.edge].ways) {
            ways.insert(span.way_id);
        }
    }
    std::vector<std::string> out;
    for (const auto id : ways) {
        out.push_back("way:" + std::to_string(id));
    }
    return out;
}

} // namespace railodd::odd::route_detail
