// The design search: hypotheses advance knot by knot along the chain, each
// its cost as a quadratic in its current element's start state
// (design_quadratic.hpp); at every candidate knot the best few open the
// elements the design rules allow, and only the best hypotheses live on
// (a beam, with a PELT-like margin). The winner's structure is then solved
// exactly (solve_structure), which also recovers every knot's state.
#include "design_dp.hpp"

#include "design_guide.hpp"
#include "design_local.hpp"
#include "design_quadratic.hpp"
#include "design_rules.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <stdexcept>

namespace railodd::geometry::fit {

namespace {

using design::Quad;
using design::S;

struct Record {
    int parent = -1;
    double s = 0.0;
    ElementKind kind = ElementKind::line;
};

struct Hypothesis {
    Quad f;
    double start = 0.0;
    ElementKind kind = ElementKind::line;
    int record = 0;
    double value = 0.0;     // minimum of f: data, priors and penalties so far
    int seen = 0;           // nodes taken since the element opened
    double covered = 0.0;   // the curvature prior is in f up to this chainage
    design::Vec4 arg = design::Vec4::Zero(); // minimiser of f: the element's likeliest start state
};

// A hypothesis younger than this many nodes is kept whatever its cost: its
// curvature slope is not yet told by the data, and older rivals that fitted
// the noise a little would crowd it out before it could show its merit.
constexpr int fresh_nodes = 2;

class Search {
public:
    // priced: each element's priors (element_prior) added as it closes.
    Search(const std::vector<FrameNode>& nodes, const DesignDpOptions& o, bool priced)
        : n_(nodes), o_(o), priced_(priced) {}

    std::vector<FrameElement> run();

private:
    void seed();
    void cover(Hypothesis& h, double to) const;
    void advance(double to, std::size_t& next, bool knot);
    void spawn(double s);
    void keep_best();
    const std::vector<std::size_t>& by_value();
    std::vector<FrameElement> best_path(double s1);
    double prior(const Hypothesis& h, const design::Vec4& start, double s, bool last) const;

    const std::vector<FrameNode>& n_;
    const DesignDpOptions& o_;
    bool priced_ = false;
    std::vector<Record> records_;
    std::vector<Hypothesis> live_;
    // Buffers kept from knot to knot.
    std::vector<std::size_t> order_;
    std::vector<Hypothesis> spare_;
    std::array<std::vector<std::size_t>, 3> kept_of_kind_;
};

void Search::seed() {
    for (const ElementKind k : design::kinds) {
        if (o_.before && !design::may_adjoin(*o_.before, k)) {
            continue;
        }
        Hypothesis h;
        h.f = design::first_element(k, o_);
        h.f.c += design::first_penalty(k, o_, !o_.start);
        h.start = o_.s0;
        h.covered = o_.s0;
        h.kind = k;
        h.record = static_cast<int>(records_.size());
        records_.push_back({-1, o_.s0, k});
        live_.push_back(std::move(h));
    }
}

// The curvature prior and the guide's up to `to`.
void Search::cover(Hypothesis& h, double to) const {
    if (o_.curvature_weight > 0.0 && to > h.covered) {
        design::add_curvature(h.f, (h.covered - h.start) / S, (to - h.start) / S, o_.curvature_weight);
    }
    if (o_.guide && to > h.covered) {
        o_.guide->add(h.f, h.start, h.covered, to);
    }
    h.covered = std::max(h.covered, to);
}

// The priors of h's element closed at s from the start state `start`
// (scaled), where the search is priced.
double Search::prior(const Hypothesis& h, const design::Vec4& start, double s, bool last) const {
    if (!priced_) {
        return 0.0;
    }
    const double k0 = start(2) / (S * S);
    const double k1 = k0 + start(3) / (S * S * S) * (s - h.start);
    const bool first = records_[static_cast<std::size_t>(h.record)].parent < 0;
    return element_prior({h.kind, h.start, s, k0, k1}, first, last, o_);
}

// Every live hypothesis takes the nodes up to `to`.
void Search::advance(double to, std::size_t& next, bool knot) {
    const std::size_t first = next;
    while (next < n_.size() && n_[next].t <= to) {
        ++next;
    }
    for (Hypothesis& h : live_) {
        design::add_nodes(h.f, n_, first, next, h.start);
        h.seen += static_cast<int>(next - first);
        if (next > first || knot) {
            // The prior is brought up to date only where knots open: where
            // nodes came, and at the extra candidates.
            cover(h, to);
            h.value = design::minimum(h.f, &h.arg);
        }
    }
}

// The best child of each parent element (kind and start knot), the `spawn`
// best such, per kind of the new element: children of one family differ
// little in state, while another family's (a long transition against a
// short one after a line) may reach a curvature the next nodes call for even
// if it costs more now (CPOP keeps every cost that is least for some state;
// this keeps a few that differ).
struct Brood {
    struct Family {
        std::pair<ElementKind, double> key;
        int parent = 0;
        Hypothesis child;
    };
    std::vector<Family> best; // at most `spawn`, ascending by the child's value

