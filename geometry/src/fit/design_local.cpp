#include "design_local.hpp"

#include "design_guide.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>

namespace railodd::geometry::fit {

namespace {

using design::Quad;
using design::S;
using design::Vec4;

constexpr double infinite = std::numeric_limits<double>::infinity();
// The most elements the local search puts in one window (design_refine.cpp).
constexpr std::size_t max_window = 3;

FrameState mirror(const FrameState& s) { return {s.z, -s.dz, s.k}; }

// The same cost seen along the chain the other way: heading and curvature
// slope change sign.
Quad mirror(Quad q) {
    constexpr double d[4] = {1.0, -1.0, 1.0, -1.0};
    for (int i = 0; i < 4; ++i) {
        q.q(i) *= d[i];
        for (int j = 0; j < 4; ++j) {
            q.P(i, j) *= d[i] * d[j];
        }
    }
    return q;
}

} // namespace

double element_prior(const FrameElement& e, bool first, bool last, const DesignDpOptions& o) {
    // No track curves tighter than a tram's 15 m: a hook that tight is a
    // stray node fitted (near a free chain end, where nothing holds it).
    constexpr double max_curvature = 1.0 / 15.0;
    if (std::max(std::abs(e.k0), std::abs(e.k1)) > max_curvature) {
        return 1e6;
    }
    if (e.kind != ElementKind::transition) {
        return 0.0;
    }
    // At a switch (a chain's tie, not a span's inside it) the branch starts
    // with its through track's curvature, whichever way its own curve
    // turns: a sign change in its first transition hides no knot.
    const bool tied = (first && o.start) || (last && o.end);
    const bool at_switch = (first && o.start && !o.before) || (last && o.end && !o.after);
    double c = 0.0;
    if (!at_switch && e.k0 * e.k1 < 0.0 && std::min(std::abs(e.k0), std::abs(e.k1)) > 1e-5) {
        c += o.parameter_penalty;
    }
    const double dk = std::abs(e.k1 - e.k0);
    if (o.transition_prior > 0.0 && dk > 1e-5) {
        const double r = std::log((e.s1 - e.s0) / transition_length_for(dk));
        // A chain cut inside a transition keeps a piece of it, never more: at
        // a free end only a transition longer than the rule pays. Without,
        // a free end swung on a long S-shaped transition across a gap
        // between nodes (sparse truth seed 1124 at 0.1 m: 470 m from 1/890 m
        // one way to 1/866 m the other, 5.0 m off; 150 sparse routes at
        // 0.1 m, 15 -> 6 beyond the limit). At a switch none pays: the rule
        // is short for a fast line's transitions (VDE 8.2 with it: 16.2
        // elements per km against 9.6).
        const bool inside = !first && !last;
        c += inside || (!tied && r > 0.0) ? o.transition_prior * r * r : 0.0;
    }
    return c;
}

double priced(const FrameDesign& d, const DesignDpOptions& o) {
    double c = d.cost;
    for (std::size_t j = 0; j < d.elements.size(); ++j) {
        c += element_prior(d.elements[j], j == 0, j + 1 == d.elements.size(), o);
    }
    return c;
}

StructureCosts::StructureCosts(const std::vector<FrameNode>& nodes, const DesignDpOptions& o) : n_(nodes), o_(o) {
    for (auto it = nodes.rbegin(); it != nodes.rend(); ++it) {
        mirrored_.push_back({-it->t, it->z, it->w});
    }
    mirror_options_ = o;
    mirror_options_.s0 = -o.s1;
    mirror_options_.s1 = -o.s0;
    mirror_options_.start = o.end ? std::optional<FrameState>(mirror(*o.end)) : std::nullopt;
    mirror_options_.end = o.start ? std::optional<FrameState>(mirror(*o.start)) : std::nullopt;
    mirror_options_.before = o.after;
    mirror_options_.after = o.before;
    if (o.guide) {
        mirror_options_.guide = o.guide->mirrored();
    }
}

void StructureCosts::reset(const std::vector<FrameElement>& st) {
    st_ = st;
    const std::size_t m = st.size();
    ForwardPass forward = forward_pass(n_, st, o_);
    cost_ = forward.cost;
    const FrameDesign d = solved(st, forward);
    forward_ = std::move(forward.knots);
    forward_valid_ = m - 1;
    std::vector<FrameElement> ms;
    for (std::size_t i = 0; i < m; ++i) {
        const FrameElement& e = st[m - 1 - i];
        ms.push_back({e.kind, -e.s1, -e.s0, 0.0, 0.0});
    }
    const std::vector<Quad> mk = forward_pass(mirrored_, ms, mirror_options_, true).knots;
    from_end_.assign(m + 1, Quad{});
    for (std::size_t r = 1; r < m; ++r) {
        from_end_[r] = mirror(mk[r]);
    }
    from_end_valid_ = m;
    prior_.assign(m, 0.0);
    prior_total_ = 0.0;
    for (std::size_t j = 0; j < m; ++j) {
        prior_[j] = element_prior(d.elements[j], j == 0, j + 1 == m, o_);
        prior_total_ += prior_[j];
    }
}

bool StructureCosts::allowed(std::size_t j, std::size_t k, std::span<const FrameElement> w) const {
    const std::size_t m = st_.size();
    for (std::size_t i = 0; i < w.size(); ++i) {
        const double len = w[i].s1 - w[i].s0;
        const bool chain_last = k == m && i + 1 == w.size();
        if (!(len > 0.0) || (!chain_last && len < design::min_length(w[i].kind, o_) - 1e-9)) {
            return false;
        }
        if (i == 0 && j == 0 && o_.before && !design::may_adjoin(*o_.before, w[i].kind)) {
            return false;
        }
        const bool has_prev = i > 0 || j > 0;
        const ElementKind prev = i > 0 ? w[i - 1].kind : (j > 0 ? st_[j - 1].kind : ElementKind::line);
        if (has_prev && !design::may_follow(prev, w[i].kind)) {
            return false;
        }
    }
    if (k == m) {
        return !o_.after || design::may_adjoin(*o_.after, w.back().kind);
    }
    return design::may_follow(w.back().kind, st_[k].kind);
}

std::size_t StructureCosts::nodes_after(double s) const {
    const auto by_t = [](double v, const FrameNode& a) { return v < a.t; };
    return static_cast<std::size_t>(std::upper_bound(n_.begin(), n_.end(), s, by_t) - n_.begin());
}

bool StructureCosts::open_at(std::size_t j, ElementKind kind, Quad& f) const {
    if (j == 0) {
        f = design::first_element(kind, o_);
        return true;
    }
    f = forward_[j];
    return design::open_element(f, kind, st_[j - 1].kind == ElementKind::transition && kind == ElementKind::transition);
}

double StructureCosts::window(std::size_t j, std::size_t k, std::span<const FrameElement> w, Update* update,
                              double bound) const {
    if (w.empty() || !allowed(j, k, w)) {
                return infinite;
    }
    const std::size_t m = st_.size();
    const std::size_t next = j == 0 ? 0 : nodes_after(st_[j - 1].s1);
    const std::size_t end = k == m ? n_.size() : nodes_after(st_[k - 1].s1);
    Quad f;
    if (!open_at(j, w[0].kind, f)) {
        return infinite;
    }
    // On the stack: the local search tries tens of millions of windows.
    std::array<design::KnotMap, max_window> on_stack;
    std::vector<design::KnotMap> on_heap;
    design::KnotMap* maps = on_stack.data();
    if (w.size() > max_window) {
        on_heap.resize(w.size());
        maps = on_heap.data();
    }
    Quad* knots = nullptr;
    if (update) {
        update->knots.assign(w.size() + 1, Quad{});
        knots = update->knots.data();
    }
    if (!walk(f, w, n_, next, end, o_, j == 0, k == m && !o_.end, maps, knots)) {
        return infinite;
    }
    const double u = (w.back().s1 - w.back().s0) / S;
    Vec4 x, y;
    double cost = 0.0;
    if (k == m) {
        cost = design::close_chain(f, u, w.back().kind, o_, &x);
    } else {
        Quad g = design::to_knot(f, u, &maps[w.size() - 1]);
        if (update) {
            update->knots.back() = g;
        }
        if (st_[k].kind == ElementKind::transition && w.back().kind == ElementKind::transition) {
            design::fix_zero(g, 2);
        }
        if (st_[k].kind == ElementKind::arc && !(g.free & 4u)) {
            return infinite;
        }
        design::add_quad(g, backward(k));
        cost = design::minimum(g, &y);
    }
    // The new elements' priors only add.
    const double outside = outside_prior(j, k);
        if (cost + outside >= bound) {
                return cost + outside;
    }
    if (k < m) {
        y(3) = 0.0;
        x = design::start_from_knot(maps[w.size() - 1], y);
    }
    return cost + window_prior(j, k, w, maps, x, outside, update ? &update->priors : nullptr);
}

void StructureCosts::replace(std::size_t j, std::size_t k, std::span<const FrameElement> w) {
    Update up;
    const double total = window(j, k, w, &up);
    const auto at = [](std::size_t i) { return static_cast<std::ptrdiff_t>(i); };
    const std::size_t n = w.size();
    st_.erase(st_.begin() + at(j), st_.begin() + at(k));
    st_.insert(st_.begin() + at(j), w.begin(), w.end());
    prior_.erase(prior_.begin() + at(j), prior_.begin() + at(k));
    prior_.insert(prior_.begin() + at(j), up.priors.begin(), up.priors.end());
    // Knot i's costs: forward_ up to the window's last inner knot, the
    // costs after it from its end on (from_end_ up to the old end's k).
    const std::size_t kept_from_end = from_end_.size() - 1 - k;
    forward_.resize(st_.size() + 1);
    forward_valid_ = j;
    for (std::size_t i = 1; i <= n && j + i < st_.size(); ++i) {
        forward_[j + i] = up.knots[i];
        forward_valid_ = j + i;
    }
    from_end_.resize(st_.size() + 1);
    from_end_valid_ = kept_from_end;
    prior_total_ = 0.0;
    for (const double p : prior_) {
        prior_total_ += p;
    }
    cost_ = total - prior_total_;
}

void StructureCosts::valid_up_to(std::size_t j) {
    while (forward_valid_ < j && forward_valid_ + 1 < st_.size()) {
        const std::size_t v = forward_valid_;
        const std::span<const FrameElement> w(&st_[v], 1);
        Quad f;
        open_at(v, w[0].kind, f);
        walk(f, w, n_, v == 0 ? 0 : nodes_after(st_[v - 1].s1), nodes_after(st_[v].s1), o_, v == 0, false,
             nullptr, nullptr);
        forward_[v + 1] = design::to_knot(f, (w[0].s1 - w[0].s0) / S);
        ++forward_valid_;
    }
}

double StructureCosts::outside_prior(std::size_t j, std::size_t k) const {
    double prior = prior_total_;
    for (std::size_t i = j; i < k; ++i) {
        prior -= prior_[i];
    }
    return prior;
}

// The priors with the window's elements as solved here (backtracked from the
// last one's start state x) added to those outside it (`outside`, their
// last full solve's values).
double StructureCosts::window_prior(std::size_t j, std::size_t k, std::span<const FrameElement> w,
                                    const design::KnotMap* maps, Vec4 x, double outside,
                                    std::vector<double>* priors) const {
    double prior = outside;
    const std::size_t m = st_.size();
    if (priors) {
        priors->assign(w.size(), 0.0);
    }
    for (std::size_t i = w.size(); i-- > 0;) {
        const double u = (w[i].s1 - w[i].s0) / S;
        FrameElement e = w[i];
        e.k0 = x(2) / (S * S);
        e.k1 = (x(2) + x(3) * u) / (S * S);
        const double p = element_prior(e, j == 0 && i == 0, k == m && i + 1 == w.size(), o_);
        prior += p;
        if (priors) {
            (*priors)[i] = p;
        }
        if (i > 0) {
            Vec4 y = x;
            y(3) = 0.0;
            x = design::start_from_knot(maps[i - 1], y);
        }
    }
    return prior;
}

} // namespace railodd::geometry::fit
