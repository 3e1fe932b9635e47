#include "design_fit.hpp"

#include "curvature_model.hpp"
#include "design_dp.hpp"
#include "design_guide.hpp"
#include "design_local.hpp"
#include "design_pass.hpp"
#include "design_polish.hpp"
#include "outlier_nodes.hpp"
#include "reference_line.hpp"
#include "railodd/geometry/indexed_alignment.hpp"

#include <algorithm>
#include <cmath>
#include <memory>
#include <optional>

namespace railodd::geometry::fit {

namespace {

constexpr double reference_step_m = 2.0;
// The scatter reported where too few nodes lie close together to tell it
// (sparse chains): the fit's own residual scale, up to this. The truth
// bench draws up to 2 m (its sparse routes at 2 m: 1.7-2.5 m estimated); a
// sparse chain's residual scale beyond is its misfit's (Cologne way
// 400045940: 10 m, nodes 15 m off at p95), and the chain's fit is judged
// against how far noise takes a node (chain_fit.cpp). The scan's 0.3 m
// prior there built half the sparse truth routes at 2 m by corners.
constexpr double untold_scatter_max_m = 3.0;
// The noise a chain starts at where the scan cannot tell it.
constexpr double untold_sigma_m = 0.3;
constexpr double smoothing_m = 30.0;
// Calibrated on the truth bench (bench_alignment_truth --method design):
// 1.2 ln n per parameter (routes beyond issue 37's deviation limits, 300 per
// regime: as many or fewer than at 1.5 in all 12; 1.0 lost at 0.1 m noise);
// a weak pull to straight (300 per metre per (1/m)^2: a 500 m arc of R 1000
// costs 0.15); the transition-length prior at 3 per squared
// log ratio (twice the rule's length costs 1.4).
constexpr double penalty_per_log_node = 1.2;
constexpr double curvature_weight = 300.0;
constexpr double transition_prior = 3.0;
// The search's extra candidate knots: the last design's, and this far
// either side; searches at most this many times.
constexpr double knot_shift_m = 2.0;
constexpr int search_rounds = 2;
// A parallel track's curvature held as firmly as a 100 m stretch of this
// chain's own curvature known to 2e-5 1/m (per metre per (1/m)^2).
constexpr double guide_weight = 1.0 / (100.0 * 2e-5 * 2e-5);

// The parameters the design spent on the nodes: the start state and each
// element's length, a transition's slope besides.
std::size_t parameters(const FrameDesign& d) {
    std::size_t k = 3;
    for (const auto& e : d.elements) {
        k += e.kind == ElementKind::transition ? 2 : 1;
    }
    return k;
}

// The noise scale of the residuals: their root mean square (each capped at
// the biweight cut of their MAD: a stray kept this round counts as a far
// node, not as its offset), corrected for half the parameters the fit
// spent on them, pooled with a prior of `prior_nodes` pseudo-nodes at
// `prior_m` (a scaled inverse chi-square prior): a chain of a few nodes
// cannot tell its scatter alone, and from its own residuals it drifts up
// (the penalty in units of it grows, fewer elements fit, the residuals grow
// again). Half: a knot's position absorbs less scatter than a linear
// parameter does, none in a gap between nodes. The MAD itself, the whole
// count and 10 pseudo-nodes left the estimate 1.06x the true noise at the
// median and 1.33x at p95 on sparse truth routes at 1 m, and 1.36x at the
// median at 0.1 m, where the prior's 0.3 m outweighed the nodes
// (docs/BENCHMARKS.md).
double residual_sigma(const DesignPass& pass, const std::vector<double>& weight, double prior_m) {
    constexpr double prior_nodes = 2.0;
    std::vector<double> kept;
    for (std::size_t i = 0; i < weight.size(); ++i) {
        if (weight[i] > 0.0) {
            kept.push_back(pass.distance[i]);
        }
    }
    const double n = static_cast<double>(kept.size());
    const double dof = std::max(0.0, n - 0.5 * static_cast<double>(parameters(pass.design)));
    const double cap = biweight_cut * 1.4826 * median(kept);
    double squares = 0.0;
    for (const double d : kept) {
        const double capped = std::min(d, cap);
        squares += capped * capped;
    }
    const double var = (squares + prior_nodes * prior_m * prior_m) / (dof + prior_nodes);
    return std::clamp(std::sqrt(var), 0.02, 10.0);
}

// Each node's weight: whole within the cut (4.685 sigma), none beyond it (a
// capped squared loss, as the passes are compared on the map), except a far
// node whose neighbour is far too: a stretch the design misses is the
// structure's fault, not the nodes'. Tukey's biweight, which weighs a node
// 2.5 sigma off by a half, let a design skip a gentle curve whose nodes lie
// 1-3 sigma to one side (OSM-like truth seed 1290 at 2 m: 9.3 m off; truth
// rows beyond the limit 12 fewer, 4 more, docs/BENCHMARKS.md); strays
// inside the cut are the node trials' to leave out.
std::vector<double> robust_weights(const std::vector<double>& d, double sigma) {
    const double c = biweight_cut * sigma;
    std::vector<double> w(d.size(), 1.0);
    for (std::size_t i = 1; i + 1 < d.size(); ++i) {
        if (d[i] > c && !(d[i - 1] > c || d[i + 1] > c)) {
            w[i] = 0.0;
        }
    }
    return w;
}

// Nodes far off the smoothing spline where their neighbours are not (an
// isolated spike) are left out of the first pass: fitted there, a spike
// near a free chain end bends the first element into a hook the later
// passes, which take that design as their frame, cannot undo. 1.5 m at
// least: the spline cuts a tight curve's nodes by up to about that much.
void screen_spikes(const ReferenceLine& smooth, const std::vector<Point2>& p, std::vector<double>& weight) {
    constexpr double spike_m = 1.5;
    std::vector<double> off;
    for (const FrameNode& n : develop(smooth, p)) {
        off.push_back(std::abs(n.z - smooth.developed(n.t)));
    }
    const std::vector<double> w = robust_weights(off, spike_m / biweight_cut);
    for (std::size_t i = 0; i < weight.size(); ++i) {
        weight[i] = w[i] == 0.0 ? 0.0 : weight[i];
    }
}

// The previous pass's structure in this pass's frame, whose reference is
// that pass's design from its start: a knot's chainage is its arc length
// there. Empty where it no longer fits the span (then the search runs).
std::vector<FrameElement> carried(const FrameDesign* previous, const DesignDpOptions& o) {
    if (!previous || previous->elements.empty()) {
        return {};
    }
    std::vector<FrameElement> st = previous->elements;
    const double shift = previous->elements.front().s0;
    for (FrameElement& e : st) {
        e.s0 -= shift;
        e.s1 -= shift;
    }
    st.front().s0 = o.s0;
    st.back().s1 = o.s1;
    for (const FrameElement& e : st) {
        if (!(e.s1 > e.s0)) {
            return {};
        }
    }
    return st;
}

// A pass's design with its elements as on the map (on_map), chainages
// those of the next pass's frame, whose reference is this design.
FrameDesign map_design(const DesignPass& pass) {
    FrameDesign d = pass.design;
    d.elements = on_map(*pass.frame, pass.design);
    return d;
}

// A structure's knots, and a little either side: candidates for the search
// besides the grid's.
std::vector<double> knots_around(const std::vector<FrameElement>& st) {
    std::vector<double> k;
    for (std::size_t i = 1; i < st.size(); ++i) {
        for (const double shift : {-knot_shift_m, 0.0, knot_shift_m}) {
            k.push_back(st[i].s0 + shift);
        }
    }
    return k;
}

// A chain's tied ends: position, heading and curvature (design_rules.hpp).
struct Ties {
    std::optional<Pose> start, end;
    const std::vector<IndexedAlignment>* guides = nullptr; // parallel tracks fitted before (design_guide.hpp)
    std::vector<char> held;                                 // per node: never left out (fit_alignment.hpp)
};

// A held node keeps its whole weight.
void hold(std::vector<double>& weight, const std::vector<char>& held) {
    for (std::size_t i = 0; i < held.size() && i < weight.size(); ++i) {
        weight[i] = held[i] ? 1.0 : weight[i];
    }
}

// What a pass searches: the whole structure (with the previous pass's
// design, where given, as a rival), or from the previous pass's structure
// the local search alone (later passes refine the frame and the noise, not
// the structure's discovery) or the local search and its windows searched
// again (after the node trials, which search again only around their nodes:
// a curve one broke in two, two arcs with a dip to straight, stays so
// otherwise; OSM-like truth seed 1096 at 0.3 m, 26 dearer than one arc).
enum class Search { whole, windows, local };

// One pass in the frame of `ref`.
DesignPass run_pass(const ReferenceLine& ref, const std::vector<Point2>& p, const std::vector<double>& weight, double sigma,
                    const Ties& ties, const FrameDesign* previous, Search search) {
    const std::optional<Pose>& start = ties.start;
    const std::optional<Pose>& end = ties.end;
    std::vector<FrameNode> nodes = develop(ref, p);
    for (std::size_t i = 0; i < nodes.size(); ++i) {
        nodes[i].w = weight[i] / (sigma * sigma);
    }
    DesignDpOptions o = calibrated_options(p.size());
    // The span of the nodes' chainages, not the first's and the last's: a
    // design that hooks at a free end can put the last node's foot inside.
    const auto [lo, hi] = std::minmax_element(nodes.begin(), nodes.end(),
                                              [](const FrameNode& a, const FrameNode& b) { return a.t < b.t; });
    o.s0 = lo->t;
    o.s1 = hi->t;
    if (start) {
        o.start = frame_state(ref, *start, o.s0);
    }
    if (end) {
        o.end = frame_state(ref, *end, o.s1);
    }
    o.s1 = std::max(o.s1, o.s0 + 1.0);
    const std::vector<FrameElement> seed = carried(previous, o);
    if (ties.guides && !ties.guides->empty() && !seed.empty()) {
        auto guide = std::make_shared<const GuideCurvature>(ref, o.s0, o.s1, *ties.guides, seed, guide_weight);
        if (!guide->empty() || !guide->joints().empty()) {
            o.guide = std::move(guide);
        }
    }
    DesignPass pass;
    if (search == Search::whole || seed.empty()) {
        pass.design = search_design(nodes, o, seed);
    } else {
        pass.design = refine_structure(nodes, seed, o);
        if (search == Search::windows) {
            pass.design = research_windows(nodes, std::move(pass.design), o);
        }
    }
    pass.design = take_guided_runs(nodes, std::move(pass.design), o);
    pass.alignment = to_alignment(ref, pass.design);
    pass.nodes = std::move(nodes);
    pass.options = o;
    pass.frame = ref;
    pass.sigma = sigma;
    pass.measure();
    return pass;
}

// The first pass's noise and weights: the outlier scan's (outlier_nodes.hpp),
// spikes left out; none where too few nodes lie close together to tell a
// scale. `few`: the scan's scale over the nodes it could test where they
// are too few to tell it (3-11), pooled with the 0.3 m prior; the prior
// alone on a chain of fewer nodes than that (a station loop of six nodes)
// whose nodes it could not test. A long chain of sparse nodes has none: its
// residual scale is all there is (the truth bench's sparse routes at 2 m).
struct FirstGuess {
    std::optional<double> sigma;
    std::optional<double> few;
};
FirstGuess first_guess(const std::vector<Point2>& p, std::vector<double>& weight) {
    constexpr std::size_t told_nodes = 12, some_nodes = 3;
    constexpr double prior_m = untold_sigma_m, prior_nodes = 2.0;
    const OutlierScan scan = find_outlier_nodes(p);
    for (std::size_t i = 0; i < p.size(); ++i) {
        weight[i] = scan.outlier[i] ? 0.0 : 1.0;
    }
    if (scan.tested >= told_nodes) {
        return {std::clamp(scan.noise_sigma_m, 0.05, 5.0), std::nullopt};
    }
    if (scan.tested < some_nodes) {
        return {std::nullopt, p.size() < told_nodes ? std::optional<double>(prior_m) : std::nullopt};
    }
    const double n = static_cast<double>(scan.tested);
    const double s2 = scan.noise_sigma_m * scan.noise_sigma_m;
    return {std::nullopt, std::sqrt((n * s2 + prior_nodes * prior_m * prior_m) / (n + prior_nodes))};
}

// The scatter reported (how far noise takes a node, chain_fit.cpp) where
// the scan could not tell it: the fit's own residual scale, up to
// untold_scatter_max_m, and up to 2.5 times what the scan saw on the nodes
// it could test. A short chain's residual scale is its misfit's where the
// design cannot follow it: Cologne's tram curves of 20-60 m meeting a switch
// at an angle, 9-15 nodes within 0.02-0.24 m of their neighbours' curve,
// were fitted at 2.5-6.2 m and kept up to 8.3 m off their nodes. 2.5: over
// 3-11 nodes the scan's MAD is rough (drawn at 1-2 m with five nodes, the
// bound falls under the true noise on 8-10 % of chains, which are spliced).
double untold_scatter(const FirstGuess& g, double sigma) {
    constexpr double few_factor = 2.5;
    const double s = std::min(sigma, untold_scatter_max_m);
    return g.few ? std::min(s, few_factor * *g.few) : s;
}

// Each node's distance to a pass's alignment on the map, not in the pass's
// frame, whose linearisation differs from pass to pass.
std::vector<double> map_distances(const Alignment& a, const std::vector<Point2>& p) {
    const IndexedAlignment ia(a);
    std::vector<double> d;
    d.reserve(p.size());
    for (const Point2& q : p) {
        d.push_back(ia.project(q.x, q.y).distance);
    }
    return d;
}

// What a pass's design costs at one noise scale, from its nodes' distances
// on the map: each squared in units of it, capped at the biweight cut (a
// stray costs every design the same), and its parameters. A frame moved onto
// a design that missed a stretch can lead the next pass further off (a 4 km
// Cologne chain: 7, 22, 70, 431 m); then the last pass that was no worse
// stands.
double pass_cost(const DesignPass& pass, const std::vector<double>& on_map, double sigma) {
    double c = 0.0;
    for (const double d : on_map) {
        c += std::min(d * d / (sigma * sigma), biweight_cut * biweight_cut);
    }
    return c + pass.options.parameter_penalty * static_cast<double>(parameters(pass.design));
}

// Whether the pass's design lies on the map (its nodes' distances there:
// on_map) otherwise than in its frame: a node's distance differs by more
// than a tenth of the noise (0.1 m at least).
bool drifted(const DesignPass& pass, const std::vector<double>& on_map) {
    for (std::size_t i = 0; i < on_map.size(); ++i) {
        if (std::abs(on_map[i] - pass.distance[i]) > std::max(0.1, 0.1 * pass.sigma)) {
            return true;
        }
    }
    return false;
}

// The next pass, in the frame of the last one's design; and once more in
// its own where it drifted. The frame is first order in a design's offset
// from its reference: the last pass's windows can move a curve metres off
// it (sparse truth seed 1102 at 0.3 m: 5 m, and 3.5 m off on the map for
// nodes on the design in the frame), and a first pass fitted at too low a
// noise leaves a wiggly reference (seed 1016 at 2 m: 17 m off on the map,
// 6 m in the frame, and the pass refused).
// With it, its nodes' distances on the map (map_distances).
struct NextPass {
    DesignPass pass;
    std::vector<double> on_map;
};
NextPass next_pass(const DesignPass& pass, const std::vector<Point2>& p, const std::vector<double>& weight, double sigma,
                   const Ties& ties, Search search) {
    const FrameDesign previous = map_design(pass);
    NextPass next{run_pass(alignment_reference(pass.alignment, reference_step_m), p, weight, sigma, ties, &previous,
                           search),
                  {}};
    next.on_map = map_distances(next.pass.alignment, p);
    if (drifted(next.pass, next.on_map)) {
        const FrameDesign own = map_design(next.pass);
        next.pass = run_pass(alignment_reference(next.pass.alignment, reference_step_m), p, weight, sigma, ties, &own,
                             Search::local);
        next.on_map = map_distances(next.pass.alignment, p);
    }
    return next;
}

// The nodes with a tied end's node where its tie is. The tie is where the
// network's fit of the track it leaves put the switch, and that can lie off
// the mapped node (Cologne: switch nodes 2.1-3.3 m off their through
// track's design, 7 of 29 branches then corners): the branch meets the
// switch there, and its fit is judged there.
std::vector<Point2> at_ties(std::vector<Point2> p, const std::optional<Pose>& start, const std::optional<Pose>& end) {
    if (start) {
        p.front() = {start->x, start->y};
    }
    if (end) {
        p.back() = {end->x, end->y};
    }
    return p;
}

// A transition whose ends hold one curvature is a line or an arc, and
// written so: the ties give it where a short chain between two switches on
// straight track is one transition (Cologne: 8 spirals from 0 to 0), and
// SUMO's netconvert cannot draw a spiral whose curvature does not change
// (it dropped the two roads made of one).
void constant_transitions_as_arcs(Alignment& a) {
    for (Primitive& e : a.primitives) {
        if (e.kind == PrimitiveKind::spiral && e.curv_start == e.curv_end) {
            e.kind = e.curv_start == 0.0 ? PrimitiveKind::line : PrimitiveKind::arc;
        }
    }
}

} // namespace

namespace {

FitResult fit_with(const std::vector<Point2>& mapped, const Ties& ties, const FitOptions& options) {
    const std::optional<Pose>& start = ties.start;
    const std::optional<Pose>& end = ties.end;
    const std::vector<Point2> p = at_ties(mapped, start, end);
    const bool fixed = options.noise_sigma_m > 0.0;
    std::vector<double> weight(p.size(), 1.0);
    // Untold, the scale starts at 0.3 m and the residuals' own takes over.
    const FirstGuess first = first_guess(p, weight);
    const std::optional<double> scatter = first.sigma;
    const double guess = scatter.value_or(untold_sigma_m);
    double sigma = fixed ? options.noise_sigma_m : guess;
    const ReferenceLine smooth = smooth_reference(p, smoothing_m, reference_step_m);
    screen_spikes(smooth, p, weight);
    hold(weight, ties.held);
    DesignPass pass = run_pass(smooth, p, weight, sigma, ties, nullptr, Search::whole);
    std::vector<double> on_map = map_distances(pass.alignment, p);
    for (int round = 0; round < 4; ++round) {
        const double next = fixed ? sigma : residual_sigma(pass, weight, guess);
        const bool settled = round > 0 && std::abs(next - sigma) < 0.05 * sigma;
        std::vector<double> w = robust_weights(pass.distance, next);
        hold(w, ties.held);
        NextPass tried = next_pass(pass, p, w, next, ties, round == 0 ? Search::whole : Search::local);
        if (pass_cost(tried.pass, tried.on_map, next) > pass_cost(pass, on_map, next) + pass.options.parameter_penalty) {
            // The pass stands, but its residuals tell the noise (given, next
            // is sigma): left at the starting guess, a real chain's sigma-hat
            // stayed 0.3 m (Lauf: a chain of 51 nodes whose residuals say
            // 0.338 m).
            if (round == 0) {
                sigma = next;
            }
            break;
        }
        sigma = next;
        weight = std::move(w);
        pass = std::move(tried.pass);
        on_map = std::move(tried.on_map);
        if (settled) {
            break;
        }
    }
    settle_node_weights(pass, weight, ties.held);
    pass = next_pass(pass, p, weight, sigma, ties, Search::windows).pass;
    // Again: the last pass's windows can build a curve to a stray the first
    // settling had no design bending to (truth seed 1158: a stray beside the
    // free start followed by an S-curve the windows made, 6.5 m off).
    settle_node_weights(pass, weight, ties.held);
    std::vector<Point> all, followed;
    for (std::size_t i = 0; i < p.size(); ++i) {
        all.push_back({mapped[i].x, mapped[i].y});
        followed.push_back({p[i].x, p[i].y});
    }
    FitResult r = polish(pass, p, all, weight, sigma, start, end);
    constant_transitions_as_arcs(r.alignment);
    r.quality.noise_sigma_m = sigma;
    r.quality.scatter_sigma_m = scatter ? *scatter : untold_scatter(first, sigma);
    r.quality.windows = 1;
    r.quality.outliers = static_cast<std::size_t>(std::count(weight.begin(), weight.end(), 0.0));
    const std::vector<char> stray = fitted_strays(r.alignment, all, weight, sigma, start.has_value(), end.has_value());
    r.quality.followed_max_m = followed_max(r.alignment, followed, stray);
    for (std::size_t i = 0; i < stray.size(); ++i) {
        if (stray[i]) {
            r.quality.strays.push_back(i);
        }
    }
    return r;
}

} // namespace

FrameDesign search_design(const std::vector<FrameNode>& nodes, DesignDpOptions o, const std::vector<FrameElement>& seed) {
    o.knots = knots_around(seed);
    // Designs are chosen between with their priors, as the refinement
    // prices them: without, a design it had priced far dearer could win
    // (sparse truth seed 1228 at 1 m: a reverse curve's straight read as a
    // 324 m transition through zero curvature, priors 56.7 against the true
    // structure's 0.3, 16.9 cheaper without them and 39.5 dearer with; 6.4
    // m off the true track).
    FrameDesign best = design_dp(nodes, o);
    double best_cost = priced(best, o);
    for (int r = 1; r < search_rounds; ++r) {
        o.knots = knots_around(best.elements);
        FrameDesign d = design_dp(nodes, o);
        const double cost = priced(d, o);
        if (!(cost < best_cost - 1e-6 * (1.0 + std::abs(best_cost)))) {
            break;
        }
        best = std::move(d);
        best_cost = cost;
    }
    if (!seed.empty()) {
        // Where a last pass's design is given, this is the search's last
        // run; its windows are searched again (in the first pass as well: 2.1x
        // the fit time against 1.5x, and an OSM-like truth route at 0.1 m,
        // seed 1083, 3.3 m off on a hook the next passes kept).
        best = research_windows(nodes, std::move(best), o);
        // The search is a beam: on a few sparse nodes with a tied end it can
        // miss what the last pass found (a turnout's short curve: 535
        // against 42 on one Cologne chain), and a worse design inflates the
        // next noise estimate until the design gives up the curve.
        FrameDesign incumbent = refine_structure(nodes, seed, o);
        if (priced(incumbent, o) < priced(best, o)) {
            best = std::move(incumbent);
        }
    }
    return best;
}

DesignDpOptions calibrated_options(std::size_t n) {
    DesignDpOptions o;
    o.parameter_penalty = penalty_per_log_node * std::log(std::max<double>(8.0, static_cast<double>(n)));
    o.curvature_weight = curvature_weight;
    o.transition_prior = transition_prior;
    return o;
}

FitResult fit_design(const std::vector<Point2>& mapped, const std::optional<Pose>& start, const std::optional<Pose>& end,
                     const FitOptions& options, const std::vector<IndexedAlignment>& guides,
                     const std::vector<char>& held) {
    return fit_with(mapped, {start, end, &guides, held}, options);
}

} // namespace railodd::geometry::fit
