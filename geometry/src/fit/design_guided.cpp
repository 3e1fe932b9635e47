// A parallel track's structure as a rival (issue 37 item 7): where a chain
// runs beside a track fitted before it, its design over each of the guide's
// curves is replaced by the guide's elements at the guide's knots, and kept
// where that costs less (the same objective, the guide's prior in it) and
// moves no node far off. The prior (design_guide.hpp) pulls the curvature,
// but the search places the knots from this chain's nodes alone, and on
// sparse nodes they fall where the transition-length prior puts them, not
// across from the neighbour's (VDE 8.2: transitions side by side 0.33-2.6x
// each other's length at p10-p90), and the curves disagree along the
// transitions. Few rivals are taken (VDE 8.2: 10 of 704 over all passes;
// most cost more, the two tracks' nodes placing their transitions apart),
// but a knot taken is held in the polish (design_polish.cpp hold_shared_knots).
#include "design_guide.hpp"

#include "design_rules.hpp"

#include <algorithm>
#include <cmath>
#include <optional>

namespace railodd::geometry::fit {

namespace {

using Joint = GuideCurvature::Joint;

// A rival leaves no node further off than this (in sigmas), or than the
// design does: where the neighbour's own fit strays a metre from its nodes,
// its curve copied strays from this track's, and the prior in the cost
// pays for it (truth routes, sparse beside OSM-like: a guided fit's nodes
// 1.2 m off at p95, its own 0.3 m).
constexpr double max_guided_z = 3.0;

// The index of the element of `el` that holds chainage t.
std::size_t holding(const std::vector<FrameElement>& el, double t) {
    const auto it = std::upper_bound(el.begin(), el.end(), t, [](double x, const FrameElement& e) { return x < e.s1; });
    return std::min<std::size_t>(static_cast<std::size_t>(it - el.begin()), el.size() - 1);
}

// Whether the guide's elements between joints i and k follow the design
// rules and are long enough.
bool valid_between(const std::vector<Joint>& j, std::size_t i, std::size_t k, const DesignDpOptions& o) {
    for (std::size_t q = i; q < k; ++q) {
        if (j[q].after != j[q + 1].before || (q + 1 < k && !design::may_follow(j[q + 1].before, j[q + 1].after)) ||
            j[q + 1].t - j[q].t < design::min_length(j[q].after, o)) {
            return false;
        }
    }
    return true;
}

// The design's elements up to joint `a` (continued by the guide's first
// element where the kinds are one line or one arc, else cut there), the
// guide's elements from a to b, then the design's from b on. Nothing where
// the kinds break a design rule or a cut leaves an element too short.
std::optional<std::vector<FrameElement>> spliced(const std::vector<FrameElement>& el, const Joint& a, const Joint& b,
                                                 const std::vector<Joint>& inner, const DesignDpOptions& o) {
    const std::size_t e = holding(el, a.t), f = holding(el, b.t);
    if (f < e) {
        return std::nullopt;
    }
    std::vector<FrameElement> out(el.begin(), el.begin() + static_cast<std::ptrdiff_t>(e));
    FrameElement head = el[e];
    if (design::continues(head.kind, a.after)) {
        head.s1 = inner.empty() ? b.t : inner.front().t;
    } else if (design::may_follow(head.kind, a.after) && a.t - head.s0 >= design::min_length(head.kind, o)) {
        head.s1 = a.t;
        out.push_back(head);
        head = {a.after, a.t, inner.empty() ? b.t : inner.front().t, 0.0, 0.0};
    } else {
        return std::nullopt;
    }
    out.push_back(head);
    for (std::size_t q = 0; q < inner.size(); ++q) {
        out.push_back({inner[q].after, inner[q].t, q + 1 < inner.size() ? inner[q + 1].t : b.t, 0.0, 0.0});
    }
    FrameElement tail = el[f];
    if (design::continues(tail.kind, b.before)) {
        out.back().s1 = tail.s1;
    } else if (design::may_follow(b.before, tail.kind) && tail.s1 - b.t >= design::min_length(tail.kind, o)) {
        tail.s0 = b.t;
        out.push_back(tail);
    } else {
        return std::nullopt;
    }
    out.insert(out.end(), el.begin() + static_cast<std::ptrdiff_t>(f) + 1, el.end());
    return out;
}

// The rivals for one run: each of the guide's curves in it, line to line,
// on its own (the tracks' nodes may agree on one curve and not the next);
// where it has none, from its first joint where the design can meet the
// guide's structure to its last.
std::vector<std::pair<std::size_t, std::size_t>> rival_spans(const std::vector<Joint>& j) {
    std::vector<std::pair<std::size_t, std::size_t>> spans;
    for (std::size_t i = 0; i < j.size(); ++i) {
        if (j[i].before != ElementKind::line) {
            continue;
        }
        for (std::size_t k = i + 1; k < j.size(); ++k) {
            if (j[k].after == ElementKind::line) {
                spans.push_back({i, k});
                i = k - 1;
                break;
            }
        }
    }
    return spans;
}

std::optional<std::vector<FrameElement>> rival(const std::vector<FrameElement>& el, const std::vector<Joint>& j,
                                               std::size_t i, std::size_t k, const DesignDpOptions& o) {
    if (!valid_between(j, i, k, o)) {
        return std::nullopt;
    }
    const std::vector<Joint> inner(j.begin() + static_cast<std::ptrdiff_t>(i) + 1, j.begin() + static_cast<std::ptrdiff_t>(k));
    return spliced(el, j[i], j[k], inner, o);
}

std::optional<std::vector<FrameElement>> widest_rival(const std::vector<FrameElement>& el, const std::vector<Joint>& j,
                                                      const DesignDpOptions& o) {
    for (std::size_t i = 0; i < j.size(); ++i) {
        for (std::size_t k = j.size(); k-- > i + 1;) {
            if (auto st = rival(el, j, i, k, o)) {
                return st;
            }
        }
    }
    return std::nullopt;
}

// The largest of the nodes' weighted residuals (in sigmas).
double worst(const FrameDesign& d, const std::vector<FrameNode>& nodes) {
    const std::vector<double> r = frame_residuals(d, nodes);
    double m = 0.0;
    for (std::size_t i = 0; i < nodes.size(); ++i) {
        m = std::max(m, std::abs(r[i]) * std::sqrt(nodes[i].w));
    }
    return m;
}

} // namespace

FrameDesign take_guided_runs(const std::vector<FrameNode>& nodes, FrameDesign design, const DesignDpOptions& o) {
    if (!o.guide || design.elements.empty()) {
        return design;
    }
    double design_worst = worst(design, nodes);
    const auto try_rival = [&](const std::optional<std::vector<FrameElement>>& st) {
        if (!st) {
            return;
        }
        FrameDesign d = solve_structure(nodes, *st, o);
        if (!(d.cost < design.cost)) {
            return;
        }
        const double d_worst = worst(d, nodes);
        if (d_worst <= std::max(design_worst, max_guided_z)) {
            design = std::move(d);
            design_worst = d_worst;
        }
    };
    const std::vector<Joint>& all = o.guide->joints();
    for (std::size_t i = 0; i < all.size();) {
        std::size_t k = i;
        while (k < all.size() && all[k].run == all[i].run) {
            ++k;
        }
        const std::vector<Joint> run(all.begin() + static_cast<std::ptrdiff_t>(i), all.begin() + static_cast<std::ptrdiff_t>(k));
        i = k;
        const auto spans = rival_spans(run);
        for (const auto& [a, b] : spans) {
            try_rival(rival(design.elements, run, a, b, o));
        }
        if (spans.empty() && run.size() >= 2) {
            try_rival(widest_rival(design.elements, run, o));
        }
    }
    return design;
}

} // namespace railodd::geometry::fit
