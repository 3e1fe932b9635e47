#include "profile_ties.hpp"

#include "railodd/geometry/vertex_legs.hpp"
#include "vertical/gradient_stats.hpp"

#include <Eigen/Sparse>

#include <algorithm>
#include <cmath>

namespace railodd::geometry {

namespace {

bool measured(const VerticalProfile& p) { return p.source == ElevationSource::dem || p.source == ElevationSource::osm_ele; }

// One track end at a vertex: its side of the vertex (0 / 1 from the
// movements, -1 where no train passes) and the grade leaving the vertex.
struct End {
    std::size_t edge = 0;
    bool at_start = false;
    int side = -1;
};

// Sides of each vertex (movement_sides): legs a train passes between lie on
// opposite sides.
std::vector<std::vector<End>> ends_by_vertex(const TrackGraph& graph, const FittedNetwork& net) {
    const std::vector<std::vector<Leg>> legs = legs_by_vertex(graph, net);
    std::vector<std::vector<End>> out(legs.size());
    for (std::size_t v = 0; v < legs.size(); ++v) {
        const auto& at = legs[v];
        std::vector<std::pair<std::size_t, std::size_t>> movements;
        for (std::size_t i = 0; i < at.size(); ++i) {
            for (std::size_t j = i + 1; j < at.size(); ++j) {
                if (g2_mismatch(at[i], at[j]).empty()) {
                    movements.emplace_back(i, j);
                }
            }
        }
        const LegSides sides = movement_sides(at.size(), movements);
        for (std::size_t i = 0; i < at.size(); ++i) {
            out[v].push_back({at[i].edge, at[i].at_start, sides.colour[i]});
        }
    }
    return out;
}

// Vertices connected to a measured track through the network.
std::vector<char> reaches_data(const TrackGraph& graph, const std::vector<VerticalProfile>& profiles) {
    std::vector<std::vector<std::size_t>> adj(graph.vertices.size());
    std::vector<char> seen(graph.vertices.size(), 0);
    std::vector<std::size_t> stack;
    for (std::size_t e = 0; e < graph.edges.size(); ++e) {
        adj[graph.edges[e].from].push_back(graph.edges[e].to);
        adj[graph.edges[e].to].push_back(graph.edges[e].from);
        if (measured(profiles[e])) {
            stack.push_back(graph.edges[e].from);
        }
    }
    while (!stack.empty()) {
        const std::size_t v = stack.back();
        stack.pop_back();
        if (!seen[v]) {
            seen[v] = 1;
            stack.insert(stack.end(), adj[v].begin(), adj[v].end());
        }
    }
    return seen;
}

// Vertex heights: the mean of measured ends, the rest harmonic over the
// network (each track pulls with weight 1 / length). Parts of the network
// no measured track reaches stay at 0.
std::vector<double> vertex_heights(const TrackGraph& graph, const FittedNetwork& net,
                                   const std::vector<VerticalProfile>& profiles, const std::vector<std::vector<End>>& ends,
                                   const std::vector<char>& data) {
    const std::size_t nv = ends.size();
    std::vector<double> sum(nv, 0.0), h(nv, 0.0);
    std::vector<int> count(nv, 0);
    for (std::size_t v = 0; v < nv; ++v) {
        for (const End& e : ends[v]) {
            if (measured(profiles[e.edge])) {
                sum[v] += elevation_at(profiles[e.edge].polys, e.at_start ? 0.0 : length(net.edges[e.edge].alignment));
                ++count[v];
            }
        }
        h[v] = count[v] > 0 ? sum[v] / count[v] : 0.0;
    }
    std::vector<long> unknown(nv, -1);
    long n = 0;
    for (std::size_t v = 0; v < nv; ++v) {
        unknown[v] = count[v] == 0 && data[v] ? n++ : -1;
    }
    if (n == 0) {
        return h;
    }
    std::vector<Eigen::Triplet<double>> t;
    Eigen::VectorXd rhs = Eigen::VectorXd::Zero(n);
    for (std::size_t e = 0; e < graph.edges.size(); ++e) {
        const std::size_t a = graph.edges[e].from, b = graph.edges[e].to;
        const double w = 1.0 / std::max(1.0, length(net.edges[e].alignment));
        for (const auto& [p, q] : {std::pair{a, b}, std::pair{b, a}}) {
            if (unknown[p] < 0 || p == q) { // measured, unreached or a loop
                continue;
            }
            t.emplace_back(unknown[p], unknown[p], w);
            if (unknown[q] >= 0) {
                t.emplace_back(unknown[p], unknown[q], -w);
            } else {
                rhs[unknown[p]] += w * h[q];
            }
        }
    }
    Eigen::SparseMatrix<double> m(n, n);
    m.setFromTriplets(t.begin(), t.end());
    const Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>> ldlt(m);
    const Eigen::VectorXd x = ldlt.solve(rhs);
    for (std::size_t v = 0; v < nv; ++v) {
        if (unknown[v] >= 0) {
            h[v] = x[unknown[v]];
        }
    }
    return h;
}

// Adds the cubic through (0, d0, m0) and (len, d1, m1) to every piece.
void add_hermite(std::vector<ElevationPoly>& polys, double len, double d0, double d1, double m0, double m1) {
    const double c2 = (3.0 * (d1 - d0) / len - 2.0 * m0 - m1) / len;
    const double c3 = (2.0 * (d0 - d1) / len + m0 + m1) / (len * len);
    for (ElevationPoly& p : polys) {
        const double s = p.s;
        p.a += d0 + s * (m0 + s * (c2 + s * c3));
        p.b += m0 + s * (2.0 * c2 + 3.0 * c3 * s);
        p.c += c2 + 3.0 * c3 * s;
        p.d += c3;
    }
}

struct Network {
    const TrackGraph& graph;
    const FittedNetwork& net;
    std::vector<VerticalProfile>& profiles;
    std::vector<std::vector<End>> ends;
    std::vector<double> h;

