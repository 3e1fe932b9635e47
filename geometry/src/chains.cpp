// Through routes at vertices and the chains of edges they form.
#include "railodd/geometry/track_fit.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <tuple>

namespace railodd::geometry {

namespace {

// One end of an edge at a vertex: the edge and whether it is the edge's start.
struct EdgeEnd {
    std::size_t edge;
    bool at_start;
};

// Direction in which the edge leaves the vertex, from a node ~20 m away so
// that one noisy node next to the vertex does not decide it.
double leaving_heading(const GraphEdge& e, bool at_start) {
    const auto& n = e.nodes;
    const ingest::XY v = at_start ? n.front().xy : n.back().xy;
    ingest::XY far = v;
    for (std::size_t i = 1; i < n.size(); ++i) {
        far = at_start ? n[i].xy : n[n.size() - 1 - i].xy;
        if (std::hypot(far.x - v.x, far.y - v.y) >= 20.0) {
            break;
        }
    }
    return std::atan2(far.y - v.y, far.x - v.x);
}

double deflection(double leave_a, double leave_b) {
    // Straight through: b leaves opposite to a.
    double d = std::remainder(leave_b - (leave_a + std::numbers::pi), 2 * std::numbers::pi);
    return std::abs(d);
}

std::vector<EdgeEnd> ends_at(const TrackGraph& g, std::size_t v) {
    std::vector<EdgeEnd> ends;
    for (std::size_t e : g.vertices[v].edges) {
        const GraphEdge& edge = g.edges[e];
        const bool both = edge.from == v && edge.to == v;
        if (both) {
            // A loop edge appears twice in the vertex's list; add each end once.
            const bool have_start = std::any_of(ends.begin(), ends.end(), [&](const EdgeEnd& x) { return x.edge == e && x.at_start; });
            ends.push_back({e, !have_start});
        } else {
            ends.push_back({e, edge.from == v});
        }
    }
    return ends;
}

// Partner of every edge end: the end it continues straight into, if any.
struct Pairing {
    std::vector<long> at_start; // per edge: index of partner edge end (edge*2 + (at_start ? 0 : 1)), or -1
    std::vector<long> at_end;
};

long code(const EdgeEnd& e) { return static_cast<long>(e.edge * 2 + (e.at_start ? 0 : 1)); }

Pairing pair_ends(const TrackGraph& g, double max_deflection) {
    Pairing p{std::vector<long>(g.edges.size(), -1), std::vector<long>(g.edges.size(), -1)};
    for (std::size_t v = 0; v < g.vertices.size(); ++v) {
        const std::vector<EdgeEnd> ends = ends_at(g, v);
        std::vector<std::tuple<double, std::size_t, std::size_t>> candidates;
        for (std::size_t i = 0; i < ends.size(); ++i) {
            for (std::size_t j = i + 1; j < ends.size(); ++j) {
                const double d = deflection(leaving_heading(g.edges[ends[i].edge], ends[i].at_start),
                                            leaving_heading(g.edges[ends[j].edge], ends[j].at_start));
                if (d < max_deflection) {
                    candidates.emplace_back(d, i, j);
                }
            }
        }
        std::sort(candidates.begin(), candidates.end());
        std::vector<char> used(ends.size(), 0);
        for (const auto& [d, i, j] : candidates) {
            if (used[i] || used[j]) {
                continue;
            }
            used[i] = used[j] = 1;
            auto set = [&](const EdgeEnd& a, const EdgeEnd& b) {
                (a.at_start ? p.at_start : p.at_end)[a.edge] = code(b);
            };
            set(ends[i], ends[j]);
            set(ends[j], ends[i]);
        }
    }
    return p;
}

} // namespace

std::vector<Chain> build_chains(const TrackGraph& g, double max_deflection) {
    const Pairing p = pair_ends(g, max_deflection);
    std::vector<char> done(g.edges.size(), 0);
    std::vector<Chain> chains;
    auto partner = [&](std::size_t edge, bool at_start) { return at_start ? p.at_start[edge] : p.at_end[edge]; };
    auto walk = [&](std::size_t first, bool reversed) {
        Chain c;
        std::size_t e = first;
        bool rev = reversed;
        while (true) {
            done[e] = 1;
            c.items.push_back({e, rev});
            const long next = partner(e, rev); // leaving through the edge's far end
            if (next < 0) {
                break;
            }
            const auto ne = static_cast<std::size_t>(next / 2);
            if (done[ne]) {
                break; // a ring closed on itself
            }
            e = ne;
            rev = (next % 2) == 1; // entering at its end: run it backwards
        }
        const GraphEdge& f = g.edges[c.items.front().edge];
        const GraphEdge& l = g.edges[c.items.back().edge];
        c.start.vertex = c.items.front().reversed ? f.to : f.from;
        c.end.vertex = c.items.back().reversed ? l.from : l.to;
        chains.push_back(std::move(c));
    };
    // Chains start at edge ends without a partner, in edge order; what is
    // left afterwards are rings.
    for (std::size_t e = 0; e < g.edges.size(); ++e) {
        if (done[e]) {
            continue;
        }
        if (p.at_start[e] < 0) {
            walk(e, false);
        } else if (p.at_end[e] < 0) {
            walk(e, true);
        }
    }
    for (std::size_t e = 0; e < g.edges.size(); ++e) {
        if (!done[e]) {
            walk(e, false);
        }
    }
    return chains;
}

} // namespace railodd::geometry
