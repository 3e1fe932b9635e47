// Local search on the design the beam found: each knot moved, each element
// merged away, kept where the exact cost (solve_structure) falls. The beam
// decides at each knot on the nodes seen so far; a knot's best place and
// whether an element pays for itself show only once the nodes after it are
// in, which this pass sees whole.
#include "design_dp.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace railodd::geometry::fit {

namespace {

double min_length(ElementKind k, const DesignDpOptions& o) {
    return k == ElementKind::line ? o.min_line_m : k == ElementKind::arc ? o.min_arc_m : o.min_transition_m;
}

// The design rules of the search (design_dp.cpp, successors) and its minimum
// lengths (the last element may end short: the chain ends where it ends).
bool valid(const std::vector<FrameElement>& st, const DesignDpOptions& o) {
    for (std::size_t j = 0; j < st.size(); ++j) {
        const double len = st[j].s1 - st[j].s0;
        if (!(len > 0.0) || (j + 1 < st.size() && len < min_length(st[j].kind, o) - 1e-9)) {
            return false;
        }
        if (j > 0 && st[j - 1].kind != ElementKind::transition && st[j].kind != ElementKind::transition) {
            return false;
        }
    }
    return true;
}

// Priors on the solved design that no quadratic can state: a transition's
// length against the one its curvature change calls for, and a curvature
// sign change inside one transition counted as the knot at zero it hides.
double design_prior(const FrameDesign& d, const DesignDpOptions& o) {
    double c = 0.0;
    for (const FrameElement& e : d.elements) {
        if (e.kind != ElementKind::transition) {
            continue;
        }
        const double dk = std::abs(e.k1 - e.k0);
        if (e.k0 * e.k1 < 0.0 && std::min(std::abs(e.k0), std::abs(e.k1)) > 1e-5) {
            c += o.parameter_penalty;
        }
        if (o.transition_prior > 0.0 && dk > 1e-5 && &e != &d.elements.front() && &e != &d.elements.back()) {
            const double r = std::log((e.s1 - e.s0) / transition_length_for(dk));
            c += o.transition_prior * r * r;
        }
    }
    return c;
}

class Refiner {
public:
    Refiner(const std::vector<FrameNode>& n, const DesignDpOptions& o) : n_(n), o_(o) {}

    double cost(const std::vector<FrameElement>& st) const {
        if (!valid(st, o_)) {
            return std::numeric_limits<double>::infinity();
        }
        const FrameDesign d = solve_structure(n_, st, o_);
        return d.cost + design_prior(d, o_);
    }

    // Tries `st`; keeps it in `best` where it costs less.
    bool offer(std::vector<FrameElement> st, std::vector<FrameElement>& best, double& best_cost) const {
        const double c = cost(st);
        if (c < best_cost - 1e-9) {
            best = std::move(st);
            best_cost = c;
            return true;
        }
        return false;
    }

    bool move_knots(std::vector<FrameElement>& st, double& c) const {
        bool improved = false;
        const double h = o_.knot_step_m;
        for (std::size_t j = 1; j < st.size(); ++j) {
            std::vector<FrameElement> best = st;
            for (const double d : {-2 * h, -h, -0.5 * h, 0.5 * h, h, 2 * h}) {
                std::vector<FrameElement> t = st;
                t[j - 1].s1 += d;
                t[j].s0 += d;
                offer(std::move(t), best, c);
            }
            improved |= best[j].s0 != st[j].s0;
            st = std::move(best);
        }
        return improved;
    }

    bool merge_elements(std::vector<FrameElement>& st, double& c) const {
        bool improved = false;
        for (std::size_t j = 0; j + 1 < st.size(); ++j) {
            std::vector<FrameElement> best = st;
            // The knot between j and j + 1 dropped, either kind kept.
            for (int keep = 0; keep < 2; ++keep) {
                std::vector<FrameElement> t = st;
                t[j].s1 = t[j + 1].s1;
                if (keep == 1) {
                    t[j].kind = t[j + 1].kind;
                }
                t.erase(t.begin() + static_cast<std::ptrdiff_t>(j) + 1);
                offer(std::move(t), best, c);
            }
            // Element j + 1 dropped between its neighbours.
            if (j + 2 < st.size()) {
                std::vector<FrameElement> t = st;
                const double mid = 0.5 * (t[j + 1].s0 + t[j + 1].s1);
                t[j].s1 = mid;
                t[j + 2].s0 = mid;
                t.erase(t.begin() + static_cast<std::ptrdiff_t>(j) + 1);
                offer(std::move(t), best, c);
            }
            if (best.size() != st.size()) {
                improved = true;
                st = std::move(best);
            }
        }
        return improved;
    }

    bool split_elements(std::vector<FrameElement>& st, double& c) const {
        bool improved = false;
        constexpr ElementKind kinds[3] = {ElementKind::line, ElementKind::transition, ElementKind::arc};
        for (std::size_t j = 0; j < st.size(); ++j) {
            std::vector<FrameElement> best = st;
            const FrameElement e = st[j];
            for (const double f : {1.0 / 3.0, 0.5, 2.0 / 3.0}) {
                const double at = e.s0 + f * (e.s1 - e.s0);
                for (const ElementKind a : kinds) {
                    for (const ElementKind b : kinds) {
                        std::vector<FrameElement> t = st;
                        t[j] = {a, e.s0, at, 0.0, 0.0};
                        t.insert(t.begin() + static_cast<std::ptrdiff_t>(j) + 1, FrameElement{b, at, e.s1, 0.0, 0.0});
                        offer(std::move(t), best, c);
                    }
                }
            }
            // A transition through zero as two meeting a line between them.
            if (e.kind == ElementKind::transition) {
                const double a = e.s0 + (e.s1 - e.s0) / 3.0, b = e.s0 + 2.0 * (e.s1 - e.s0) / 3.0;
                std::vector<FrameElement> t = st;
                t[j].s1 = a;
                t.insert(t.begin() + static_cast<std::ptrdiff_t>(j) + 1,
                         {FrameElement{ElementKind::line, a, b, 0.0, 0.0}, FrameElement{ElementKind::transition, b, e.s1, 0.0, 0.0}});
                offer(std::move(t), best, c);
            }
            if (best.size() != st.size()) {
                improved = true;
                st = std::move(best);
                ++j;
            }
        }
        return improved;
    }

private:
    const std::vector<FrameNode>& n_;
    const DesignDpOptions& o_;
};

} // namespace

FrameDesign refine_structure(const std::vector<FrameNode>& nodes, const FrameDesign& design,
                             const DesignDpOptions& o) {
    const Refiner r(nodes, o);
    std::vector<FrameElement> st = design.elements;
    double c = r.cost(st);
    for (int round = 0; round < 6; ++round) {
        const bool merged = r.merge_elements(st, c);
        const bool split = r.split_elements(st, c);
        const bool moved = r.move_knots(st, c);
        if (!merged && !split && !moved) {
            break;
        }
    }
    return solve_structure(nodes, st, o);
}

} // namespace railodd::geometry::fit