    double len(std::size_t e) const { return length(net.edges[e].alignment); }
    std::size_t vertex_at(std::size_t e, bool at_start) const {
        const auto& ge = graph.edges[e];
        return (at_start != net.edges[e].reversed) ? ge.from : ge.to;
    }
    // Grade leaving the vertex along the end, before the ties.
    double leaving(const End& end) const {
        const double l = len(end.edge);
        if (!measured(profiles[end.edge])) {
            return (h[vertex_at(end.edge, !end.at_start)] - h[vertex_at(end.edge, end.at_start)]) / std::max(l, 1e-9);
        }
        const auto& polys = profiles[end.edge].polys;
        return end.at_start ? gradient_at(polys, 0.0) : -gradient_at(polys, l);
    }
};

// Per vertex, the grade leaving it on side 0 (the mean over the ends a
// train passes, those on side 1 counted backwards).
std::vector<double> vertex_grades(const Network& n) {
    std::vector<double> g(n.ends.size(), 0.0);
    for (std::size_t v = 0; v < n.ends.size(); ++v) {
        double sum = 0.0;
        int count = 0;
        for (const End& e : n.ends[v]) {
            if (e.side >= 0 && n.len(e.edge) > 0.0) {
                sum += e.side == 0 ? n.leaving(e) : -n.leaving(e);
                ++count;
            }
        }
        g[v] = count > 0 ? sum / count : 0.0;
    }
    return g;
}

// Height and grade (along s) each end of each track must meet.
struct Target {
    double h0 = 0.0, h1 = 0.0, g0 = 0.0, g1 = 0.0;
};

std::vector<Target> targets(const Network& n, const std::vector<double>& grade) {
    std::vector<Target> t(n.graph.edges.size());
    for (std::size_t v = 0; v < n.ends.size(); ++v) {
        for (const End& e : n.ends[v]) {
            const double out = e.side < 0 ? n.leaving(e) : (e.side == 0 ? grade[v] : -grade[v]);
            Target& x = t[e.edge];
            (e.at_start ? x.h0 : x.h1) = n.h[v];
            (e.at_start ? x.g0 : x.g1) = e.at_start ? out : -out;
        }
    }
    return t;
}

} // namespace

ProfileTies tie_profiles(const TrackGraph& graph, const FittedNetwork& net, std::vector<VerticalProfile>& profiles) {
    ProfileTies ties;
    if (std::none_of(profiles.begin(), profiles.end(), measured)) {
        return ties; // no data anywhere: every track stays flat, and says so
    }
    const std::vector<char> data = reaches_data(graph, profiles);
    Network n{graph, net, profiles, ends_by_vertex(graph, net), {}};
    n.h = vertex_heights(graph, net, profiles, n.ends, data);
    for (std::size_t v = 0; v < n.ends.size(); ++v) {
        double lo = 1e300, hi = -1e300;
        for (const End& e : n.ends[v]) {
            if (measured(profiles[e.edge])) {
                const double z = elevation_at(profiles[e.edge].polys, e.at_start ? 0.0 : n.len(e.edge));
                lo = std::min(lo, z);
                hi = std::max(hi, z);
            }
        }
        ties.vertices += n.ends[v].size() > 1 ? 1 : 0;
        ties.max_height_step_m = std::max(ties.max_height_step_m, hi - lo);
    }
    const std::vector<Target> t = targets(n, vertex_grades(n));
    for (std::size_t e = 0; e < profiles.size(); ++e) {
        const double l = n.len(e);
        VerticalProfile& p = profiles[e];
        if (!(l > 0.0) || (!measured(p) && !data[graph.edges[e].from])) {
            continue;
        }
        if (!measured(p)) {
            p.polys = {{0.0, 0.0, 0.0, 0.0, 0.0}};
            p.source = ElevationSource::interpolated;
            ++ties.interpolated;
        }
        add_hermite(p.polys, l, t[e].h0 - elevation_at(p.polys, 0.0), t[e].h1 - elevation_at(p.polys, l),
                    t[e].g0 - gradient_at(p.polys, 0.0), t[e].g1 - gradient_at(p.polys, l));
        p.max_gradient_permille = 1000.0 * vertical::max_abs_gradient(p.polys, l);
        p.steep = vertical::steep_stretches(p.polys, l, ProfileOptions{}.steep_permille / 1000.0);
    }
    return ties;
}

} // namespace railodd::geometry
