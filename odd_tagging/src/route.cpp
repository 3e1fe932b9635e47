#include "railodd/odd/route.hpp"

#include "railodd/geometry/alignment.hpp"
#include "railodd/odd/profile_summary.hpp"
#include "railodd/util/errors.hpp"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdint>
#include <functional>
#include <limits>
#include <numbers>
#include <optional>
#include <queue>
#include <set>
#include <tuple>

namespace railodd::odd {

namespace {

constexpr double infinity = std::numeric_limits<double>::infinity();

// An end of an edge's alignment, as an index: 2 * edge (s = 0) or
// 2 * edge + 1 (s = length). The route search runs over these ends.
std::size_t end_index(std::size_t edge, bool at_end) { return 2 * edge + (at_end ? 1 : 0); }
std::size_t edge_of(std::size_t end) { return end / 2; }
bool at_end(std::size_t end) { return end % 2 == 1; }

struct Network {
    const geometry::TrackGraph& graph;
    const geometry::FittedNetwork& fitted;
    std::vector<double> lengths;                 // per edge, of its alignment
    std::vector<std::vector<std::size_t>> moves; // per end: the ends a train may continue into at its vertex

    double s_of(std::size_t end) const { return at_end(end) ? lengths[edge_of(end)] : 0.0; }

    std::size_t vertex_of(std::size_t end) const {
        const auto& e = graph.edges[edge_of(end)];
        // An alignment fitted against the node order starts at the edge's `to`.
        return at_end(end) != fitted.edges[edge_of(end)].reversed ? e.to : e.from;
    }

    // Heading of the track leaving the vertex through this end.
    double outgoing_heading(std::size_t end) const {
        const auto& a = fitted.edges[edge_of(end)].alignment;
        const geometry::Pose p = geometry::evaluate(a, s_of(end));
        return at_end(end) ? p.hdg + std::numbers::pi : p.hdg;
    }

    // A chain item is left through its alignment end when chain and alignment
    // run the same way along the graph edge.
    std::size_t exit_end(const geometry::ChainItem& item) const {
        return end_index(item.edge, item.reversed == fitted.edges[item.edge].reversed);
    }
    std::size_t entry_end(const geometry::ChainItem& item) const { return exit_end(item) ^ 1U; }