    // What a child must cost less than to enter.
    double bar(std::size_t spawn) const {
        return best.size() < spawn ? std::numeric_limits<double>::infinity() : best.back().child.value;
    }

    void offer(std::pair<ElementKind, double> key, int parent, Hypothesis&& g, std::size_t spawn) {
        auto same = std::find_if(best.begin(), best.end(), [&](const Family& f) { return f.key == key; });
        if (same != best.end()) {
            if (g.value >= same->child.value) {
                return;
            }
            best.erase(same);
        } else if (g.value >= bar(spawn)) {
            return;
        }
        const auto at = std::upper_bound(best.begin(), best.end(), g.value,
                                         [](double v, const Family& f) { return v < f.child.value; });
        best.insert(at, Family{key, parent, std::move(g)});
        if (best.size() > spawn) {
            best.pop_back();
        }
    }
};

void Search::spawn(double s) {
    // Every child is built and valued exactly: a line or a second transition
    // must meet the knot at zero curvature, which the parent's own minimum
    // does not tell (ranking by it lost the way back to straight track). A
    // child costs at least its parent's minimum plus its penalty (it is the
    // parent's cost under constraints), so parents are taken in order of
    // value and a kind's children no longer built once that bound passes
    // the kind's bar: the same broods as building them all.
    const std::vector<std::size_t>& order = by_value();
    Brood brood[3];
    for (const std::size_t i : order) {
        const Hypothesis& h = live_[i];
        // The minima are rounded by about a millionth of their value.
        const double floor = h.value - 1e-4 * (1.0 + std::abs(h.value));
        const bool long_enough = s - h.start >= design::min_length(h.kind, o_) - 1e-9;
        // Its element's priors, which are never negative: the bound below
        // stays one without them.
        const double closed = long_enough ? prior(h, h.arg, s, false) : 0.0;
        bool open[3] = {false, false, false};
        for (const ElementKind kind : design::kinds) {
            const int k = static_cast<int>(kind);
            open[k] = design::may_follow(h.kind, kind) &&
                      floor + closed + design::element_penalty(kind, o_, false) < brood[k].bar(o_.spawn);
        }
        if (!open[0] && !open[1] && !open[2]) {
            if (floor + o_.parameter_penalty >= std::max({brood[0].bar(o_.spawn), brood[1].bar(o_.spawn), brood[2].bar(o_.spawn)})) {
                break;
            }
            continue;
        }
        if (!long_enough) {
            continue;
        }
        const Quad knot = design::to_knot(h.f, (s - h.start) / S);
        const Record& parent = records_[static_cast<std::size_t>(h.record)];
        for (const ElementKind kind : design::kinds) {
            Hypothesis g;
            g.f = knot;
            if (!open[static_cast<int>(kind)] ||
                !design::open_element(g.f, kind, h.kind == ElementKind::transition && kind == ElementKind::transition)) {
                continue;
            }
            g.f.c += design::element_penalty(kind, o_, false) + closed;
            g.start = s;
            g.covered = s;
            g.kind = kind;
            g.value = design::minimum(g.f, &g.arg);
            brood[static_cast<int>(kind)].offer({parent.kind, parent.s}, h.record, std::move(g), o_.spawn);
        }
    }
    for (Brood& b : brood) {
        for (Brood::Family& f : b.best) {
            f.child.record = static_cast<int>(records_.size());
            records_.push_back({f.parent, s, f.child.kind});
            live_.push_back(std::move(f.child));
        }
    }
}

// Whether `h`, no cheaper than `by`, is a near copy of it: by's cost at h's
// likeliest state is no more than h's own there. The future cost of a
// hypothesis depends only on its element's kind and its current state, so
// such a copy seldom wins later; left in the beam, copies (one transition
// opened at every knot of a gap) crowd out the rival structures the next
// nodes decide between (dense truth seed 1000 at 0.3 m: the true path
// dropped 1.2 above the best, 48 copies ahead of it).
bool near_copy(const Hypothesis& h, const Hypothesis& by) {
    if (h.kind != by.kind || h.f.free != by.f.free) {
        return false;
    }
    // h's likeliest state carried to by's start (design::flow(u) * h.arg,
    // written out: this runs for pairs of hypotheses at every knot), less
    // by's own, on by's variables. The flow over the distance between the
    // starts serves whatever chainage they are compared at.
    const double u = (by.start - h.start) / S;
    const design::Vec4& a = h.arg;
    double d[4] = {a(0) + u * (a(1) + u * (0.5 * a(2) + u * a(3) / 6.0)), a(1) + u * (a(2) + 0.5 * u * a(3)),
                   a(2) + u * a(3), a(3)};
    // On by's variables only: the other terms are exact zeros.
    int v[4], m = 0;
    for (int i = 0; i < 4; ++i) {
        if (by.f.free & (1u << i)) {
            d[i] -= by.arg(i);
            v[m++] = i;
        }
    }
    double cost = by.value;
    for (int a = 0; a < m; ++a) {
        for (int b = 0; b < m; ++b) {
            cost += d[v[a]] * by.f.P(v[a], v[b]) * d[v[b]];
        }
    }
    return cost <= h.value;
}

// The beam: the best hypotheses, none more than a margin above the best,
// near copies of a better one left out.
void Search::keep_best() {
    const std::vector<std::size_t>& order = by_value();
    const double margin = o_.prune_margin >= 0.0 ? o_.prune_margin : 4.0 * o_.parameter_penalty + 20.0;
    const double worst = live_[order.front()].value + margin;
    std::size_t old = 0;
    std::vector<std::pair<std::pair<ElementKind, double>, std::size_t>> per_knot;
    std::vector<Hypothesis>& kept = spare_;
    kept.clear();
    // Only a hypothesis of the same kind can be a near copy: the kept ones
    // by kind, so the test reads no others.
    std::array<std::vector<std::size_t>, 3>& of_kind = kept_of_kind_;
    for (std::vector<std::size_t>& v : of_kind) {
        v.clear();
    }
    for (const std::size_t i : order) {
        Hypothesis& h = live_[i];
        if (h.value > worst && !kept.empty()) {
            break;
        }
        const bool fresh = h.seen < fresh_nodes;
        if (!fresh && old >= o_.beam) {
            continue;
        }
        // Histories ending in the same element (kind and start) compete for
        // `spawn` places only: the optimal-partitioning recursion keeps the
        // best one per knot and kind. Asked before the near copies, which
        // cost more to tell.
        const std::pair<ElementKind, double> key{h.kind, h.start};
        auto it = std::find_if(per_knot.begin(), per_knot.end(), [&](const auto& e) { return e.first == key; });
        if (it == per_knot.end()) {
            per_knot.push_back({key, 0});
            it = per_knot.end() - 1;
        }
        if (it->second >= o_.spawn) {
            continue;
        }
        std::vector<std::size_t>& same_kind = of_kind[static_cast<std::size_t>(h.kind)];
        if (!fresh && std::any_of(same_kind.begin(), same_kind.end(), [&](std::size_t k) { return near_copy(h, kept[k]); })) {
            continue;
        }
        ++it->second;
        old += fresh ? 0 : 1;
        same_kind.push_back(kept.size());
        kept.push_back(std::move(h));
    }
    live_.swap(kept);
}

// The live hypotheses' indices by ascending value, ties in index order (a
// stable sort). Indices, not the hypotheses: each is a 4 x 4 system. By
// insertion into a buffer kept from knot to knot: no allocation per knot
// (std::stable_sort took 2.4 % of VDE 8.2's fit with its buffers, this
// 2.1 %).
const std::vector<std::size_t>& Search::by_value() {
    std::vector<std::size_t>& order = order_;
    order.resize(live_.size());
    for (std::size_t i = 0; i < order.size(); ++i) {
        const double v = live_[i].value;
        std::size_t j = i;
        for (; j > 0 && v < live_[order[j - 1]].value; --j) {
            order[j] = order[j - 1];
        }
        order[j] = i;
    }
    return order;
}

std::vector<FrameElement> Search::best_path(double s1) {
    double best = std::numeric_limits<double>::infinity();
    int at = -1;
    // An element the one after the span may follow, where the beam kept one
    // (research_span refines the design as it was where none).
    const bool any_follows = std::any_of(live_.begin(), live_.end(), [&](const Hypothesis& h) {
        return !o_.after || design::may_adjoin(*o_.after, h.kind);
    });
    for (const Hypothesis& h : live_) {
        if (any_follows && o_.after && !design::may_adjoin(*o_.after, h.kind)) {
            continue;
        }
        // The last element at a free end: a transition's curvature there is
        // one more parameter.
        const bool free_transition = !o_.end && h.kind == ElementKind::transition;
        design::Vec4 start = design::Vec4::Zero();
        const double v = design::close_chain(h.f, (s1 - h.start) / S, h.kind, o_, &start) + prior(h, start, s1, true) +
                         (free_transition ? design::element_penalty(h.kind, o_, true) -
                                                design::element_penalty(h.kind, o_, false)
                                          : 0.0);
        if (v < best) {
            best = v;
            at = h.record;
        }
    }
    std::vector<FrameElement> path;
    double end = s1;
    for (int r = at; r >= 0; r = records_[static_cast<std::size_t>(r)].parent) {
        const Record& rec = records_[static_cast<std::size_t>(r)];
        path.push_back({rec.kind, rec.s, end, 0.0, 0.0});
        end = rec.s;
    }
    std::reverse(path.begin(), path.end());
    return path;
}

std::vector<FrameElement> Search::run() {
    seed();
    const double span = o_.s1 - o_.s0;
    const auto steps = static_cast<std::size_t>(std::max(1.0, std::ceil(span / o_.knot_step_m - 1e-9)));
    std::size_t next = 0;
    while (next < n_.size() && n_[next].t < o_.s0) {
        ++next;
    }
    // Nodes before the range (none where s0 is the first node's chainage) count at its start.
    for (Hypothesis& h : live_) {
        design::add_nodes(h.f, n_, 0, next, h.start);
    }
    // Knots open on the grid where nodes came, and at the extra candidates.
    std::vector<std::pair<double, bool>> at; // chainage, an extra candidate
    for (std::size_t k = 1; k < steps; ++k) {
        at.push_back({o_.s0 + static_cast<double>(k) * o_.knot_step_m, false});
    }
    for (const double x : o_.knots) {
        if (x > o_.s0 && x < o_.s1) {
            at.push_back({x, true});
        }
    }
    std::sort(at.begin(), at.end());
    at.push_back({o_.s1, false});
    for (std::size_t k = 0; k < at.size(); ++k) {
        const std::size_t before = next;
        advance(at[k].first, next, at[k].second);
        if (k + 1 < at.size() && (next > before || at[k].second)) {
            spawn(at[k].first);
            keep_best();
        }
    }
    // Nodes past the range count at its end.
    for (Hypothesis& h : live_) {
        design::add_nodes(h.f, n_, next, n_.size(), h.start);
        cover(h, o_.s1);
    }
    return best_path(o_.s1);
}

} // namespace

double transition_length_for(double curvature) {
    const double r = 1.0 / std::max(std::abs(curvature), 1e-6);
    const double v = std::min(250.0, std::sqrt(r * 250.0 / 11.8));
    return std::clamp(0.45 * v, 20.0, 250.0);
}

FrameDesign design_dp(const std::vector<FrameNode>& nodes, const DesignDpOptions& o) {
    if (nodes.empty() || !(o.s1 > o.s0) || !(o.knot_step_m > 0.0)) {
        throw std::invalid_argument("design_dp: no nodes or an empty chainage range");
    }
    const std::vector<FrameNode> sorted = by_chainage(nodes);
    // Twice: plain, and with each element's priors priced as it closes, at
    // its likeliest state then. The plain beam misses designs whose
    // transitions the priors want of another length (in an exact frame at
    // the true noise, sparse routes over a penalty dearer than the true
    // structure 25 / 20 -> 15 / 5 at 0.3 / 1.0 m), and the priced alone
    // fails where few nodes tell a transition's state as it closes (a
    // sparse second track's search ended millions dearer, curves of R 10 m
    // through its gaps): the cheaper design, priors priced, wins.
    const auto fitted = [&](const std::vector<FrameElement>& structure) {
        return o.refine ? refine_structure(sorted, structure, o) : solve_structure(sorted, structure, o);
    };
    const std::vector<FrameElement> a = Search(sorted, o, false).run();
    const std::vector<FrameElement> b = Search(sorted, o, true).run();
    const auto same = [](const FrameElement& x, const FrameElement& y) {
        return x.kind == y.kind && x.s0 == y.s0 && x.s1 == y.s1;
    };
    FrameDesign plain = fitted(a);
    if (std::equal(a.begin(), a.end(), b.begin(), b.end(), same)) {
        return plain;
    }
    FrameDesign with_priors = fitted(b);
    return priced(with_priors, o) < priced(plain, o) ? with_priors : plain;
}

} // namespace railodd::geometry::fit
