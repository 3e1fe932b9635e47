// The alignment fit against ground truth (synthetic/alignment_truth): seeded
// designs drawn like OSM, fitted at default options, scored against the
// design. Run: build/bench/bench_alignment_truth [ROUTES] [SIGMA ...]
// [--outliers F] [--worst N] [--bound] [--first SEED] [--spacing
// osm|dense|sparse|very-sparse] [--method design|windowed] [--tied] [--chain] [--km L] (defaults: 300 routes from
// seed 1000, sigma 0.1 0.3 1.0, 1 % outliers, OSM-like node spacing
// (alignment_truth.hpp), the design search (the default fit); --worst lists the
// N worst routes and arcs; --bound
// adds each arc's Cramer-Rao bound, design_crlb.hpp; --tied ties both
// ends to the design's poses, as switches tie a chain; --chain builds the
// chain as the network's fit does, spliced, patched or by corners where the
// fit misses nodes, and counts each). Prints, per sigma, the
// deviation of the fit from the true centreline, the radius error of every
// design arc, elements against the design and spurious curvature sign
// changes: the figures issue 18's targets are stated in. --km draws routes
// at least L km long (default 8): how the fit's time grows with a chain.
#include "chain_fit.hpp"
#include "design_crlb.hpp"

#include "railodd/geometry/fit_alignment.hpp"
#include "railodd/truth/alignment_truth.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <optional>
#include <string>
#include <vector>

using namespace railodd;

