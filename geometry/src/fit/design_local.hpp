#pragma once
// The cost of a structure with a few neighbouring elements replaced, in time
// proportional to the nodes they cover: the cost of everything before the
// window as a quadratic in the state at its first knot (the forward pass of
// solve_structure) and of everything after it as a quadratic in the state
// at its last knot (the same pass run backwards along the chain), as a
// Kalman smoother splits a track in two. What the local search
// (design_refine.cpp) tries thousands of times per chain.
#include "design_dp.hpp"
#include "design_quadratic.hpp"
#include "design_rules.hpp"

#include <cassert>
#include <limits>
#include <span>
#include <vector>

namespace railodd::geometry::fit {

// A run of elements from the cost f of its first, already open: the nodes
// [next, end) in, its first element's penalty, every knot crossed by the
// design rules and the next element's penalty added; the run's first
// element may start the chain (at_chain_start: free or tied, or continuing
// the element before a span) and its last end it at a free end (their
// penalties say so).
// maps[i] / knots[i + 1], where given (arrays of w.size() and w.size() + 1),
// receive the knot after w[i] (the knot cost before the next element opens). False where a knot forbids the next
// element; f ends as the last element's cost. Nodes sorted by t; a node at a
// knot is the element's before it, or, with `at_knot_after`, the one's after
// it (the backward pass runs along the mirrored chain, and a node counted on
// both sides of a window's end cost every trial there its residual twice).
bool walk(design::Quad& f, std::span<const FrameElement> w, const std::vector<FrameNode>& nodes, std::size_t next,
          std::size_t end, const DesignDpOptions& o, bool at_chain_start, bool last_at_free_end, design::KnotMap* maps,
          design::Quad* knots, bool at_knot_after = false);

// The forward pass over a whole structure: its cost, the knot costs before
// each element opens (knots[j] for j in 1..m-1), the knot maps for
// backtracking and the last element's start state. Nodes sorted by t.
struct ForwardPass {
    double cost = 0.0;
    std::vector<design::Quad> knots;
    std::vector<design::KnotMap> maps;
    design::Vec4 last_start = design::Vec4::Zero();
};
ForwardPass forward_pass(const std::vector<FrameNode>& nodes, const std::vector<FrameElement>& st, const DesignDpOptions& o,
                         bool at_knot_after = false);

// The structure with every knot's state, backtracked from the last
// element's start (no data cost).
FrameDesign solved(const std::vector<FrameElement>& st, const ForwardPass& pass);

// Priors on a solved element that no quadratic can state: a transition's
// length against the one its curvature change calls for (at a free chain
// end, where it may be cut, only a longer one; at a tied one none), a
// curvature sign change inside one transition counted as the knot at zero
// it hides, and no curvature beyond 1/15 m. first, last: the element begins
// or ends the chain.
double element_prior(const FrameElement& e, bool first, bool last, const DesignDpOptions& o);
// A whole design's cost with its elements' priors, as the refinement prices
// it: what designs are chosen between by (search rounds, windows searched
// again, the last pass's design). FrameDesign::cost leaves the priors out,
// and the node trials and guided rivals still compare it so: with the
// priors in FrameDesign::cost itself, a guided sparse track left a good
// pair of nodes out 3.9 m off (ParallelTracks seed 2002).
double priced(const FrameDesign& d, const DesignDpOptions& o);

class StructureCosts {
public:
    // nodes sorted by t; both must outlive this.
    StructureCosts(const std::vector<FrameNode>& nodes, const DesignDpOptions& o);

    // Takes `st` as the current structure: its forward and backward knot costs.
    void reset(const std::vector<FrameElement>& st);
    double cost() const { return cost_ + prior_total_; }

    // The cost with elements [j, k) replaced by w, which spans the same
    // chainage; infinite where the design rules forbid the sequence. Needs
    // the forward knot costs up to j (valid_up_to). Where the cost is sure
    // to reach `bound` before the new elements' priors (which are never
    // negative) are solved, it returns a value no less than `bound`: most
    // trials of the local search fail so, and the priors' backtracking
    // was a fifth of their time.
    double replaced(std::size_t j, std::size_t k, std::span<const FrameElement> w,
                    double bound = std::numeric_limits<double>::infinity()) const {
        return window(j, k, w, nullptr, bound);
    }

    // Takes the replacement as made without a full reset: the knot costs
    // before the window stand, those after it are brought up to date as
    // valid_up_to asks, and the backward costs hold from the window's end
    // on, so the next trials must lie wholly after its first element. The
    // priors of elements outside it keep their values until the next reset.
    void replace(std::size_t j, std::size_t k, std::span<const FrameElement> w);

    // Brings the forward knot costs up to knot j.
    void valid_up_to(std::size_t j);

private:
    struct Update {
        std::vector<design::Quad> knots; // knots[i]: before w[i] opens (i >= 1); knots[w.size()]: before element k
        std::vector<double> priors;      // of w's elements
    };
    double window(std::size_t j, std::size_t k, std::span<const FrameElement> w, Update* update,
                  double bound = std::numeric_limits<double>::infinity()) const;
    bool allowed(std::size_t j, std::size_t k, std::span<const FrameElement> w) const;
    double window_prior(std::size_t j, std::size_t k, std::span<const FrameElement> w, const design::KnotMap* maps,
                        design::Vec4 x, double outside, std::vector<double>* priors) const;
    // The priors of the elements outside [j, k), as of the last full solve.
    double outside_prior(std::size_t j, std::size_t k) const;
    std::size_t nodes_after(double s) const;
    // The cost f of an element of `kind` opened at knot j (the chain's start
    // for j = 0); false where the design rules forbid it there.
    bool open_at(std::size_t j, ElementKind kind, design::Quad& f) const;

    const std::vector<FrameNode>& n_;
    const DesignDpOptions& o_;
    std::vector<FrameNode> mirrored_;
    DesignDpOptions mirror_options_;
    std::vector<FrameElement> st_;
    // The cost of the nodes after knot k as a quadratic in its state.
    // Only knots after the last replacement's window are read before the
    // next reset (the sweep goes on after it).
    const design::Quad& backward(std::size_t k) const {
        assert(st_.size() - k <= from_end_valid_);
        return from_end_[st_.size() - k];
    }

    // forward_[i]: the nodes' cost up to knot i, valid for i <= forward_valid_
    // (beyond it stale until valid_up_to). The costs after a knot are kept
    // by its number counted from the end, which a replacement before it
    // leaves alone: a replacement costs its window, not the chain (a 512 km
    // chain's search spent 17 % of its time moving them).
    std::vector<design::Quad> forward_, from_end_;
    std::size_t forward_valid_ = 0;
    std::size_t from_end_valid_ = 0; // from_end_[r] holds for r <= this
    std::vector<double> prior_; // per element, from the last full solve
    double prior_total_ = 0.0;
    double cost_ = 0.0;
};

} // namespace railodd::geometry::fit
