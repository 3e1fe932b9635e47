#include "design_guide.hpp"

#include "reference_line.hpp"

#include <algorithm>
#include <cmath>
#include <optional>

namespace railodd::geometry::fit {

namespace {

constexpr double min_offset_m = 2.5, max_offset_m = 6.5; // double track: 3.5-6 m between centres
constexpr double min_alignment = 0.9995;                  // cosine of the headings' angle: 1.8 degrees
// A stretch beside the guide at least this long, its offset within this
// much of its median: a branch leaving a switch runs within 6.5 m of its
// through track for a few tens of metres at a turnout's angle, and a
// crossover passes; neither is a parallel track.
constexpr double min_run_m = 100.0, offset_spread_m = 0.75;
// The chain's own last design within this of the guide's curvature (1/m,
// and a share of it): measured on VDE 8.2, Cologne, Liechtenstein and Lauf
// (docs/BENCHMARKS.md); without the test a prior everywhere took
// Liechtenstein's double-track difference from 14.5 to 25.7 %.
constexpr double own_tolerance = 1e-4, own_share = 0.25;

struct Sample {
    bool beside = false;
    double k = 0.0, offset = 0.0;
    std::size_t guide = 0; // which guide, and the foot's arc length on it
    double s = 0.0;
};

// The concentric curvature a guide asks for at reference point `at`, if it
// runs beside it.
Sample guided_curvature(const IndexedAlignment& g, const Pose& at) {
    // Many samples are nowhere near: no Newton refine for them.
    const std::optional<Projection> near = g.project_near(at.x, at.y, max_offset_m);
    if (!near) {
        return {};
    }
    const Projection& pr = *near;
    if (!(pr.s > 1e-6 && pr.s < g.length() - 1e-6) || std::abs(pr.offset) < min_offset_m ||
        std::abs(pr.offset) > max_offset_m) {
        return {};
    }
    const Pose p = g.evaluate(pr.s);
    const double along = std::cos(p.hdg - at.hdg);
    if (std::abs(along) < min_alignment) {
        return {};
    }
    const double concentric = p.curvature / (1.0 - pr.offset * p.curvature);
    return {true, along > 0.0 ? concentric : -concentric, pr.offset, 0, pr.s};
}

Sample beside_any(const std::vector<IndexedAlignment>& guides, const Pose& at) {
    for (std::size_t g = 0; g < guides.size(); ++g) {
        Sample s = guided_curvature(guides[g], at);
        if (s.beside) {
            s.guide = g;
            return s;
        }
    }
    return {};
}

ElementKind kind_of(const Primitive& p) {
    return p.kind == PrimitiveKind::line ? ElementKind::line
                                         : (p.kind == PrimitiveKind::arc ? ElementKind::arc : ElementKind::transition);
}

// The guide's element joints (arc lengths), ascending.
std::vector<double> joints(const IndexedAlignment& g) {
    std::vector<double> j;
    double s = 0.0;
    for (const Primitive& p : g.alignment().primitives) {
        s += p.length;
        j.push_back(s);
    }
    j.pop_back(); // the end is no joint
    return j;
}

// The chainages across from a guide's joints, between samples beside it,
// with its elements' kinds either side in this chain's direction; a run
// of samples beside one guide is one run.
std::vector<GuideCurvature::Joint> joints_across(const std::vector<double>& ts, const std::vector<Sample>& samples,
                                                 const std::vector<IndexedAlignment>& guides) {
    std::vector<std::vector<double>> at(guides.size());
    std::vector<GuideCurvature::Joint> out;
    std::size_t run = 0;
    for (std::size_t i = 0; i + 1 < samples.size(); ++i) {
        const Sample& a = samples[i];
        const Sample& b = samples[i + 1];
        if (!a.beside || !b.beside || a.guide != b.guide) {
            run += a.beside ? 1 : 0;
            continue;
        }
        if (at[a.guide].empty()) {
            at[a.guide] = joints(guides[a.guide]);
        }
        const std::vector<double>& j = at[a.guide];
        const auto& prim = guides[a.guide].alignment().primitives;
        const double lo = std::min(a.s, b.s), hi = std::max(a.s, b.s);
        for (auto it = std::upper_bound(j.begin(), j.end(), lo); it != j.end() && *it <= hi; ++it) {
            const auto k = static_cast<std::size_t>(it - j.begin());
            const ElementKind first = kind_of(prim[k]), second = kind_of(prim[k + 1]);
            const bool along = b.s > a.s;
            out.push_back({ts[i] + (ts[i + 1] - ts[i]) * (*it - a.s) / (b.s - a.s), along ? first : second,
                           along ? second : first, run});
        }
    }
    return out;
}

// Runs of samples beside a guide kept where they are long and steady.
void keep_steady_runs(std::vector<Sample>& samples, double step) {
    for (std::size_t i = 0; i < samples.size();) {
        if (!samples[i].beside) {
            ++i;
            continue;
        }
        std::size_t j = i;
        std::vector<double> off;
        while (j < samples.size() && samples[j].beside) {
            off.push_back(samples[j++].offset);
        }
        std::nth_element(off.begin(), off.begin() + static_cast<std::ptrdiff_t>(off.size() / 2), off.end());
        const double median = off[off.size() / 2];
        std::size_t steady = 0;
        for (std::size_t q = i; q < j; ++q) {
            samples[q].beside = std::abs(samples[q].offset - median) <= offset_spread_m;
            steady += samples[q].beside ? 1 : 0;
        }
        if (static_cast<double>(steady) * step < min_run_m) {
            for (std::size_t q = i; q < j; ++q) {
                samples[q].beside = false;
            }
        }
        i = j;
    }
}

// The curvature of a structure's elements at t (their ends' curvatures).
double curvature_at(const std::vector<FrameElement>& el, double t) {
    auto it = std::upper_bound(el.begin(), el.end(), t, [](double x, const FrameElement& e) { return x < e.s1; });
    if (it == el.end()) {
        it = el.end() - 1;
    }
    const double f = it->s1 > it->s0 ? std::clamp((t - it->s0) / (it->s1 - it->s0), 0.0, 1.0) : 0.0;
    return it->k0 + f * (it->k1 - it->k0);
}

} // namespace

GuideCurvature::GuideCurvature(const ReferenceLine& ref, double t0, double t1, const std::vector<IndexedAlignment>& guides,
                               const std::vector<FrameElement>& own, double weight, double step) {
    std::vector<double> ts;
    std::vector<Sample> beside;
    for (double t = t0 + 0.5 * step; t < t1; t += step) {
        ts.push_back(t);
        beside.push_back(beside_any(guides, ref.at(t)));
    }
    // The joints wherever the tracks run side by side: a rival structure is
    // judged by the nodes (design_guided.cpp); the prior only where the
    // chain's own design agrees.
    std::vector<Sample> samples = beside;
    keep_steady_runs(beside, step);
    joints_ = joints_across(ts, beside, guides);
    for (std::size_t i = 0; i < ts.size(); ++i) {
        Sample& s = samples[i];
        if (s.beside && !own.empty() && std::abs(curvature_at(own, ts[i]) - s.k) > own_tolerance + own_share * std::abs(s.k)) {
            s.beside = false;
        }
    }
    keep_steady_runs(samples, step);
    for (std::size_t i = 0; i < ts.size(); ++i) {
        const double w = samples[i].beside ? weight * step : 0.0, g = samples[i].k;
        append(ts[i], w, w * g, w * g * g);
    }
    mirrored_ = std::make_shared<const GuideCurvature>(mirror());
}

void GuideCurvature::append(double t, double w, double wg, double wgg) {
    Sums s = sums_.back();
    s.w += w;
    s.wt += w * t;
    s.wtt += w * t * t;
    s.wg += wg;
    s.wgt += wg * t;
    s.wgg += wgg;
    t_.push_back(t);
    sums_.push_back(s);
}

std::pair<std::size_t, std::size_t> GuideCurvature::samples_in(double a, double b) const {
    // The samples lie a step apart: the index is read off and then stepped
    // to the first at or after x (lower_bound's answer; the chainages were
    // summed step by step). A binary search per element cost 6 % of a fit.
    const double step = t_.size() > 1 ? (t_.back() - t_.front()) / static_cast<double>(t_.size() - 1) : 1.0;
    const auto at = [&](double x) {
        const double guess = t_.empty() ? 0.0 : std::ceil((x - t_.front()) / step);
        auto i = static_cast<std::size_t>(std::clamp(guess, 0.0, static_cast<double>(t_.size())));
        while (i < t_.size() && t_[i] < x) {
            ++i;
        }
        while (i > 0 && t_[i - 1] >= x) {
            --i;
        }
        return i;
    };
    return {at(a), at(b)};
}

GuideCurvature GuideCurvature::mirror() const {
    GuideCurvature m;
    for (std::size_t j = t_.size(); j-- > 0;) {
        // Sample j's own terms, at chainage -t.
        const Sums& a = sums_[j];
        const Sums& b = sums_[j + 1];
        m.append(-t_[j], b.w - a.w, b.wg - a.wg, b.wgg - a.wgg);
    }
    for (auto it = joints_.rbegin(); it != joints_.rend(); ++it) {
        m.joints_.push_back({-it->t, it->after, it->before, it->run});
    }
    return m;
}

void GuideCurvature::add(design::Quad& f, double s, double a, double b) const {
    if (empty() || !(b > a)) {
        return;
    }
    const auto [i, j] = samples_in(a, b);
    if (j <= i) {
        return;
    }
    const Sums& lo = sums_[i];
    const Sums& hi = sums_[j];
    const double w = hi.w - lo.w;
    if (!(w > 0.0)) {
        return;
    }
    // In the element's scaled chainage u = (t - s) / S.
    const double S = design::S;
    const double wt = hi.wt - lo.wt, wtt = hi.wtt - lo.wtt, wg = hi.wg - lo.wg, wgt = hi.wgt - lo.wgt;
    const double wu = (wt - s * w) / S, wuu = (wtt - 2.0 * s * wt + s * s * w) / (S * S);
    const double wgu = (wgt - s * wg) / S;
    const double S2 = S * S, S4 = S2 * S2;
    const bool k = f.free & 4u, slope = f.free & 8u;
    if (k) {
        f.P(2, 2) += w / S4;
        f.q(2) += wg / S2;
    }
    if (k && slope) {
        f.P(2, 3) += wu / S4;
        f.P(3, 2) += wu / S4;
    }
    if (slope) {
        f.P(3, 3) += wuu / S4;
        f.q(3) += wgu / S2;
    }
    f.c += hi.wgg - lo.wgg;
}

GuideCurvature::Mean GuideCurvature::over(double a, double b) const {
    const auto [i, j] = samples_in(a, b);
    const double w = j > i ? sums_[j].w - sums_[i].w : 0.0;
    if (!(w > 0.0)) {
        return {};
    }
    return {w, (sums_[j].wg - sums_[i].wg) / w, (sums_[j].wt - sums_[i].wt) / w};
}

} // namespace railodd::geometry::fit