namespace {

double quantile(std::vector<double> v, double q) {
    if (v.empty()) {
        return 0.0;
    }
    std::sort(v.begin(), v.end());
    return v[std::min(v.size() - 1, static_cast<std::size_t>(q * static_cast<double>(v.size())))];
}

struct Worst {
    double value = 0.0;
    std::string what;
};

// The `count` largest of `items`, printed one per line under `title`.
void print_worst(const char* title, std::vector<Worst> items, int count) {
    if (count <= 0) {
        return;
    }
    std::stable_sort(items.begin(), items.end(), [](const Worst& a, const Worst& b) { return a.value > b.value; });
    std::printf("  %s:\n", title);
    for (int i = 0; i < count && i < static_cast<int>(items.size()); ++i) {
        std::printf("    %s\n", items[static_cast<std::size_t>(i)].what.c_str());
    }
}

struct Options {
    int routes = 300;
    std::vector<double> sigmas;
    double outliers = 0.01;
    int worst = 0;
    bool bound = false;
    int first = 1000; // seed of the first route
    truth::Spacing spacing = truth::Spacing::osm;
    geometry::FitMethod method = geometry::FitMethod::design_search;
    bool tied = false; // both ends tied to the design's pose there, as a chain between two switches is
    bool chain = false; // as the network's fit builds a chain (fit_chain_points: splices, patches, corners)
    double length_m = truth::TruthOptions{}.length_m;
};

// The design's pose where a node's foot is: what a switch ties a chain's end to.
geometry::Pose pose_at(const geometry::Alignment& design, const geometry::Point& node) {
    return geometry::evaluate(design, geometry::project_point(design, node.x, node.y).s);
}

// A route fitted as the options say, and how its chain was built (-1: the
// fit alone).
struct RouteFit {
    geometry::Alignment alignment;
    double noise_m = 0.0;
    int method = -1;
    std::size_t patched = 0;
};

RouteFit fit_route(const Options& opt, const truth::TruthRoute& r) {
    geometry::FitOptions fo;
    fo.method = opt.method;
    std::optional<geometry::Pose> start, end;
    if (opt.tied) {
        start = pose_at(r.design, r.nodes.front());
        end = pose_at(r.design, r.nodes.back());
    }
    if (opt.chain) {
        geometry::ChainFit c = geometry::fit_chain_points(r.nodes, start, end, fo);
        return {std::move(c.alignment), c.noise_sigma_m, static_cast<int>(c.method), c.patched_stretches};
    }
    geometry::FitResult f = geometry::fit_alignment(r.nodes, start, end, fo);
    return {std::move(f.alignment), f.quality.noise_sigma_m, -1, 0};
}

// The arcs' Cramer-Rao bounds (relative sd of the curvature) against the
// fit's radius errors: how many arcs no fit could bring within 2 or 3 %
// (twice the bound beyond it), and the errors in units of the bound.
void print_bounds(const std::vector<double>& bound, const std::vector<double>& radius) {
    std::vector<double> ratio;
    std::size_t over2 = 0, over3 = 0;
    for (std::size_t i = 0; i < bound.size() && i < radius.size(); ++i) {
        ratio.push_back(radius[i] / bound[i]);
        over2 += 2 * bound[i] > 0.02 ? 1 : 0;
        over3 += 2 * bound[i] > 0.03 ? 1 : 0;
    }
    const double n = static_cast<double>(std::max<std::size_t>(1, bound.size()));
    std::printf("  curvature bound (relative sd): p50 %.2f %%, p95 %.2f %%; arcs whose 2-sd bound exceeds 2 %%: %.1f %%, "
                "3 %%: %.1f %%; error / bound p50 %.2f, p95 %.2f\n",
                100 * quantile(bound, 0.5), 100 * quantile(bound, 0.95), 100.0 * static_cast<double>(over2) / n,
                100.0 * static_cast<double>(over3) / n, quantile(ratio, 0.5), quantile(ratio, 0.95));
}

// One route's line for the worst routes, and one per arc for the worst arcs.
void add_worst(int seed, const truth::TruthRoute& r, const truth::TruthScore& s, double noise_m,
               std::vector<Worst>& worst_routes, std::vector<Worst>& worst_arcs) {
    char line[256];
    std::snprintf(line, sizeof line,
                  "seed %d: max %.2f m at s %.0f of %.0f, p95 %.2f m, %zu / %zu elements, noise %.2f m", seed,
                  s.deviation_max_m, s.deviation_max_at_m, geometry::length(r.design), s.deviation_p95_m,
                  s.fit_elements, s.design_elements, noise_m);
    worst_routes.push_back({s.deviation_max_m, line});
    for (std::size_t a = 0; a < r.arcs.size() && a < s.radius_errors.size(); ++a) {
        std::snprintf(line, sizeof line, "seed %d arc at s %.0f: R %.0f m, %.0f m long, error %.1f %%", seed,
                      r.arcs[a].s0, 1.0 / r.arcs[a].curvature, r.arcs[a].s1 - r.arcs[a].s0, 100 * s.radius_errors[a]);
        worst_arcs.push_back({s.radius_errors[a], line});
    }
}

void run_sigma(const Options& opt, double sigma) {
    const int routes = opt.routes, worst = opt.worst;
    const double outliers = opt.outliers;
    std::vector<double> p50, p95, dmax, radius, ratio, noise, bound, radius_bounded;
    std::vector<Worst> worst_routes, worst_arcs;
    long spurious = 0, routes_spurious = 0, over_1m = 0, over_limit = 0;
    long methods[4] = {0, 0, 0, 0}; // routes per geometry::ChainMethod
    std::size_t patched = 0;
    const double limit = truth::deviation_limit(sigma, opt.spacing);
    double km = 0.0, seconds = 0.0;
    for (int i = 0; i < routes; ++i) {
        truth::TruthOptions o;
        o.sigma_m = sigma;
        o.outlier_fraction = outliers;
        o.spacing = opt.spacing;
        o.length_m = opt.length_m;
        const int seed = opt.first + i;
        const truth::TruthRoute r = truth::make_route(static_cast<std::uint64_t>(seed), o);
        const auto t0 = std::chrono::steady_clock::now();
        const RouteFit fit = fit_route(opt, r);
        seconds += std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
        const truth::TruthScore s = truth::score(r, fit.alignment);
        noise.push_back(fit.noise_m / sigma);
        if (fit.method >= 0) {
            ++methods[fit.method];
            patched += fit.patched;
        }
        km += geometry::length(r.design) / 1000.0;
        p50.push_back(s.deviation_p50_m);
        p95.push_back(s.deviation_p95_m);
        dmax.push_back(s.deviation_max_m);
        over_1m += s.deviation_max_m > 1.0 ? 1 : 0;
        over_limit += s.deviation_max_m > limit ? 1 : 0;
        radius.insert(radius.end(), s.radius_errors.begin(), s.radius_errors.end());
        if (opt.bound) {
            const std::vector<double> b = bench::arc_curvature_bounds(r, sigma);
            if (b.size() == s.radius_errors.size()) {
                bound.insert(bound.end(), b.begin(), b.end());
                radius_bounded.insert(radius_bounded.end(), s.radius_errors.begin(), s.radius_errors.end());
            }
        }
        add_worst(seed, r, s, fit.noise_m, worst_routes, worst_arcs);
        ratio.push_back(static_cast<double>(s.fit_elements) / static_cast<double>(s.design_elements));
        spurious += std::max(0L, s.spurious_sign_changes);
        routes_spurious += s.spurious_sign_changes > 0 ? 1 : 0;
    }
    const auto within = [&](double e) {
        return 100.0 * static_cast<double>(std::count_if(radius.begin(), radius.end(), [e](double x) { return x <= e; })) /
               static_cast<double>(std::max<std::size_t>(1, radius.size()));
    };
    std::printf("sigma %.1f m, %.1f %% outlier nodes: %d routes, %.0f km, %zu design arcs, fit %.1f s (%.0f km/s)\n",
                sigma, 100 * outliers, routes, km, radius.size(), seconds, km / std::max(seconds, 1e-9));
    std::printf("  deviation from the true centreline (m): route p50 median %.3f; route p95 median %.3f, p95 %.3f; "
                "route max median %.2f, p95 %.2f, max %.2f; routes with max > 1 m: %ld; over the %.1f m limit: %ld\n",
                quantile(p50, 0.5), quantile(p95, 0.5), quantile(p95, 0.95), quantile(dmax, 0.5), quantile(dmax, 0.95),
                quantile(dmax, 1.0), over_1m, limit, over_limit);
    std::printf("  arc radius error: p50 %.1f %%, p95 %.1f %%, max %.1f %%; within 2 %%: %.1f %%, within 3 %%: %.1f %%, "
                "within 8 %%: %.1f %%\n",
                100 * quantile(radius, 0.5), 100 * quantile(radius, 0.95), 100 * quantile(radius, 1.0), within(0.02),
                within(0.03), within(0.08));
    std::printf("  estimated noise / sigma: p5 %.2f, median %.2f, p95 %.2f\n", quantile(noise, 0.05),
                quantile(noise, 0.5), quantile(noise, 0.95));
    std::printf("  elements / design: median %.2f, p95 %.2f, max %.2f; spurious sign changes: %ld on %ld routes\n",
                quantile(ratio, 0.5), quantile(ratio, 0.95), quantile(ratio, 1.0), spurious, routes_spurious);
    if (opt.chain) {
        std::printf("  chains: railway %ld, spliced %ld, patched %ld (%zu stretches), corners %ld\n", methods[0], methods[1],
                    methods[2], patched, methods[3]);
    }
    if (opt.bound) {
        print_bounds(bound, radius_bounded);
    }
    print_worst("routes of largest max deviation", worst_routes, worst);
    print_worst("arcs of largest radius error", worst_arcs, worst);
}

} // namespace

