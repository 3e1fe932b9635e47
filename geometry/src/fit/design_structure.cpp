// One structure (element kinds and knots) solved exactly in the developed
// frame: the same moves as the search (design_quadratic.hpp) along one path,
// then back from the end to recover every knot's state (as a Kalman
// smoother recovers states from an information filter).
#include "design_dp.hpp"

#include "design_guide.hpp"
#include "design_local.hpp"
#include "design_quadratic.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace railodd::geometry::fit {

using design::Quad;
using design::S;
using design::Vec4;

std::vector<FrameNode> by_chainage(std::vector<FrameNode> n) {
    const auto by_t = [](const FrameNode& a, const FrameNode& b) { return a.t < b.t; };
    if (!std::is_sorted(n.begin(), n.end(), by_t)) {
        std::stable_sort(n.begin(), n.end(), by_t);
    }
    return n;
}

namespace {

// The state u past the start of element e, from the state (z, dz) there.
FrameState along(const FrameElement& e, double z, double dz, double u) {
    const double L = e.s1 - e.s0, g = L > 0.0 ? (e.k1 - e.k0) / L : 0.0;
    return {z + dz * u + e.k0 * u * u / 2 + g * u * u * u / 6, dz + e.k0 * u + g * u * u / 2, e.k0 + g * u};
}

} // namespace

FrameState state_along(const FrameElement& e, const FrameState& start, double u) {
    return along(e, start.z, start.dz, u);
}

std::vector<double> frame_residuals(const FrameDesign& d, const std::vector<FrameNode>& nodes) {
    std::vector<std::size_t> order(nodes.size());
    for (std::size_t i = 0; i < order.size(); ++i) {
        order[i] = i;
    }
    std::stable_sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return nodes[a].t < nodes[b].t; });
    std::vector<double> r(nodes.size(), 0.0);
    FrameState at = d.start; // at the start of element j
    std::size_t j = 0;
    for (const std::size_t i : order) {
        while (j + 1 < d.elements.size() && nodes[i].t > d.elements[j].s1) {
            at = along(d.elements[j], at.z, at.dz, d.elements[j].s1 - d.elements[j].s0);
            ++j;
        }
        r[i] = nodes[i].z - along(d.elements[j], at.z, at.dz, nodes[i].t - d.elements[j].s0).z;
    }
    return r;
}

double stray_cost(const FrameDesign& d, const std::vector<FrameNode>& nodes) {
    double c = 0.0;
    for (const FrameNode& n : nodes) {
        if (n.w == 0.0) {
            const double off = (n.z - design_state(d, n.t).z) / stray_scale_m;
            c += off * off;
        }
    }
    return c;
}

FrameState design_state(const FrameDesign& d, double t) {
    FrameState at = d.start;
    std::size_t j = 0;
    while (j + 1 < d.elements.size() && t > d.elements[j].s1) {
        at = along(d.elements[j], at.z, at.dz, d.elements[j].s1 - d.elements[j].s0);
        ++j;
    }
    return along(d.elements[j], at.z, at.dz, t - d.elements[j].s0);
}

bool walk(Quad& f, std::span<const FrameElement> w, const std::vector<FrameNode>& n, std::size_t next,
          std::size_t end, const DesignDpOptions& o, bool at_chain_start, bool last_at_free_end, design::KnotMap* maps,
          Quad* knots, bool at_knot_after) {
    const auto free_end = [&](std::size_t i) {
        return (i == 0 && at_chain_start && !o.start) || (i + 1 == w.size() && last_at_free_end);
    };
    f.c += at_chain_start ? design::first_penalty(w.front().kind, o, free_end(0))
                          : design::element_penalty(w.front().kind, o, free_end(0));
    for (std::size_t i = 0;; ++i) {
        const FrameElement& e = w[i];
        const bool last = i + 1 == w.size();
        std::size_t upto = next;
        while (upto < end && (last || n[upto].t < e.s1 || (n[upto].t == e.s1 && !at_knot_after))) {
            ++upto;
        }
        design::add_nodes(f, n, next, upto, e.s0);
        next = upto;
        if (o.curvature_weight > 0.0) {
            design::add_curvature(f, 0.0, (e.s1 - e.s0) / S, o.curvature_weight);
        }
        if (o.guide) {
            o.guide->add(f, e.s0, e.s0, e.s1);
        }
        if (last) {
            return true;
        }
        Quad g = design::to_knot(f, (e.s1 - e.s0) / S, maps ? &maps[i] : nullptr);
        if (knots) {
            knots[i + 1] = g;
        }
        const ElementKind k = w[i + 1].kind;
        if (!design::open_element(g, k, e.kind == ElementKind::transition && k == ElementKind::transition)) {
            return false;
        }
        g.c += design::element_penalty(k, o, free_end(i + 1));
        f = std::move(g);
    }
}

ForwardPass forward_pass(const std::vector<FrameNode>& n, const std::vector<FrameElement>& st, const DesignDpOptions& o,
                         bool at_knot_after) {
    if (st.empty()) {
        throw std::invalid_argument("solve_structure: no elements");
    }
    ForwardPass r;
    r.knots.assign(st.size() + 1, Quad{});
    r.maps.assign(st.size(), design::KnotMap{});
    Quad f = design::first_element(st.front().kind, o);
    if (!walk(f, st, n, 0, n.size(), o, true, !o.end, r.maps.data(), r.knots.data(), at_knot_after)) {
        throw std::invalid_argument("solve_structure: the design rules forbid this sequence");
    }
    r.cost = design::close_chain(f, (st.back().s1 - st.back().s0) / S, st.back().kind, o, &r.last_start);
    return r;
}

FrameDesign solved(const std::vector<FrameElement>& st, const ForwardPass& pass) {
    std::vector<Vec4> x(st.size());
    x.back() = pass.last_start;
    for (std::size_t j = st.size() - 1; j-- > 0;) {
        Vec4 y = x[j + 1];
        y(3) = 0.0;
        x[j] = design::start_from_knot(pass.maps[j], y);
    }
    FrameDesign d;
    d.cost = pass.cost;
    d.start = {x[0](0), x[0](1) / S, x[0](2) / (S * S)};
    for (std::size_t j = 0; j < st.size(); ++j) {
        const double u = (st[j].s1 - st[j].s0) / S;
        d.elements.push_back({st[j].kind, st[j].s0, st[j].s1, x[j](2) / (S * S), (x[j](2) + x[j](3) * u) / (S * S)});
    }
    return d;
}

FrameDesign solve_structure(const std::vector<FrameNode>& in, const std::vector<FrameElement>& st,
                            const DesignDpOptions& o) {
    const std::vector<FrameNode> n = by_chainage(in);
    FrameDesign d = solved(st, forward_pass(n, st, o));
    const std::vector<double> r = frame_residuals(d, n);
    for (std::size_t i = 0; i < n.size(); ++i) {
        d.data_cost += n[i].w * r[i] * r[i];
    }
    return d;
}

} // namespace railodd::geometry::fit