    void link(std::size_t a, std::size_t b) {
        moves[a].push_back(b);
        moves[b].push_back(a);
    }
};

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

struct Path {
    double length = infinity;
    std::vector<RoutePiece> pieces;
};

void add_piece(Path& p, std::size_t edge, double s_from, double s_to) {
    p.pieces.push_back({edge, s_to < s_from, s_from, s_to, 0.0});
}

// Zero-length pieces (a station on a vertex) dropped, chainage accumulated.
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
Path shortest_path(const Network& n, const geometry::AttachedFeature& a, const geometry::AttachedFeature& b) {
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

std::string lower(std::string s) {
    std::transform(s.begin(), s.end(), s.begin(), [](unsigned char c) { return std::tolower(c); });
    return s;
}

bool is_stop(const std::string& kind) {
    return kind == "station" || kind == "halt" || kind == "stop" || kind == "tram_stop";
}

// The attached stations named `name`: exact matches, else matches ignoring case.
std::vector<const geometry::AttachedFeature*> stations_named(const geometry::Attachment& attachment,
                                                             const std::vector<ingest::Feature>& features,
                                                             const std::string& name, std::string& found) {
    std::vector<const geometry::AttachedFeature*> exact, folded;
    std::set<std::string> names;
    for (const auto& a : attachment.attached) {
        const auto& f = features.at(a.feature);
        const std::string n = ingest::tag_or(f.tags, "name");
        if (!is_stop(f.kind) || n.empty()) {
            continue;
        }
        names.insert(n);
        if (n == name) {
            exact.push_back(&a);
        } else if (lower(n) == lower(name)) {
            folded.push_back(&a);
        }
    }
    if (exact.empty() && folded.empty()) {
        std::string list;
        for (const auto& n : names) {
            list += (list.empty() ? "" : ", ") + n;
        }
        throw InputError("", "station '" + name + "' is not in the selection; stations are: " +
                                 (list.empty() ? "(none)" : list));
    }
    found = ingest::tag_or(features[(exact.empty() ? folded : exact).front()->feature].tags, "name");
    return exact.empty() ? folded : exact;
}

// The element's sampled line (evenly spaced from chainage_start to
// chainage_end) cut to the fractions [t0, t1] of its length.
std::vector<std::pair<double, double>> cut_line(const std::vector<std::pair<double, double>>& line, double t0,
                                                double t1) {
    if (line.size() < 2 || (t0 <= 0.0 && t1 >= 1.0)) {
        return line;
    }
    const double last = static_cast<double>(line.size() - 1);
    auto at = [&](double t) {
        const double x = std::clamp(t, 0.0, 1.0) * last;
        const std::size_t i = std::min(static_cast<std::size_t>(x), line.size() - 2);
        const double f = x - static_cast<double>(i);
        return std::pair{line[i].first + f * (line[i + 1].first - line[i].first),
                         line[i].second + f * (line[i + 1].second - line[i].second)};
    };
    std::vector<std::pair<double, double>> out{at(t0)};
    for (std::size_t i = 1; i + 1 < line.size(); ++i) {
        const double t = static_cast<double>(i) / last;
        if (t > t0 && t < t1) {
            out.push_back(line[i]);
        }
    }
    out.push_back(at(t1));
    return out;
}

// The element's part on one route piece, in route chainage; none if it is off the piece.
std::optional<TaggedElement> on_piece(const TaggedElement& e, const RoutePiece& p) {
    const double lo = std::min(p.s_from, p.s_to), hi = std::max(p.s_from, p.s_to);
    const double c0 = std::min(e.chainage_start, e.chainage_end), c1 = std::max(e.chainage_start, e.chainage_end);
    const double a = e.point ? c0 : std::max(c0, lo), b = e.point ? c0 : std::min(c1, hi);
    if (e.track != p.edge || (e.point ? (a < lo - 1e-6 || a > hi + 1e-6) : b - a <= 1e-6)) {
        return std::nullopt;
    }
    auto chainage = [&](double s) { return p.chainage_start + (p.reversed ? p.s_from - s : s - p.s_from); };
    TaggedElement out = e;
    if (!e.point) {
        // s runs with the edge's chainage on the element's road: move it in by what was cut.
        out.s_start = e.s_start + (a - c0);
        out.s_end = e.s_end - (c1 - b);
        out.lonlat = cut_line(e.lonlat, (a - c0) / (c1 - c0), (b - c0) / (c1 - c0));
    }
    out.chainage_start = std::min(chainage(a), chainage(b));
    out.chainage_end = std::max(chainage(a), chainage(b));
    return out;
}

bool names_any(const std::vector<std::string>& ids, const std::set<std::string>& known) {
    return std::any_of(ids.begin(), ids.end(), [&](const std::string& id) { return known.contains(id); });
}

} // namespace

Route find_route(const geometry::TrackGraph& graph, const geometry::FittedNetwork& fitted,
                 const geometry::Attachment& attachment, const std::vector<ingest::Feature>& features,
                 const std::string& from, const std::string& to) {
    Route route;
    const auto starts = stations_named(attachment, features, from, route.from);
    const auto ends = stations_named(attachment, features, to, route.to);
    const Network network = build_network(graph, fitted);
    Path best;
    for (const auto* a : starts) {
        for (const auto* b : ends) {
            Path p = shortest_path(network, *a, *b);
            if (p.length < best.length) {
                best = std::move(p);
            }
        }
    }
    if (best.length == infinity) {
        throw InputError("", "no route from station '" + route.from + "' to station '" + route.to +
                                 "': no path over the track graph joins them (through routes and switch movements only)");
    }
    route.length_m = best.length;
    route.pieces = std::move(best.pieces);
    std::set<std::int64_t> ways;
    for (const auto& p : route.pieces) {
        for (const auto& span : graph.edges[p.edge].ways) {
            ways.insert(span.way_id);
        }
    }
    for (const auto id : ways) {
        route.osm_ways.push_back("way:" + std::to_string(id));
    }
    return route;
}

OddProfile along_route(const OddProfile& profile, const Route& route, const Taxonomy& taxonomy) {
    OddProfile out = profile;
    out.elements.clear();
    for (const auto& piece : route.pieces) {
        for (const auto& e : profile.elements) {
            if (auto part = on_piece(e, piece)) {
                out.elements.push_back(std::move(*part));
            }
        }
    }
    std::stable_sort(out.elements.begin(), out.elements.end(), [](const TaggedElement& a, const TaggedElement& b) {
        return std::tie(a.chainage_start, a.element, a.chainage_end) <
               std::tie(b.chainage_start, b.element, b.chainage_end);
    });
    // Unparsed values stay when they belong to the route: a way of an edge on
    // it, or an object behind a kept element.
    std::set<std::string> ids(route.osm_ways.begin(), route.osm_ways.end());
    for (const auto& e : out.elements) {
        ids.insert(e.osm_ids.begin(), e.osm_ids.end());
    }
    std::erase_if(out.unparsed, [&](const Unparsed& u) { return !names_any(u.osm_ids, ids); });
    out.route = route.from + " -> " + route.to;
    out.length_m = route.length_m;
    out.tracks = route.pieces.size();
    out.summary = summarize(out, &taxonomy);
    return out;
}

nlohmann::ordered_json route_report(const Route& route) {
    nlohmann::ordered_json pieces = nlohmann::ordered_json::array();
    for (const auto& p : route.pieces) {
        pieces.push_back({{"edge", p.edge},
                          {"reversed", p.reversed},
                          {"s_from", p.s_from},
                          {"s_to", p.s_to},
                          {"chainage_start", p.chainage_start}});
    }
    return {{"from", route.from}, {"to", route.to}, {"length_m", route.length_m}, {"pieces", std::move(pieces)}};
}

} // namespace railodd::odd
