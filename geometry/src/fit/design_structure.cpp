// One structure (element kinds and knots) solved exactly in the developed
// frame: the same moves as the search (design_quadratic.hpp) along one path,
// then back from the end to recover every knot's state (as a Kalman
// smoother recovers states from an information filter).
#include "design_dp.hpp"

#include "design_local.hpp"
#include "design_quadratic.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace railodd::geometry::fit {

namespace {

using design::Quad;
using design::S;
using design::Vec4;

// z of the design at chainage t, from the element's start state x.
double z_at(const Vec4& x, double u) { return design::node_row(u).dot(x); }

} // namespace

double frame_z(const FrameDesign& d, double t) {
    double z = d.start.z, dz = d.start.dz;
    for (const FrameElement& e : d.elements) {
        const double L = e.s1 - e.s0, g = L > 0.0 ? (e.k1 - e.k0) / L : 0.0;
        if (t <= e.s1 || &e == &d.elements.back()) {
            const double u = t - e.s0;
            return z + dz * u + e.k0 * u * u / 2 + g * u * u * u / 6;
        }
        z += dz * L + e.k0 * L * L / 2 + g * L * L * L / 6;
        dz += e.k0 * L + g * L * L / 2;
    }
    return z;
}

double forward_pass(const std::vector<FrameNode>& n, const std::vector<FrameElement>& st, const DesignDpOptions& o,
                    std::vector<Quad>* knots, std::vector<design::KnotMap>* maps, Vec4* last_start) {
    if (st.empty()) {
        throw std::invalid_argument("solve_structure: no elements");
    }
    const std::size_t m = st.size();
    if (knots) {
        knots->assign(m + 1, Quad{});
    }
    if (maps) {
        maps->assign(m, design::KnotMap{});
    }
    Quad f = design::empty_quad(design::first_free(st.front().kind));
    if (o.start) {
        design::add_tie(f, design::scaled(*o.start), design::tie_weight);
    } else {
        design::add_free_end(f, 0.0);
    }
    const auto free_end = [&](std::size_t j) { return (j == 0 && !o.start) || (j + 1 == m && !o.end); };
    f.c += design::element_penalty(st.front().kind, o, free_end(0));
    std::size_t next = 0;
    for (std::size_t j = 0;; ++j) {
        const FrameElement& e = st[j];
        const bool last = j + 1 == m;
        for (; next < n.size() && (last || n[next].t <= e.s1); ++next) {
            design::add_row(f, design::node_row((n[next].t - e.s0) / S), n[next].w, n[next].z);
        }
        if (o.curvature_weight > 0.0) {
            design::add_curvature(f, 0.0, (e.s1 - e.s0) / S, o.curvature_weight);
        }
        if (last) {
            break;
        }
        Quad g = design::to_knot(f, (e.s1 - e.s0) / S, maps ? &(*maps)[j] : nullptr);
        if (knots) {
            (*knots)[j + 1] = g;
        }
        const ElementKind k = st[j + 1].kind;
        if (!design::open_element(g, k, e.kind == ElementKind::transition && k == ElementKind::transition)) {
            throw std::invalid_argument("solve_structure: the design rules forbid this sequence");
        }
        g.c += design::element_penalty(k, o, free_end(j + 1));
        f = g;
    }
    Vec4 x = Vec4::Zero();
    double cost = 0.0;
    if (o.end) {
        design::KnotMap map;
        Quad g = design::to_knot(f, (st.back().s1 - st.back().s0) / S, &map);
        design::add_tie(g, design::scaled(*o.end), design::tie_weight);
        Vec4 y;
        cost = design::minimum(g, &y);
        y(3) = 0.0;
        x = design::start_from_knot(map, y);
    } else {
        design::add_free_end(f, (st.back().s1 - st.back().s0) / S);
        cost = design::minimum(f, &x);
    }
    if (last_start) {
        *last_start = x;
    }
    return cost;
}

FrameDesign solve_structure(const std::vector<FrameNode>& in, const std::vector<FrameElement>& st,
                            const DesignDpOptions& o) {
    std::vector<FrameNode> n = in;
    if (!std::is_sorted(n.begin(), n.end(), [](const FrameNode& a, const FrameNode& b) { return a.t < b.t; })) {
        std::stable_sort(n.begin(), n.end(), [](const FrameNode& a, const FrameNode& b) { return a.t < b.t; });
    }
    std::vector<design::KnotMap> maps;
    std::vector<Vec4> x(st.size());
    FrameDesign d;
    d.cost = forward_pass(n, st, o, nullptr, &maps, &x.back());
    for (std::size_t j = st.size() - 1; j-- > 0;) {
        Vec4 y = x[j + 1];
        y(3) = 0.0;
        x[j] = design::start_from_knot(maps[j], y);
    }
    d.start = {x[0](0), x[0](1) / S, x[0](2) / (S * S)};
    for (std::size_t j = 0; j < st.size(); ++j) {
        const double u = (st[j].s1 - st[j].s0) / S;
        d.elements.push_back({st[j].kind, st[j].s0, st[j].s1, x[j](2) / (S * S), (x[j](2) + x[j](3) * u) / (S * S)});
    }
    std::size_t j = 0;
    for (const FrameNode& node : n) {
        while (j + 1 < st.size() && node.t > st[j].s1) {
            ++j;
        }
        const double r = node.z - z_at(x[j], (node.t - st[j].s0) / S);
        d.data_cost += node.w * r * r;
    }
    return d;
}

} // namespace railodd::geometry::fit
