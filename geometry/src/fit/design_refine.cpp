// Local search on the design the beam found: each knot moved, each element
// merged away or split, kept where the cost with its priors falls. The beam
// decides at each knot on the nodes seen so far; a knot's best place and
// whether an element pays for itself show only once the nodes after it are
// in, which this pass sees whole. Each trial costs only the nodes of the
// elements it changes (StructureCosts).
#include "design_dp.hpp"
#include "design_local.hpp"
#include "design_rules.hpp"

#include <algorithm>
#include <array>
#include <initializer_list>
#include <cmath>
#include <limits>
#include <span>
#include <utility>

namespace railodd::geometry::fit {

namespace {

struct Move {
    std::size_t j = 0, k = 0; // elements [j, k) replaced
    std::vector<FrameElement> with;
    double cost = std::numeric_limits<double>::infinity();
};

class Refiner {
public:
    Refiner(const std::vector<FrameNode>& n, const DesignDpOptions& o, std::pair<double, double> span)
        : costs_(n, o), o_(o), span_(span) {}

    // Runs rounds of moves until none lowers the cost by a thousandth of a
    // noise variance (a hundredth of a penalty made the truth bench's dense
    // routes at 1 m noise 10 % worse: small knot moves add up); after the
    // first round only around elements the last one changed (elsewhere the
    // moves were tried and did not pay). Returns the structure.
    // A move taken, the sweep goes on after its new elements (the knot
    // costs are brought up to date as it goes, StructureCosts::replace); they
    // are tried in the next round, which starts from a full solve.
    std::vector<FrameElement> run(std::vector<FrameElement> st) {
        const double min_gain = 1e-3;
        std::vector<char> dirty(st.size(), 1);
        for (int round = 0; round < 8; ++round) {
            costs_.reset(st);
            std::vector<char> next(st.size(), 0);
            bool improved = false;
            for (std::size_t j = 0; j < st.size(); ++j) {
                if (!dirty[j] || st[j].s1 < span_.first || st[j].s0 > span_.second) {
                    continue;
                }
                costs_.valid_up_to(j);
                Move best;
                best.cost = costs_.cost() - min_gain;
                try_merges(st, j, best);
                try_splits(st, j, best);
                try_knot(st, j, best);
                try_stretch(st, j, best);
                if (best.with.empty()) {
                    continue;
                }
                costs_.replace(best.j, best.k, best.with);
                take(st, best, dirty, next);
                j = best.j + best.with.size() - 1;
                improved = true;
            }
            if (!improved) {
                break;
            }
            dirty = std::move(next);
        }
        return st;
    }

private:
    // The move made: its elements and those within two of them to be tried
    // again, in this round (`dirty`) and the next.
    static void take(std::vector<FrameElement>& st, const Move& m, std::vector<char>& dirty, std::vector<char>& next) {
        const auto at = [](std::size_t i) { return static_cast<std::ptrdiff_t>(i); };
        st.erase(st.begin() + at(m.j), st.begin() + at(m.k));
        st.insert(st.begin() + at(m.j), m.with.begin(), m.with.end());
        for (std::vector<char>* v : {&dirty, &next}) {
            v->erase(v->begin() + at(m.j), v->begin() + at(m.k));
            v->insert(v->begin() + at(m.j), m.with.size(), 1);
            const std::size_t lo = m.j > 2 ? m.j - 2 : 0, hi = std::min(st.size(), m.j + m.with.size() + 2);
            std::fill(v->begin() + at(lo), v->begin() + at(hi), 1);
        }
    }

    // Trials are built on the stack: the local search tries tens of millions.
    void offer(std::size_t j, std::size_t k, std::span<const FrameElement> w, Move& best) const {
        const double c = costs_.replaced(j, k, w, best.cost);
        if (c < best.cost) {
            best = {j, k, std::vector<FrameElement>(w.begin(), w.end()), c};
        }
    }
    void offer(std::size_t j, std::size_t k, std::initializer_list<FrameElement> w, Move& best) const {
        offer(j, k, std::span<const FrameElement>(w.begin(), w.size()), best);
    }

