#include "design_polish.hpp"

#include "curvature_model.hpp"
#include "design_guide.hpp"
#include "end_constraint.hpp"
#include "reference_line.hpp"

#include <algorithm>
#include <cmath>

namespace railodd::geometry::fit {

namespace {

// A knot shared with a parallel track held in the polish where the search
// put it: a metre along costs as much as a node one sigma off.
constexpr double shared_knot_weight = 1.0;
// A knot within this of a guide's joint is the guide's: carried from pass
// to pass, it moves by rounding.
constexpr double shared_knot_m = 0.25;
// The steps a solve without an apex arc may take on to meet a tied end.
constexpr int apex_end_iterations = 100;
// An arc the polish left shorter than this between two transitions (the
// search draws none under its minimum, 10 m) is tried without: the two
// transitions meeting at its curvature (VDE 8.2: 71 arcs, 48 of them at the
// solver's 0.5 m floor).
constexpr double collapsed_arc_m = 1.0;

// Per element, the shortest length the polish may give it: a transition
// at a tied end switch_transition_m (a quarter of a shorter chain), else
// the solver's own floor.
std::vector<double> length_floors(const DesignPass& pass, const std::optional<Pose>& start,
                                  const std::optional<Pose>& end) {
    const auto& el = pass.design.elements;
    const double solver = SolveOptions{}.min_length_m;
    std::vector<double> floor(el.size(), solver);
    if (el.empty()) {
        return floor;
    }
    const double held = std::max(solver, std::min(switch_transition_m, 0.25 * (el.back().s1 - el.front().s0)));
    const auto at_switch = [&](std::size_t j) {
        floor[j] = el[j].kind == ElementKind::transition ? held : floor[j];
    };
    if (start) {
        at_switch(0);
    }
    if (end) {
        at_switch(el.size() - 1);
    }
    return floor;
}

// The design as clothoids whose knots keep its structure (lines at zero
// curvature, an arc's two knots one variable, a transition meeting a line or
// another transition at zero, a tied end at its tie's curvature), every
// length free: what the exact polish moves. `floor`: per segment, the
// shortest length it may take.
CurvatureModel structure_model(const DesignPass& pass, const std::optional<Pose>& start, const std::optional<Pose>& end,
                               const std::vector<double>& floor) {
    const std::vector<FrameElement> el = on_map(*pass.frame, pass.design);
    CurvatureModel m;
    m.start = start.value_or(pass.alignment.start);
    m.start_free = !start;
    const auto is = [&](std::size_t j, ElementKind k) { return j < el.size() && el[j].kind == k; };
    if (is(0, ElementKind::line) || start) {
        m.knot_var.push_back(-1);
        m.knot_fixed.push_back(start ? start->curvature : 0.0);
    } else {
        m.curv.push_back(el[0].k0);
        m.knot_var.push_back(0);
        m.knot_fixed.push_back(0.0);
    }
    for (std::size_t j = 0; j < el.size(); ++j) {
        const double len = std::max(el[j].s1 - el[j].s0, floor[j]);
        const bool last = j + 1 == el.size();
        if (last && end) {
            m.push_segment(len, true, -1, end->curvature);
        } else if (el[j].kind == ElementKind::line || is(j + 1, ElementKind::line) ||
                   (el[j].kind == ElementKind::transition && is(j + 1, ElementKind::transition))) {
            m.push_segment(len, true, -1, 0.0);
        } else if (el[j].kind == ElementKind::arc && m.knot_var.back() >= 0) {
            m.push_segment(len, true, m.knot_var.back());
        } else {
            m.curv.push_back(el[j].k1);
            m.push_segment(len, true, static_cast<int>(m.curv.size()) - 1);
        }
    }
    return m;
}

// The pass's own alignment, moved onto its tied end (meet_end): from the
// frame it misses by up to millimetres. Not where that brings the nodes
// further off.
FitResult unpolished(const DesignPass& pass, CurvatureModel m, const std::vector<Point>& all, double sigma,
                     const std::optional<Pose>& end) {
    FitResult before{pass.alignment, measure_fit(pass.alignment, all)};
    if (!end || !meet_end(m, *end)) {
        return before;
    }
    FitResult met{m.to_alignment(), {}};
    met.quality = measure_fit(met.alignment, all);
    const bool kept = met.quality.max_m <= before.quality.max_m + 0.5 * sigma && !loops_back(met.alignment, all);
    return kept ? met : before;
}

// The knots the design took from a parallel track (design_guided.cpp) held
// where the search put them, within about a metre: on sparse nodes the
// polish slid them along a flat valley (Liechtenstein: a transition 14 m
// along from its neighbour's), and the two tracks' curves no longer matched.
void hold_shared_knots(const DesignPass& pass, const CurvatureModel& m, SolveOptions& so) {
    const auto& el = pass.design.elements;
    const auto& joints = pass.options.guide->joints();
    so.knot_at.assign(m.segments() + 1, 0.0);
    so.knot_weight.assign(m.segments() + 1, 0.0);
    double at = 0.0;
    bool any = false;
    for (std::size_t k = 1; k < el.size(); ++k) {
        at += m.lengths[k - 1];
        const bool shared = std::any_of(joints.begin(), joints.end(),
                                        [&](const GuideCurvature::Joint& j) { return std::abs(j.t - el[k].s0) < shared_knot_m; });
        so.knot_at[k] = at;
        so.knot_weight[k] = shared ? shared_knot_weight : 0.0;
        any = any || shared;
    }
    if (!any) {
        // No rows at all: the Jacobian is dense, a row per knot of a long chain.
        so.knot_at.clear();
        so.knot_weight.clear();
    }
}

// The solve's options for the pass's structure: the nodes' robust weights,
// the priors the search priced (transition lengths, a parallel track's
// curvature and the knots shared with it) and the length floors.
SolveOptions polish_options(const DesignPass& pass, const CurvatureModel& m, const std::vector<double>& weight,
                            double sigma, const std::optional<Pose>& start, const std::optional<Pose>& end,
                            std::vector<double> floor) {
    SolveOptions so;
    so.sigma_m = sigma;
    so.pin_first = !start;
    so.pin_last = true;
    so.end = end;
    // A tied end is first reached by a shrinking share of its gap per step
    // (least_squares.cpp): more steps where there is one.
    so.max_iterations = end ? 25 : 15;
    so.geodesic_acceleration = true;
    so.chain_solve = true;
    for (const double w : weight) {
        so.point_scale.push_back(std::sqrt(w));
    }
    so.abandon_loops = true;
    so.min_length_at = std::move(floor);
    const auto& el = pass.design.elements;
    so.transition_prior.assign(el.size(), 0.0);
    for (std::size_t j = 1; j + 1 < so.transition_prior.size(); ++j) {
        so.transition_prior[j] = el[j].kind == ElementKind::transition ? pass.options.transition_prior : 0.0;
    }
    if (pass.options.guide) {
        for (const FrameElement& e : el) {
            const GuideCurvature::Mean g = pass.options.guide->over(e.s0, e.s1);
            so.guide_weight.push_back(g.weight);
            so.guide_curvature.push_back(g.curvature);
            so.guide_at.push_back(e.s1 > e.s0 ? std::clamp((g.at - e.s0) / (e.s1 - e.s0), 0.0, 1.0) : 0.5);
        }
        hold_shared_knots(pass, m, so);
    }
    return so;
}

// The nodes' weighted squared distances, in sigmas: the search's measure.
double node_cost(const std::vector<double>& d, const SolveOptions& so) {
    double c = 0.0;
    for (std::size_t i = 0; i < d.size(); ++i) {
        const double s = i < so.point_scale.size() ? so.point_scale[i] : 1.0;
        c += s * s * d[i] * d[i];
    }
    return c / (so.sigma_m * so.sigma_m);
}

template <class V> void erase_at(V& v, std::size_t i) {
    if (i < v.size()) {
        v.erase(v.begin() + static_cast<std::ptrdiff_t>(i));
    }
}

// Arc j taken out of m and out of the solve's per-segment and per-knot
// rows: the transitions either side meet at its curvature variable and
// share its length.
void take_out_arc(CurvatureModel& m, SolveOptions& so, std::size_t j) {
    const double half = 0.5 * m.lengths[j];
    m.lengths[j - 1] += half;
    m.lengths[j + 1] += half;
    erase_at(m.lengths, j);
    erase_at(m.length_free, j);
    erase_at(m.knot_var, j + 1);
    erase_at(m.knot_fixed, j + 1);
    for (std::vector<double>* v : {&so.transition_prior, &so.guide_curvature, &so.guide_at, &so.guide_weight,
                                   &so.min_length_at}) {
        erase_at(*v, j);
    }
    if (!so.knot_at.empty()) {
        so.knot_at[j] += half;
        erase_at(so.knot_at, j + 1);
        erase_at(so.knot_weight, j + 1);
    }
}

// The arcs the polish shrank to nothing between two transitions (the
// arc's two knots one variable), last first; `kinds` per segment of m.
std::vector<std::size_t> collapsed_arcs(const std::vector<ElementKind>& kinds, const CurvatureModel& m) {
    const auto is = [&](std::size_t j, ElementKind k) { return kinds[j] == k; };
    std::vector<std::size_t> out;
    for (std::size_t j = kinds.size() >= 3 ? kinds.size() - 2 : 0; j >= 1; --j) {
        if (is(j, ElementKind::arc) && is(j - 1, ElementKind::transition) && is(j + 1, ElementKind::transition) &&
            m.lengths[j] < collapsed_arc_m && m.knot_var[j] >= 0 && m.knot_var[j] == m.knot_var[j + 1]) {
            out.push_back(j);
        }
    }
    return out;
}

// A model with arcs taken out (take_out_arc) and solved again, the kinds
// of its segments, and how many arcs it lacks.
struct Apex {
    CurvatureModel m;
    SolveOptions so;
    std::vector<ElementKind> kinds;
    std::size_t taken = 0;
    std::optional<FitResult> fit;
};

// `a` without arcs `js` (descending), solved again: kept where the nodes'
// cost rises over the polished design's by less than the L0 penalty of
// every length taken out, and no node lies beyond `limit`.
bool solved_without(Apex& a, const std::vector<std::size_t>& js, const DesignPass& pass, const std::vector<Point2>& p,
                    const std::vector<Point>& all, const SolveReport& polished, double limit) {
    for (const std::size_t j : js) {
        take_out_arc(a.m, a.so, j);
        a.kinds.erase(a.kinds.begin() + static_cast<std::ptrdiff_t>(j));
    }
    a.taken += js.size();
    SolveReport r = solve(a.m, p, a.so);
    if (!r.end_met && !r.gave_up) {
        // Without the arc a tied end is reached afresh, by a shrinking share
        // of its gap per step: in the polish's 25 steps 28 of the 30 solves
        // Cologne refused fell short of their tie (arcs at the 0.5 m floor,
        // most beside a switch's 2 m transition). Carried on from there.
        SolveOptions more = a.so;
        more.max_iterations = apex_end_iterations;
        r = solve(a.m, p, more);
    }
    if (!r.end_met || r.gave_up ||
        node_cost(r.distances_m, a.so) >
            node_cost(polished.distances_m, a.so) + static_cast<double>(a.taken) * pass.options.parameter_penalty) {
        return false;
    }
    FitResult out{a.m.to_alignment(), {}};
    out.quality = measure_fit(out.alignment, all);
    if (out.quality.max_m > limit || loops_back(out.alignment, all)) {
        return false;
    }
    a.fit = std::move(out);
    return true;
}

// The polished design without the arcs it shrank to nothing between two
// transitions (a curve whose transitions meet at its apex): all at once,
// else one at a time, each kept where the nodes allow (solved_without);
// again while a solve without some shrinks others. Taken all or none, once,
// Cologne kept 76 such arcs mid-chain (30 now): one arc the nodes hold kept
// every other of its chain, or the solve without one shrank the next.
// Issue 37 asks for no element under a metre the design lacks.
std::optional<FitResult> without_collapsed_arcs(const DesignPass& pass, const CurvatureModel& m, const SolveOptions& so,
                                                const std::vector<Point2>& p, const std::vector<Point>& all,
                                                const SolveReport& polished, double limit) {
    constexpr int rounds = 4;
    Apex kept{m, so, {}, 0, std::nullopt};
    for (const FrameElement& e : pass.design.elements) {
        kept.kinds.push_back(e.kind);
    }
    for (int round = 0; round < rounds; ++round) {
        const std::vector<std::size_t> js = collapsed_arcs(kept.kinds, kept.m);
        if (js.empty()) {
            break;
        }
        Apex at_once = kept;
        if (solved_without(at_once, js, pass, p, all, polished, limit)) {
            kept = std::move(at_once);
            continue;
        }
        if (js.size() == 1) {
            break; // one at a time is the solve just refused
        }
        const std::size_t before = kept.taken;
        for (const std::size_t j : js) {
            if (kept.m.lengths[j] >= collapsed_arc_m) {
                continue; // grown back where the arcs after it went
            }
            Apex one = kept;
            if (solved_without(one, {j}, pass, p, all, polished, limit)) {
                kept = std::move(one);
            }
        }
        if (kept.taken == before) {
            break;
        }
    }
    return kept.fit;
}

} // namespace

FitResult polish(const DesignPass& pass, const std::vector<Point2>& p, const std::vector<Point>& all,
                 const std::vector<double>& weight, double sigma, const std::optional<Pose>& start,
                 const std::optional<Pose>& end) {
    std::vector<double> floor = length_floors(pass, start, end);
    CurvatureModel m = structure_model(pass, start, end, floor);
    const CurvatureModel unsolved = m;
    const SolveOptions so = polish_options(pass, m, weight, sigma, start, end, std::move(floor));
    const SolveReport r = solve(m, p, so);
    FitResult before = unpolished(pass, unsolved, all, sigma, end);
    if (!r.end_met || r.gave_up) {
        return before;
    }
    // Kept only where it brings the nodes no further off: a solve that wandered
    // (a loop at the curvature bound, a tie pulling across a gap) is not.
    const double limit = before.quality.max_m + 0.5 * sigma;
    FitResult polished{m.to_alignment(), {}};
    polished.quality = measure_fit(polished.alignment, all);
    if (polished.quality.max_m > limit || loops_back(polished.alignment, all)) {
        return before;
    }
    std::optional<FitResult> apex = without_collapsed_arcs(pass, m, so, p, all, r, limit);
    return apex ? std::move(*apex) : polished;
}

} // namespace railodd::geometry::fit
