#include "design_fit.hpp"

#include "design_dp.hpp"
#include "outlier_nodes.hpp"
#include "reference_line.hpp"
#include "railodd/geometry/indexed_alignment.hpp"

#include <algorithm>
#include <cmath>

namespace railodd::geometry::fit {

namespace {

constexpr double reference_step_m = 2.0;
constexpr double smoothing_m = 30.0;

struct Pass {
    Alignment alignment;
    std::size_t parameters = 0;
    std::vector<double> distance; // of every node to the design, in the frame
};

double median(std::vector<double> v) {
    if (v.empty()) {
        return 0.0;
    }
    const auto mid = v.begin() + static_cast<std::ptrdiff_t>(v.size() / 2);
    std::nth_element(v.begin(), mid, v.end());
    return *mid;
}

// The noise scale of the residuals: their MAD, corrected for the
// parameters the fit spent on them.
double residual_sigma(const Pass& pass, const std::vector<double>& weight) {
    std::vector<double> kept;
    for (std::size_t i = 0; i < weight.size(); ++i) {
        if (weight[i] > 0.0) {
            kept.push_back(pass.distance[i]);
        }
    }
    const double n = static_cast<double>(kept.size());
    const double dof = std::max(1.0, n - static_cast<double>(pass.parameters));
    return std::clamp(1.4826 * median(kept) * std::sqrt(n / dof), 0.02, 10.0);
}

// Tukey's biweight of each node's distance; a far node whose neighbour is
// far too is kept whole: a stretch the design misses is the structure's
// fault, not the nodes'.
std::vector<double> robust_weights(const std::vector<double>& d, double sigma) {
    const double c = 4.685 * sigma;
    std::vector<double> w(d.size(), 1.0);
    for (std::size_t i = 0; i < d.size(); ++i) {
        const bool far = d[i] > c;
        const bool cluster = (i > 0 && d[i - 1] > c) || (i + 1 < d.size() && d[i + 1] > c);
        if (i == 0 || i + 1 == d.size() || (far && cluster)) {
            continue;
        }
        const double r = d[i] / c;
        w[i] = far ? 0.0 : (1 - r * r) * (1 - r * r);
    }
    return w;
}

Pass run_pass(const ReferenceLine& ref, const std::vector<Point2>& p, const std::vector<double>& weight, double sigma,
              const std::optional<Pose>& start, const std::optional<Pose>& end) {
    std::vector<FrameNode> nodes = develop(ref, p);
    for (std::size_t i = 0; i < nodes.size(); ++i) {
        nodes[i].w = weight[i] / (sigma * sigma);
    }
    DesignDpOptions o;
    o.s0 = nodes.front().t;
    o.s1 = nodes.back().t;
    if (start) {
        o.start = frame_state(ref, *start, &o.s0);
    }
    if (end) {
        o.end = frame_state(ref, *end, &o.s1);
    }
    o.s1 = std::max(o.s1, o.s0 + 1.0);
    o.parameter_penalty = 2.0 * std::log(std::max<double>(8.0, static_cast<double>(p.size())));
    const FrameDesign d = design_dp(nodes, o);
    Pass pass;
    pass.alignment = to_alignment(ref, d);
    pass.parameters = 3;
    for (const auto& e : d.elements) {
        pass.parameters += e.kind == ElementKind::transition ? 2 : 1;
    }
    for (const FrameNode& n : nodes) {
        pass.distance.push_back(std::abs(n.z - frame_z(d, n.t)));
    }
    return pass;
}

// The first pass's noise and weights: the outlier scan's (outlier_nodes.hpp),
// spikes left out, where enough nodes lie close together to tell a scale.
double first_guess(const std::vector<Point2>& p, std::vector<double>& weight) {
    const OutlierScan scan = find_outlier_nodes(p);
    for (std::size_t i = 0; i < p.size(); ++i) {
        weight[i] = scan.outlier[i] ? 0.0 : 1.0;
    }
    return scan.tested < 12 ? 0.3 : std::clamp(scan.noise_sigma_m, 0.05, 5.0);
}

} // namespace

FitResult fit_design(const std::vector<Point2>& p, const std::optional<Pose>& start, const std::optional<Pose>& end,
                     const FitOptions& options) {
    const bool fixed = options.noise_sigma_m > 0.0;
    std::vector<double> weight(p.size(), 1.0);
    const double guess = first_guess(p, weight);
    double sigma = fixed ? options.noise_sigma_m : guess;
    Pass pass = run_pass(smooth_reference(p, smoothing_m, reference_step_m), p, weight, sigma, start, end);
    for (int round = 0; round < 4; ++round) {
        const double next = fixed ? sigma : residual_sigma(pass, weight);
        const bool settled = round > 0 && std::abs(next - sigma) < 0.05 * sigma;
        sigma = next;
        weight = robust_weights(pass.distance, sigma);
        pass = run_pass(alignment_reference(pass.alignment, reference_step_m), p, weight, sigma, start, end);
        if (settled) {
            break;
        }
    }
    FitResult r;
    r.alignment = std::move(pass.alignment);
    std::vector<Point> all;
    for (const auto& q : p) {
        all.push_back({q.x, q.y});
    }
    r.quality = measure_fit(r.alignment, all);
    r.quality.noise_sigma_m = sigma;
    r.quality.windows = 1;
    r.quality.outliers = static_cast<std::size_t>(std::count(weight.begin(), weight.end(), 0.0));
    return r;
}

} // namespace railodd::geometry::fit