int main(int argc, char** argv) {
    Options o;
    o.routes = argc > 1 ? std::max(1, std::atoi(argv[1])) : 300;
    for (int i = 2; i < argc; ++i) {
        const std::string a = argv[i];
        if (a == "--outliers" && i + 1 < argc) {
            o.outliers = std::atof(argv[++i]);
        } else if (a == "--worst" && i + 1 < argc) {
            o.worst = std::atoi(argv[++i]);
        } else if (a == "--first" && i + 1 < argc) {
            o.first = std::atoi(argv[++i]);
        } else if (a == "--spacing" && i + 1 < argc) {
            const std::string v = argv[++i];
            const std::optional<truth::Spacing> named = truth::spacing_named(v);
            if (!named) {
                std::fprintf(stderr, "--spacing %s: not a spacing (%s)\n", v.c_str(), truth::spacing_names().c_str());
                std::exit(2);
            }
            o.spacing = *named;
        } else if (a == "--method" && i + 1 < argc) {
            o.method = std::string(argv[++i]) == "design" ? geometry::FitMethod::design_search : geometry::FitMethod::windowed;
        } else if (a == "--km" && i + 1 < argc) {
            o.length_m = 1000.0 * std::atof(argv[++i]);
        } else if (a == "--tied") {
            o.tied = true;
        } else if (a == "--chain") {
            o.chain = true;
        } else if (a == "--bound") {
            o.bound = true;
        } else {
            o.sigmas.push_back(std::atof(argv[i]));
        }
    }
    if (o.sigmas.empty()) {
        o.sigmas = {0.1, 0.3, 1.0};
    }
    for (const double s : o.sigmas) {
        run_sigma(o, s);
    }
    return 0;
}
