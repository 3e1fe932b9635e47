#include "railodd/truth/alignment_truth.hpp"

#include "railodd/geometry/design_summary.hpp"
#include "railodd/geometry/indexed_alignment.hpp"
#include "rng.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <utility>

namespace railodd::truth {

namespace {

using geometry::Alignment;
using geometry::make_arc;
using geometry::make_line;
using geometry::make_spiral;
using sample::Rng;

// Design speed of a curve (km/h) from its radius: 150 mm cant plus 100 mm
// deficiency, V = sqrt(R * 250 / 11.8), at most 250 km/h; the transition
// length grows with it (about 0.45 m per km/h, 25 to 250 m).
double transition_length(double radius) {
    const double v = std::min(250.0, std::sqrt(radius * 250.0 / 11.8));
    return std::clamp(std::round(0.45 * v), 25.0, 250.0);
}

// An arc length (40-1200 m) whose arc turns at most `turn` radians.
double arc_length(Rng& rng, double radius, double turn) {
    return std::max(40.0, std::min(rng.uniform(40.0, 1200.0), radius * turn));
}

double radius(Rng& rng) { return std::exp(rng.uniform(std::log(150.0), std::log(6000.0))); }

void add_arc(TruthRoute& r, double length, double k) {
    const double s0 = geometry::length(r.design);
    r.design.primitives.push_back(make_arc(length, k));
    r.arcs.push_back({s0, s0 + length, k});
}

// How far the design has turned from its start heading.
double turned(const Alignment& a) {
    double t = 0.0;
    for (const auto& p : a.primitives) {
        t += 0.5 * (p.curv_start + p.curv_end) * p.length;
    }
    return t;
}

// One curve from straight to straight: simple, reverse (two curves of
// opposite hand meeting at an inflection) or compound (two radii of one hand
// joined by a transition). Each hand turns at most about 80 degrees and the
// route keeps within about 100 degrees of its first heading, as a line
// between two places does: a design never crosses itself.
void add_curve(TruthRoute& r, Rng& rng) {
    constexpr double budget = 1.4; // rad per curve
    auto& p = r.design.primitives;
    const double heading = turned(r.design);
    const double hand = heading > 0.3 ? -1.0 : heading < -0.3 ? 1.0 : (rng.uniform() < 0.5 ? -1.0 : 1.0);
    const double r1 = radius(rng);
    const double k1 = hand / r1;
    const double t1 = transition_length(r1);
    p.push_back(make_spiral(t1, 0.0, k1));
    const double a1 = arc_length(rng, r1, std::max(0.05, budget - t1 / r1));
    add_arc(r, a1, k1);
    const double kind = rng.uniform();
    if (kind < 0.15) { // reverse
        const double r2 = radius(rng);
        const double k2 = -hand / r2;
        p.push_back(make_spiral(t1, k1, 0.0));
        const double t2 = transition_length(r2);
        p.push_back(make_spiral(t2, 0.0, k2));
        add_arc(r, arc_length(rng, r2, std::max(0.05, budget - t2 / r2)), k2);
        p.push_back(make_spiral(t2, k2, 0.0));
    } else if (kind < 0.35) { // compound: a second radius at least 30 % apart
        const double r2 = std::max(150.0, rng.uniform() < 0.5 ? r1 * rng.uniform(1.3, 2.5) : r1 / rng.uniform(1.3, 2.5));
        const double k2 = hand / r2;
        const double t12 = std::abs(t1 - transition_length(r2)) + 20.0;
        p.push_back(make_spiral(t12, k1, k2));
        const double t2 = transition_length(r2);
        const double left = budget - t1 / r1 - a1 / r1 - t12 * 0.5 * (1.0 / r1 + 1.0 / r2) - 0.5 * t2 / r2;
        add_arc(r, arc_length(rng, r2, std::max(0.05, left)), k2);
        p.push_back(make_spiral(t2, k2, 0.0));
    } else {
        p.push_back(make_spiral(t1, k1, 0.0));
    }
}

// Where the next curved primitive starts at or after s.
double next_curve_start(const Alignment& a, const std::vector<double>& starts, double s) {
    for (std::size_t i = 0; i < a.primitives.size(); ++i) {
        if (a.primitives[i].kind != geometry::PrimitiveKind::line && starts[i] + a.primitives[i].length > s) {
            return std::max(s, starts[i]);
        }
    }
    return geometry::length(a);
}

bool curved_at(const Alignment& a, const std::vector<double>& starts, double s) {
    const auto it = std::upper_bound(starts.begin(), starts.end(), s);
    const std::size_t i = it == starts.begin() ? 0 : static_cast<std::size_t>(it - starts.begin()) - 1;
    return a.primitives[i].kind != geometry::PrimitiveKind::line;
}

// Mapped nodes at the options' spacing (on straights, one soon after a curve
// begins, as mappers densify there); lateral scatter and
// outliers across the line. The first and last nodes are never outliers: a
// chain ends at a vertex (switch, buffer stop) that other ways share, whose
// misplacement would bend them all.
void draw(TruthRoute& r, Rng& rng, const TruthOptions& o) {
    const geometry::IndexedAlignment ia(r.design);
    const std::vector<double> starts = geometry::primitive_s(r.design);
    const double total = ia.length();
    for (double s = 0.0;;) {
        const geometry::Pose p = ia.evaluate(s);
        const bool out = rng.uniform() < o.outlier_fraction && s > 0.0 && s < total;
        const double off = out ? (rng.uniform() < 0.5 ? -1.0 : 1.0) * rng.uniform(3.0, 10.0) : o.sigma_m * rng.normal();
        r.nodes.push_back({p.x - off * std::sin(p.hdg), p.y + off * std::cos(p.hdg)});
        r.outlier.push_back(out);
        if (s >= total) {
            return;
        }
        double step = 0.0;
        if (o.spacing == Spacing::dense) {
            step = rng.uniform(5.0, 15.0);
        } else if (curved_at(r.design, starts, s)) {
            step = o.spacing == Spacing::sparse        ? rng.uniform(25.0, 60.0)
                   : o.spacing == Spacing::very_sparse ? rng.uniform(25.0, 200.0)
                                                       : rng.uniform(5.0, 40.0);
        } else {
            // The two draws' order is the compiler's (arguments of one
            // call): gcc and clang draw different routes from one seed.
            // Kept so, or every figure in the docs would move.
            step = std::min(o.spacing == Spacing::sparse        ? rng.uniform(100.0, 400.0)
                            : o.spacing == Spacing::very_sparse ? rng.uniform(250.0, 1250.0)
                                                                : rng.uniform(50.0, 250.0),
                            next_curve_start(r.design, starts, s) - s + rng.uniform(2.0, 15.0));
        }
        s = std::min(total, s + step);
    }
}

double quantile(std::vector<double> v, double q) {
    if (v.empty()) {
        return 0.0;
    }
    const auto k = static_cast<std::size_t>(std::min<double>(static_cast<double>(v.size() - 1),
                                                             std::floor(q * static_cast<double>(v.size()))));
    std::nth_element(v.begin(), v.begin() + static_cast<std::ptrdiff_t>(k), v.end());
    return v[k];
}

} // namespace

TruthRoute make_route(std::uint64_t seed, const TruthOptions& options) {
    Rng rng(seed);
    TruthRoute r;
    r.design.start = {rng.uniform(-500.0, 500.0), rng.uniform(-500.0, 500.0), rng.uniform(-3.14, 3.14), 0.0};
    r.design.primitives.push_back(make_line(rng.uniform(100.0, 2000.0)));
    while (geometry::length(r.design) < options.length_m) {
        add_curve(r, rng);
        r.design.primitives.push_back(make_line(rng.uniform(100.0, 2000.0)));
    }
    r.sign_changes = sign_changes(r.design);
    draw(r, rng, options);
    return r;
}

std::size_t sign_changes(const Alignment& a) { return geometry::curvature_sign_changes(geometry::IndexedAlignment(a)); }

namespace {

// The command line's name of each spacing, in the enum's order.
constexpr std::pair<const char*, Spacing> spacing_table[] = {
    {"osm", Spacing::osm}, {"dense", Spacing::dense}, {"sparse", Spacing::sparse}, {"very-sparse", Spacing::very_sparse}};

} // namespace

std::optional<Spacing> spacing_named(const std::string& name) {
    for (const auto& [n, spacing] : spacing_table) {
        if (name == n) {
            return spacing;
        }
    }
    return std::nullopt;
}

std::string spacing_names() {
    std::string out;
    for (const auto& [n, spacing] : spacing_table) {
        out += out.empty() ? n : std::string(", ") + n;
    }
    return out;
}

double deviation_limit(double sigma, Spacing spacing) {
    if (sigma <= 0.3) {
        return spacing == Spacing::sparse || spacing == Spacing::very_sparse ? 1.5 : 1.0;
    }
    return sigma <= 1.0 ? 2.5 : 5.0;
}

TruthScore score(const TruthRoute& route, const Alignment& fit) {
    TruthScore sc;
    const geometry::IndexedAlignment truth(route.design);
    const geometry::IndexedAlignment fitted(fit);
    std::vector<double> dev;
    for (double s = 0.0; s <= truth.length(); s += 2.0) {
        const geometry::Pose p = truth.evaluate(s);
        dev.push_back(fitted.project(p.x, p.y).distance);
    }
    sc.deviation_p50_m = quantile(dev, 0.5);
    sc.deviation_p95_m = quantile(dev, 0.95);
    if (!dev.empty()) {
        const auto worst = std::max_element(dev.begin(), dev.end());
        sc.deviation_max_m = *worst;
        sc.deviation_max_at_m = 2.0 * static_cast<double>(worst - dev.begin());
    }
    for (const auto& arc : route.arcs) {
        const geometry::Pose mid = truth.evaluate(0.5 * (arc.s0 + arc.s1));
        const double k = fitted.evaluate(fitted.project(mid.x, mid.y).s).curvature;
        // A fit curving the other way or not at all is off by the whole radius and more.
        sc.radius_errors.push_back(k * arc.curvature > 0.0 ? std::abs(arc.curvature / k - 1.0) : 10.0);
    }
    sc.design_elements = route.design.primitives.size();
    sc.fit_elements = fit.primitives.size();
    sc.spurious_sign_changes = static_cast<long>(sign_changes(fit)) - static_cast<long>(route.sign_changes);
    return sc;
}

} // namespace railodd::truth
