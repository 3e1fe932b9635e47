#include "design_local.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace railodd::geometry::fit {

namespace {

using design::Quad;
using design::S;
using design::Vec4;

constexpr double infinite = std::numeric_limits<double>::infinity();

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

double element_prior(const FrameElement& e, bool chain_end, const DesignDpOptions& o) {
    // No track curves tighter than a tram's 15 m: a hook that tight is a
    // stray node fitted (near a free chain end, where nothing holds it).
    constexpr double max_curvature = 1.0 / 15.0;
    if (std::max(std::abs(e.k0), std::abs(e.k1)) > max_curvature) {
        return 1e6;
    }
    if (e.kind != ElementKind::transition) {
        return 0.0;
    }
    double c = 0.0;
    if (e.k0 * e.k1 < 0.0 && std::min(std::abs(e.k0), std::abs(e.k1)) > 1e-5) {
        c += o.parameter_penalty;
    }
    const double dk = std::abs(e.k1 - e.k0);
    if (o.transition_prior > 0.0 && dk > 1e-5 && !chain_end) {
        const double r = std::log((e.s1 - e.s0) / transition_length_for(dk));
        c += o.transition_prior * r * r;
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
}

void StructureCosts::reset(const std::vector<FrameElement>& st) {
    st_ = st;
    const std::size_t m = st.size();
    ForwardPass forward = forward_pass(n_, st, o_);
    cost_ = forward.cost;
    const FrameDesign d = solved(st, forward);
    forward_ = std::move(forward.knots);
    std::vector<FrameElement> ms;
    for (std::size_t i = 0; i < m; ++i) {
        const FrameElement& e = st[m - 1 - i];
        ms.push_back({e.kind, -e.s1, -e.s0, 0.0, 0.0});
    }
    const std::vector<Quad> mk = forward_pass(mirrored_, ms, mirror_options_).knots;
    backward_.assign(m + 1, Quad{});
    for (std::size_t k = 1; k < m; ++k) {
        backward_[k] = mirror(mk[m - k]);
    }
    prior_.assign(m, 0.0);
    prior_total_ = 0.0;
    for (std::size_t j = 0; j < m; ++j) {
        prior_[j] = element_prior(d.elements[j], j == 0 || j + 1 == m, o_);
        prior_total_ += prior_[j];
    }
}

bool StructureCosts::allowed(std::size_t j, std::size_t k, const std::vector<FrameElement>& w) const {
    const std::size_t m = st_.size();
    for (std::size_t i = 0; i < w.size(); ++i) {
        const double len = w[i].s1 - w[i].s0;
        const bool chain_last = k == m && i + 1 == w.size();
        if (!(len > 0.0) || (!chain_last && len < design::min_length(w[i].kind, o_) - 1e-9)) {
            return false;
        }
        const bool has_prev = i > 0 || j > 0;
        const ElementKind prev = i > 0 ? w[i - 1].kind : (j > 0 ? st_[j - 1].kind : ElementKind::line);
        if (has_prev && !design::may_follow(prev, w[i].kind)) {
            return false;
        }
    }
    return k == m || design::may_follow(w.back().kind, st_[k].kind);
}

double StructureCosts::replaced(std::size_t j, std::size_t k, const std::vector<FrameElement>& w) const {
    if (w.empty() || !allowed(j, k, w)) {
        return infinite;
    }
    const std::size_t m = st_.size();
    const auto by_t = [](double v, const FrameNode& a) { return v < a.t; };
    const std::size_t next = j == 0 ? 0 : static_cast<std::size_t>(std::upper_bound(n_.begin(), n_.end(), st_[j - 1].s1, by_t) - n_.begin());
    const std::size_t end = k == m ? n_.size() : static_cast<std::size_t>(std::upper_bound(n_.begin(), n_.end(), st_[k - 1].s1, by_t) - n_.begin());
    Quad f;
    if (j == 0) {
        f = design::first_element(w[0].kind, o_);
    } else {
        f = forward_[j];
        const bool after_transition = st_[j - 1].kind == ElementKind::transition && w[0].kind == ElementKind::transition;
        if (!design::open_element(f, w[0].kind, after_transition)) {
            return infinite;
        }
    }
    std::vector<design::KnotMap> maps(w.size());
    if (!walk(f, w, n_, next, end, o_, j == 0 && !o_.start, k == m && !o_.end, &maps, nullptr)) {
        return infinite;
    }
    const double u = (w.back().s1 - w.back().s0) / S;
    Vec4 x;
    double cost = 0.0;
    if (k == m) {
        cost = design::close_chain(f, u, o_, &x);
    } else {
        Quad g = design::to_knot(f, u, &maps.back());
        if (st_[k].kind == ElementKind::transition && w.back().kind == ElementKind::transition) {
            design::fix_zero(g, 2);
        }
        if (st_[k].kind == ElementKind::arc && !(g.free & 4u)) {
            return infinite;
        }
        design::add_quad(g, backward_[k]);
        Vec4 y;
        cost = design::minimum(g, &y);
        y(3) = 0.0;
        x = design::start_from_knot(maps.back(), y);
    }
    return cost + window_prior(j, k, w, maps, x);
}

// The priors with the window's elements as solved here (backtracked from the
// last one's start state x) in place of the old ones; those outside keep
// their last full solve's values.
double StructureCosts::window_prior(std::size_t j, std::size_t k, const std::vector<FrameElement>& w,
                                    const std::vector<design::KnotMap>& maps, Vec4 x) const {
    double prior = prior_total_;
    for (std::size_t i = j; i < k; ++i) {
        prior -= prior_[i];
    }
    const std::size_t m = st_.size();
    for (std::size_t i = w.size(); i-- > 0;) {
        const double u = (w[i].s1 - w[i].s0) / S;
        FrameElement e = w[i];
        e.k0 = x(2) / (S * S);
        e.k1 = (x(2) + x(3) * u) / (S * S);
        prior += element_prior(e, (j == 0 && i == 0) || (k == m && i + 1 == w.size()), o_);
        if (i > 0) {
            Vec4 y = x;
            y(3) = 0.0;
            x = design::start_from_knot(maps[i - 1], y);
        }
    }
    return prior;
}

} // namespace railodd::geometry::fit
