// The design search again over one span of a design, tied to the design
// around it (design_dp.hpp research_span), and over every run of a few
// elements in turn (research_windows): a large-neighbourhood search after
// the beam. The beam decides each knot among rivals from the whole chain
// so far; over a span tied at both ends it compares only the structures
// that differ there, and the refine's single moves cannot reach one several
// elements deep.
#include "design_dp.hpp"
#include "design_local.hpp"

#include "design_rules.hpp"

#include <algorithm>
#include <cmath>

namespace railodd::geometry::fit {

namespace {

// Elements per window and windows half a window apart: every knot inside
// two windows. Measured on the truth bench (100 routes, no outliers,
// elements / design p95 at 0.1 and 0.3 m): OSM-like 1.15 / 1.10 -> 1.09 /
// 1.04, dense 1.17 / 1.12 -> 1.13 / 1.05, fit time 1.5x.
constexpr std::size_t window_elements = 5;

// Histories each new element in a window may follow (3 in the whole
// search). Against a tied end the beam at 3 ended a window up to 400 above
// the span's best (OSM-like truth seed 1041 at 2 m); at 8 the fit takes
// 1.15x as long. At 8 a sparse tied route kept a stray followed (seed 1422
// at 0.1 m, 9.0 m off): the true structure with the stray left out costs
// 294-305, the span's search found 319.
constexpr std::size_t window_spawn = 10;

// The end of the window from element j: window_elements on, and further to
// where the curvature is zero, as at a curve's end, for up to as many
// again. A span's ends are tied to the design's state, curvature too: a
// window that ends inside a wrong curve is held to it (OSM-like truth seed
// 1096 at 0.3 m: a broken-back curve, two arcs with a dip to straight
// between, six elements from line to line, 26 dearer than one arc).
std::size_t window_end(const std::vector<FrameElement>& el, std::size_t j) {
    std::size_t k = std::min(el.size(), j + window_elements);
    while (k < el.size() && k < j + 2 * window_elements && el[k - 1].k1 != 0.0) {
        ++k;
    }
    return k;
}

} // namespace

FrameDesign research_span(const std::vector<FrameNode>& nodes, const FrameDesign& design, const DesignDpOptions& o,
                          double lo, double hi) {
    DesignDpOptions w = o;
    w.knots.clear();        // the grid's, where nodes came
    w.spawn = window_spawn;
    for (const FrameElement& e : design.elements) {
        if (lo > o.s0 && e.s0 < lo) {
            w.before = e.kind;
        }
        if (hi < o.s1 && e.s1 > hi && !w.after) {
            w.after = e.kind;
        }
    }
    if (w.before) {
        w.start = design_state(design, lo);
    }
    if (w.after) {
        w.end = design_state(design, hi);
    }
    w.s0 = lo;
    w.s1 = hi;
    std::vector<FrameNode> inside;
    for (const FrameNode& n : nodes) {
        if (n.t >= lo && n.t <= hi) {
            inside.push_back(n);
        }
    }
    if (inside.empty() || !(hi > lo + 1.0)) {
        // Nodes out of chainage order (a chain doubling back) can leave the
        // span empty: no search there.
        return refine_structure(nodes, design.elements, o, {lo, hi});
    }
    const FrameDesign local = design_dp(inside, w);
    std::vector<FrameElement> st;
    // A line or an arc the span's first or last element goes on with is one element.
    const auto append = [&st](const FrameElement& e) {
        if (!st.empty() && design::continues(st.back().kind, e.kind)) {
            st.back().s1 = e.s1;
        } else {
            st.push_back(e);
        }
    };
    for (FrameElement e : design.elements) {
        if (e.s0 < lo) {
            e.s1 = std::min(e.s1, lo);
            append(e);
        }
    }
    for (const FrameElement& e : local.elements) {
        append(e);
    }
    for (FrameElement e : design.elements) {
        if (e.s1 > hi) {
            e.s0 = std::max(e.s0, hi);
            append(e);
        }
    }
    for (std::size_t j = 1; j < st.size(); ++j) {
        if (!design::may_follow(st[j - 1].kind, st[j].kind)) {
            return refine_structure(nodes, design.elements, o, {lo, hi});
        }
    }
    // The refine reaches a span's length beyond it each way: far enough for
    // the elements the new ones push against, and a long chain's refine
    // stays local (a whole-chain refine per node trial made Cologne's fit
    // run for over ten minutes).
    const double reach = hi - lo;
    return refine_structure(nodes, st, o, {lo - reach, hi + reach});
}

FrameDesign research_windows(const std::vector<FrameNode>& nodes, FrameDesign design, const DesignDpOptions& o) {
    double now = priced(design, o) + stray_cost(design, nodes);
    for (std::size_t j = 0; j + 1 < design.elements.size(); j += window_elements / 2) {
        const auto& el = design.elements;
        const std::size_t k = window_end(el, j);
        FrameDesign d = research_span(nodes, design, o, el[j].s0, el[k - 1].s1);
        const double cost = priced(d, o) + stray_cost(d, nodes);
        if (cost < now - 1e-6 * (1.0 + std::abs(now))) {
            design = std::move(d);
            now = cost;
        }
    }
    return design;
}

} // namespace railodd::geometry::fit
