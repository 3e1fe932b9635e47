#include "design_rules.hpp"

namespace railodd::geometry::fit::design {

Vec4 scaled(const FrameState& s) { return {s.z, s.dz * S, s.k * S * S, 0.0}; }

bool may_follow(ElementKind before, ElementKind after) {
    return before == ElementKind::transition || after == ElementKind::transition;
}

bool continues(ElementKind beyond, ElementKind kind) { return kind == beyond && kind != ElementKind::transition; }

bool may_adjoin(ElementKind beyond, ElementKind kind) { return may_follow(beyond, kind) || continues(beyond, kind); }

double first_penalty(ElementKind kind, const DesignDpOptions& o, bool at_free_end) {
    return o.before && continues(*o.before, kind) ? 0.0 : element_penalty(kind, o, at_free_end);
}

double min_length(ElementKind k, const DesignDpOptions& o) {
    return k == ElementKind::line ? o.min_line_m : k == ElementKind::arc ? o.min_arc_m : o.min_transition_m;
}

double element_penalty(ElementKind k, const DesignDpOptions& o, bool at_free_end) {
    const double params = k == ElementKind::arc ? 2.0 : (k == ElementKind::transition && at_free_end) ? 2.0 : 1.0;
    return params * o.parameter_penalty;
}

void add_free_end(Quad& f, double u) {
    constexpr double sd = S * S / 500.0; // scaled curvature
    add_row(f, Vec4(0.0, 0.0, 1.0, u), 1.0 / (sd * sd), 0.0);
}

Quad first_element(ElementKind kind, const DesignDpOptions& o) {
    Quad f = empty_quad(first_free(kind));
    if (o.before == ElementKind::transition && kind == ElementKind::transition) {
        fix_zero(f, 2);
    }
    if (o.start) {
        add_tie(f, scaled(*o.start), tie_weight);
    } else {
        add_free_end(f, 0.0);
    }
    return f;
}

void add_nodes(Quad& f, const std::vector<FrameNode>& n, std::size_t first, std::size_t last, double s0) {
    if (last <= first) {
        return;
    }
    // A node's row is (1, u, u^2/2, u^3/6): its outer product holds only the
    // powers u^0..u^6, so the nodes are summed as weighted power sums (of w,
    // and of w z up to u^3) and the quadratic built once: the local search
    // adds the nodes of every trial window this way.
    double m[7] = {}, r[4] = {}, c = 0.0;
    for (std::size_t i = first; i < last; ++i) {
        const double u = (n[i].t - s0) / S, w = n[i].w, wz = w * n[i].z;
        const double u2 = u * u, u3 = u2 * u;
        m[0] += w;
        m[1] += w * u;
        m[2] += w * u2;
        m[3] += w * u3;
        m[4] += w * u2 * u2;
        m[5] += w * u2 * u3;
        m[6] += w * u3 * u3;
        r[0] += wz;
        r[1] += wz * u;
        r[2] += wz * u2;
        r[3] += wz * u3;
        c += wz * n[i].z;
    }
    constexpr double fact[4] = {1.0, 1.0, 2.0, 6.0};
    for (int a = 0; a < 4; ++a) {
        if (!(f.free & (1u << a))) {
            continue;
        }
        f.q(a) += r[a] / fact[a];
        for (int b = 0; b < 4; ++b) {
            if (f.free & (1u << b)) {
                f.P(a, b) += m[a + b] / (fact[a] * fact[b]);
            }
        }
    }
    f.c += c;
}

double close_chain(Quad f, double u, ElementKind kind, const DesignDpOptions& o, Vec4* start) {
    if (!o.end) {
        add_free_end(f, u);
        return minimum(f, start);
    }
    KnotMap map;
    Quad g = to_knot(f, u, &map);
    if (o.after == ElementKind::transition && kind == ElementKind::transition) {
        fix_zero(g, 2);
    }
    add_tie(g, scaled(*o.end), tie_weight);
    Vec4 y;
    const double refund = o.after && continues(*o.after, kind) ? element_penalty(kind, o, false) : 0.0;
    const double cost = minimum(g, &y) - refund;
    if (start) {
        y(3) = 0.0;
        *start = start_from_knot(map, y);
    }
    return cost;
}

} // namespace railodd::geometry::fit::design
