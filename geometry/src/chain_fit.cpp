// Choosing how one chain is built; see chain_fit.hpp.
#include "chain_fit.hpp"

#include "design_splice.hpp"
#include "stretch_patch.hpp"
#include "tie_splice.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

namespace railodd::geometry {

namespace {

// A railway fit straying further than this from a node (beyond what the
// node's noise explains, noise_reach) is not kept.
constexpr double fallback_deviation_m = 2.0;
// A fit with tied ends straying further than this is tried again with free
// ends and the tied stretches spliced on: the ties, not the mapping, are what
// bends it most often (a branch meeting its through track at an angle).
constexpr double retry_deviation_m = 0.5;
// What a railway fit's end may miss its tied pose by (the fit's own
// precision, well inside OpenDRIVE link tolerances of 1 mm / 1e-4 rad).
constexpr double max_gap_m = 1e-4;
constexpr double max_heading_rad = 1e-6;
constexpr double max_curvature = 1e-9;
// Length of a spliced stretch: room for a turnout's worth of heading change.
constexpr double splice_length_m = 40.0;
// Length of the stretch that brings a fit missing its tied pose onto it:
// the miss is the polish's (millimetres, mostly), which a few metres
// mend; the rest of the tied fit, chosen over the splices, stays as it is.
constexpr double miss_splice_length_m = 10.0;
constexpr CornerFitOptions corner_options{1000.0, 0.25};
// How many times a run fitted again may itself be patched (run_fit).
constexpr int patch_depth = 2;

// The furthest a node's noise alone takes it from the true track among n
// nodes, at a family-wise 5 %: the two-sided normal quantile at 0.05 / n (13
// nodes: 2.9 sigma; 1,000: 4.1). Sigma is the smaller of the fit's own
// (residual) estimate and the nodes' scatter about their neighbours, which
// a design that cuts a corner does not inflate. A fixed 0.5 or 2 m turned
// most design-search fits at 1 m noise into corners (truth routes tied at
// both ends, dense 1.0 m: elements 194x the design at p95) and spliced tied
// ends that were within the noise (Cologne: 618 of 888 splices below 3
// sigma). The windowed fit estimates no scatter: no reach there.
double noise_reach(std::size_t n, const FitQuality& q) {
    const double sigma = std::min(q.noise_sigma_m, q.scatter_sigma_m);
    if (n == 0 || !(sigma > 0.0)) {
        return 0.0;
    }
    const double tail = 0.05 / static_cast<double>(n);
    double lo = 0.0, hi = 40.0;
    for (int i = 0; i < 60; ++i) {
        const double z = 0.5 * (lo + hi);
        (std::erfc(z / std::sqrt(2.0)) > tail ? lo : hi) = z;
    }
    return lo * sigma;
}

// Whether the spliced fit, furthest `spliced_worst` from a node, explains
// the tied fit's miss (`tied_worst`): it brings every node within what
// their noise explains (the ties were what bent the tied fit), or within
// the chain's limit where the tied fit is beyond it (whose stretch the
// patch would rebuild by corners through that node), or it passes nearer
// by more than the noise. A node off the track that neither follows
// decides nothing: an outlier 8-10 m off at 2 m of noise left the two a
// few centimetres apart either way, and which was nearer chose the splice
// (truth routes tied at both ends, dense 2.0 m with outliers: 98 of 300
// spliced, on outliers up to 7 km from either tie).
bool explains_the_miss(double spliced_worst, double tied_worst, double reach, double limit, const FitQuality& q) {
    const double sigma = std::min(q.noise_sigma_m, q.scatter_sigma_m);
    return spliced_worst <= retry_deviation_m + reach || (tied_worst > limit && spliced_worst <= limit) ||
           spliced_worst < tied_worst - sigma;
}

// Nodes the fit passes beyond `limit` whose neighbours both lie within the
// noise's reach of it: a lone spike no railway follows, an outlier inside
// the robust weights' cut (9-10 m off at 2 m of noise), left out as the
// fit's strays are. Judged as followed, the patch rebuilt the stretch round
// it by corners through it: 8 of the 10 worst tied truth routes at OSM-like
// 2.0 m with outliers, 8.5-10 m off the true track there. A hook or a jog
// moves two or more nodes off and stays judged, and so does a node with
// fewer than two witnesses on a side (nodes, or a tie), as for the fit's
// own strays (design_pass.hpp): a free end node is always followed, and a
// Cologne yard track of three nodes, tied at its switch, had its middle
// node taken for a spike 17 m off a design that bowed between its ends.
// d: each node's distance from the fit.
std::vector<std::size_t> with_lone_spikes(const std::vector<double>& d, std::vector<std::size_t> strays, double limit,
                                          double reach, const std::vector<std::size_t>& held, bool tied_start,
                                          bool tied_end) {
    const std::size_t first = tied_start ? 1 : 2, last_after = tied_end ? 1 : 2;
    for (std::size_t i = first; i + last_after < d.size(); ++i) {
        if (d[i] > limit && d[i - 1] <= reach && d[i + 1] <= reach && !std::binary_search(held.begin(), held.end(), i)) {
            strays.push_back(i);
        }
    }
    std::sort(strays.begin(), strays.end());
    strays.erase(std::unique(strays.begin(), strays.end()), strays.end());
    return strays;
}

// The furthest of the distances d of the nodes that are not strays (ascending).
double followed_max(const std::vector<double>& d, const std::vector<std::size_t>& strays) {
    double worst = 0.0;
    for (std::size_t i = 0; i < d.size(); ++i) {
        if (!std::binary_search(strays.begin(), strays.end(), i)) {
            worst = std::max(worst, d[i]);
        }
    }
    return worst;
}

// Whether `candidate` may replace `kept`: no tighter than a track turns
// (design_splice.hpp) where `kept` is not. The corners follow their nodes
// whatever it takes: where the nodes leave a tie at an angle within a few
// metres (a branch drawn onto its through track across the switch), with
// corners of R 0.5-5 m, which no vehicle could run (Munich's sub-metre
// elements were mostly such corners).
bool may_replace(const Alignment& kept, const Alignment& candidate) {
    return drivable(candidate) || !drivable(kept);
}

bool misses(const EndMiss& m) {
    return m.gap_m > max_gap_m || m.heading_rad > max_heading_rad || m.curvature > max_curvature;
}

// A ring (a chain closed on itself with no switch on it: first and last
// node one) has its end brought onto its own start, so that it runs on
// round without a kink.
void close_ring(ChainFit& f, const std::vector<Point>& p, const std::optional<Pose>& start,
                const std::optional<Pose>& end, double limit) {
    // No track runs round a shorter ring than a circle of its tightest
    // curve (VDE 8.2 has two of 3-4 m, mapping slips).
    const double shortest = 2.0 * std::numbers::pi / max_track_curvature;
    if (!closes_on_itself(p) || start || end || polyline_chainage(p).back() < shortest) {
        return;
    }
    const Pose home = evaluate(f.alignment, 0.0);
    if (misses(end_miss(f.alignment, home))) {
        f.alignment = splice_end(f.alignment, p, home, miss_splice_length_m, corner_options, limit);
        ++f.spliced_ends;
    }
}

// The free fit with each tied end's stretch rebuilt (tie_splice.hpp): by a
// few curves of design passing the nodes within `tolerance`, else corners.
ChainFit spliced(const Alignment& free_fit, const std::vector<Point>& p, const std::optional<Pose>& start,
                 const std::optional<Pose>& end, double tolerance) {
    ChainFit f{free_fit, ChainMethod::spliced, 0};
    if (start) {
        f.alignment = splice_start(f.alignment, p, *start, splice_length_m, corner_options, tolerance, !end);
        ++f.spliced_ends;
    }
    if (end) {
        f.alignment = splice_end(f.alignment, p, *end, splice_length_m, corner_options, tolerance, !start);
        ++f.spliced_ends;
    }
    return f;
}

// How far a spliced fit lies from the chain's nodes: all of them (what it
// is chosen by, against the tied fit's) and those it follows, its free
// fit's strays left out (what the chain's limit is read against, as the
// tied fit's followed_max_m is). Judged by all, a chain whose free fit left
// a stray out was sent to corners throughout: the patch, which skips
// strays, found no stretch to cut (Cologne: chains of up to 14 km).
struct SplicedFit {
    ChainFit fit;
    std::vector<std::size_t> strays;
    double worst_all = 0.0;
    double worst_followed = 0.0;
};

void measure(SplicedFit& s, const std::vector<Point>& p) {
    if (loops_back(s.fit.alignment, p)) {
        s.worst_all = s.worst_followed = std::numeric_limits<double>::infinity();
        return;
    }
    const std::vector<double> d = distances(s.fit.alignment, p);
    s.worst_all = d.empty() ? 0.0 : *std::max_element(d.begin(), d.end());
    s.worst_followed = followed_max(d, s.strays);
}

// The fit with free ends, its tied stretches spliced on. Splices of design
// are tried first (within the chain's limit); where the chain then strays
// further than the tied fit did (`tied_worst`), corners, which follow
// every node within 0.25 m.
SplicedFit spliced_fit(const std::vector<Point>& p, const std::optional<Pose>& start, const std::optional<Pose>& end,
                       const FitOptions& o, const std::vector<IndexedAlignment>& guides, double limit,
                       double tied_worst) {
    FitResult r = fit_alignment(p, std::nullopt, std::nullopt, o, guides);
    SplicedFit s{spliced(r.alignment, p, start, end, limit), std::move(r.quality.strays)};
    measure(s, p);
    if (s.worst_all >= tied_worst) {
        s.fit = spliced(r.alignment, p, start, end, 0.0);
        measure(s, p);
    }
    return s;
}

bool patch(ChainFit& f, const std::vector<Point>& p, const std::vector<std::size_t>& strays, double limit,
           const std::optional<Pose>& start, const std::optional<Pose>& end, const FitOptions& o,
           const std::vector<IndexedAlignment>& guides, int depth);

// A run fitted again on its own, with the chain's tie where it reaches a
// tied end; kept where it follows its nodes as a chain's fit must (within
// 2 m of what their noise explains) and loops nowhere, or where it does
// once patched in turn (`depth` more times at most).
std::optional<Alignment> run_fit(const std::vector<Point>& run, const std::optional<Pose>& start,
                                 const std::optional<Pose>& end, const FitOptions& o,
                                 const std::vector<IndexedAlignment>& guides, int depth) {
    const FitResult r = fit_alignment(run, start, end, o, guides);
    if (loops_back(r.alignment, run)) {
        return std::nullopt;
    }
    const double limit = fallback_deviation_m + noise_reach(run.size(), r.quality);
    if (r.quality.followed_max_m <= limit) {
        return r.alignment;
    }
    ChainFit f{r.alignment, ChainMethod::railway, 0};
    if (depth > 0 && patch(f, run, r.quality.strays, limit, start, end, o, guides, depth - 1)) {
        return f.alignment;
    }
    return std::nullopt;
}

using Ranges = std::vector<std::pair<std::size_t, std::size_t>>;

// The chain cut round the nodes its fit passes beyond `limit`
// (stretch_patch.hpp): corners across those stretches, the nodes between
// fitted again. A chain that misses a few nodes keeps a design elsewhere:
// built by corners throughout, one node 3 m off made a 554-node chain of
// VDE 8.2 2,700 elements. Fitted again, not cut from the fit: the nodes it
// missed pulled it aside (a hairpin at the end of a straight tilted the
// straight 1.8 m among nodes 2 cm off). A run whose fit fails (patched in
// turn, run_fit) is built by corners with the stretches beside it, not the
// whole chain: one run of VDE 8.2's chain 166 (87 km, nodes 140-900 m
// apart and 2-14 m off any design between nodes 200 and 300) sent it to
// corners, 1,770 elements in place of 218 (shift 2 mm, docs/BENCHMARKS.md).
bool patch(ChainFit& f, const std::vector<Point>& p, const std::vector<std::size_t>& strays, double limit,
           const std::optional<Pose>& start, const std::optional<Pose>& end, const FitOptions& o,
           const std::vector<IndexedAlignment>& guides, int depth) {
    constexpr std::size_t min_run = 4;
    std::vector<char> skip(p.size(), 0);
    for (const std::size_t i : strays) {
        skip[i] = 1;
    }
    // Wider where a stretch's corners do not assemble within the limit:
    // chain 166's did not at shifts 3 and 4 mm (nodes 140-900 m apart),
    // and did once wider.
    for (const std::size_t reach : {std::size_t{2}, std::size_t{6}, std::size_t{18}}) {
        const Ranges missed = missed_stretches(f.alignment, p, skip, limit, min_run, reach);
        const Ranges runs = runs_between(missed, p.size());
        if (missed.empty() || runs.empty()) {
            return false;
        }
        std::vector<Alignment> fits;
        std::vector<char> ok;
        for (const auto& [a, b] : runs) {
            const std::vector<Point> run(p.begin() + static_cast<long>(a), p.begin() + static_cast<long>(b) + 1);
            std::optional<Alignment> r =
                run_fit(run, a == 0 ? start : std::nullopt, b + 1 == p.size() ? end : std::nullopt, o, guides, depth);
            ok.push_back(r ? 1 : 0);
            if (r) {
                fits.push_back(std::move(*r));
            }
        }
        const Ranges stretches = with_failed_runs(missed, runs, ok);
        if (fits.empty() || runs_between(stretches, p.size()).size() != fits.size()) {
            return false;
        }
        std::optional<Alignment> a = assemble_patched(p, stretches, fits, start, end, corner_options, limit);
        if (a && !loops_back(*a, p)) {
            f.alignment = std::move(*a);
            f.method = ChainMethod::patched;
            f.patched_stretches = stretches.size();
            f.spliced_ends = 0; // the runs are fitted with the chain's ties; a tie they miss is spliced below
            return true;
        }
    }
    return false;
}

} // namespace

ChainFit fit_chain_points(const std::vector<Point>& p, const std::optional<Pose>& start,
                          const std::optional<Pose>& end, const FitOptions& o, const std::vector<IndexedAlignment>& guides,
                          const std::vector<std::size_t>& held) {
    const FitResult r = fit_alignment(p, start, end, o, guides, held);
    double worst = loops_back(r.alignment, p) ? std::numeric_limits<double>::infinity() : r.quality.followed_max_m;
    ChainFit best{r.alignment, ChainMethod::railway, 0, 0, r.quality.noise_sigma_m, r.quality.outliers};
    std::vector<std::size_t> strays = r.quality.strays;
    const double reach = noise_reach(p.size(), r.quality);
    const double limit = fallback_deviation_m + reach;
    if (worst > limit && std::isfinite(worst)) {
        const std::vector<double> d = distances(r.alignment, p);
        strays = with_lone_spikes(d, std::move(strays), limit, reach, held, start.has_value(), end.has_value());
        best.outliers += strays.size() - r.quality.strays.size();
        worst = followed_max(d, strays);
    }
    if ((start || end) && worst > retry_deviation_m + reach) {
        SplicedFit s = spliced_fit(p, start, end, o, guides, limit, worst);
        s.fit.noise_sigma_m = best.noise_sigma_m;
        s.fit.outliers = best.outliers;
        if (s.worst_all < worst && explains_the_miss(s.worst_all, worst, reach, limit, r.quality) &&
            may_replace(best.alignment, s.fit.alignment)) {
            best = std::move(s.fit);
            worst = s.worst_followed;
            strays = std::move(s.strays);
        }
    }
    if (worst > limit && std::isfinite(worst) && patch(best, p, strays, limit, start, end, o, guides, patch_depth)) {
        worst = limit;
    }
    if (worst > limit) {
        // No railway-grade sequence came within reach of every mapped node
        // (tram corners, kinks): lines with clothoid corners keep every node
        // close and the ties exact, where they turn as a track can.
        Alignment corners = corner_polyline(p, start, end, corner_options);
        if (!std::isfinite(worst) || may_replace(best.alignment, corners)) {
            return {std::move(corners), ChainMethod::corners, 0, 0, best.noise_sigma_m, 0};
        }
        best.beyond_limit = true;
    }
    // The fit holds its end pose as a constraint, but a window whose every
    // model failed to meet it (least-squares fallback) may still miss, and
    // so may the design search's start (its frame ties a start by a weight;
    // only its polish holds it exactly: Cologne, 4 of 3,465 branch starts
    // up to 1.2 m and 0.46 rad off, or at another curvature): then that
    // stretch is rebuilt from the fit's pose there to the tied pose.
    if (best.method == ChainMethod::railway || best.method == ChainMethod::patched) {
        if (start && misses(start_miss(best.alignment, *start))) {
            best.alignment = splice_start(best.alignment, p, *start, miss_splice_length_m, corner_options, limit, !end);
            ++best.spliced_ends;
        }
        if (end && misses(end_miss(best.alignment, *end))) {
            best.alignment = splice_end(best.alignment, p, *end, miss_splice_length_m, corner_options, limit, !start);
            ++best.spliced_ends;
        }
        close_ring(best, p, start, end, limit);
        if (best.method == ChainMethod::railway && best.spliced_ends > 0) {
            best.method = ChainMethod::spliced;
        }
    }
    return best;
}

} // namespace railodd::geometry