    // The knot at the start of element j moved by up to two knot steps.
    void try_knot(const std::vector<FrameElement>& st, std::size_t j, Move& best) const {
        if (j == 0) {
            return;
        }
        const double h = o_.knot_step_m;
        for (const double d : {-2 * h, -h, -0.5 * h, -0.25 * h, 0.25 * h, 0.5 * h, h, 2 * h}) {
            std::array<FrameElement, 2> w{st[j - 1], st[j]};
            w[0].s1 += d;
            w[1].s0 += d;
            offer(j - 1, j + 1, w, best);
        }
    }

    // Transition j lengthened or shortened about its middle. Between a line
    // and an arc the nodes hold its middle and the arc's radius firmly and
    // its length loosely (the curve's shift goes with the square of the
    // length): a valley across the knot moves one at a time, which stall
    // in it (sparse truth seed 1090 at 0.1 m: a design 20 cost units dearer
    // than the truth's, 2.3 m off, and a knot moved 5 m either way 60
    // dearer still).
    void try_stretch(const std::vector<FrameElement>& st, std::size_t j, Move& best) const {
        if (j == 0 || j + 1 >= st.size() || st[j].kind != ElementKind::transition) {
            return;
        }
        const double h = o_.knot_step_m;
        for (const double d : {-2 * h, -h, -0.5 * h, -0.25 * h, 0.25 * h, 0.5 * h, h, 2 * h}) {
            std::array<FrameElement, 3> w{st[j - 1], st[j], st[j + 1]};
            w[0].s1 -= d;
            w[1].s0 -= d;
            w[1].s1 += d;
            w[2].s0 += d;
            offer(j - 1, j + 2, w, best);
        }
    }

    // The knot after element j dropped (either kind kept), or element j + 1
    // dropped between its neighbours.
    void try_merges(const std::vector<FrameElement>& st, std::size_t j, Move& best) const {
        if (j + 1 >= st.size()) {
            return;
        }
        for (const ElementKind k : {st[j].kind, st[j + 1].kind}) {
            offer(j, j + 2, {FrameElement{k, st[j].s0, st[j + 1].s1, 0.0, 0.0}}, best);
        }
        if (j + 2 < st.size()) {
            // Three into one: an arc split by a near-constant transition, a
            // short curve between two transitions.
            for (const ElementKind k : design::kinds) {
                offer(j, j + 3, {FrameElement{k, st[j].s0, st[j + 2].s1, 0.0, 0.0}}, best);
            }
            const double mid = 0.5 * (st[j + 1].s0 + st[j + 1].s1);
            std::array<FrameElement, 2> w{st[j], st[j + 2]};
            w[0].s1 = mid;
            w[1].s0 = mid;
            offer(j, j + 3, w, best);
        }
    }

    // Element j of another kind, split in two of any kinds, or a transition
    // into two with a line between (a reverse curve's straight).
    void try_splits(const std::vector<FrameElement>& st, std::size_t j, Move& best) const {
        const FrameElement& e = st[j];
        for (const ElementKind k : design::kinds) {
            if (k != e.kind) {
                offer(j, j + 1, {FrameElement{k, e.s0, e.s1, 0.0, 0.0}}, best);
            }
        }
        for (const double f : {0.25, 0.5, 0.75}) {
            const double at = e.s0 + f * (e.s1 - e.s0);
            for (const ElementKind a : design::kinds) {
                for (const ElementKind b : design::kinds) {
                    offer(j, j + 1, {FrameElement{a, e.s0, at, 0.0, 0.0}, FrameElement{b, at, e.s1, 0.0, 0.0}}, best);
                }
            }
        }
        if (e.kind == ElementKind::transition) {
            const double a = e.s0 + (e.s1 - e.s0) / 3.0, b = e.s0 + 2.0 * (e.s1 - e.s0) / 3.0;
            offer(j, j + 1,
                  {FrameElement{ElementKind::transition, e.s0, a, 0.0, 0.0}, FrameElement{ElementKind::line, a, b, 0.0, 0.0},
                   FrameElement{ElementKind::transition, b, e.s1, 0.0, 0.0}},
                  best);
        }
    }

    StructureCosts costs_;
    const DesignDpOptions& o_;
    std::pair<double, double> span_;
};

} // namespace

FrameDesign refine_structure(const std::vector<FrameNode>& nodes, const std::vector<FrameElement>& structure,
                             const DesignDpOptions& o, std::pair<double, double> span) {
    const std::vector<FrameNode> sorted = by_chainage(nodes);
    Refiner r(sorted, o, span);
    return solve_structure(sorted, r.run(structure), o);
}

} // namespace railodd::geometry::fit
