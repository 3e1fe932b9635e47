// Cached evaluation and nearest-point search on one alignment.
#include "railodd/geometry/indexed_alignment.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>
#include <utility>

namespace railodd::geometry {

namespace {

struct Residual {
    double along;   // (Q - P) . T: positive while the point lies ahead
    double slope;   // d(along)/ds
    double offset;  // (Q - P) . N, left positive
    double distance;
};

Residual residual(const Pose& p, double x, double y) {
    const double dx = x - p.x;
    const double dy = y - p.y;
    const double c = std::cos(p.hdg);
    const double s = std::sin(p.hdg);
    const double offset = -dx * s + dy * c;
    return {dx * c + dy * s, -1.0 + p.curvature * offset, offset, std::hypot(dx, dy)};
}

} // namespace

IndexedAlignment::IndexedAlignment(Alignment alignment, double sample_step)
    : alignment_(std::move(alignment)), step_(sample_step) {
    if (!(sample_step > 0.0) || !std::isfinite(sample_step)) {
        throw std::invalid_argument("IndexedAlignment: sample step must be positive, got " +
                                    std::to_string(sample_step));
    }
    validate(alignment_);
    starts_ = primitive_starts(alignment_);
    s_starts_ = primitive_s(alignment_);
    length_ = geometry::length(alignment_);

    for (std::size_t i = 0; i < starts_.size(); ++i) {
        const Primitive& p = alignment_.primitives[i];
        const auto n = std::max<std::size_t>(1, static_cast<std::size_t>(std::ceil(p.length / sample_step)));
        for (std::size_t j = 0; j < n; ++j) {
            const double ds = p.length * static_cast<double>(j) / static_cast<double>(n);
            const Pose q = geometry::evaluate(starts_[i], p, ds);
            samples_.push_back({s_starts_[i] + ds, q.x, q.y});
        }
    }
    const Pose end = evaluate(length_);
    samples_.push_back({length_, end.x, end.y});
    build_tree();
}

IndexedAlignment IndexedAlignment::for_evaluation(Alignment alignment) {
    return IndexedAlignment(std::move(alignment), std::numeric_limits<double>::max());
}

void IndexedAlignment::build_tree() {
    const std::size_t blocks = (samples_.size() + block_size - 1) / block_size;
    leaves_ = 1;
    while (leaves_ < blocks) {
        leaves_ *= 2;
    }
    const double inf = std::numeric_limits<double>::infinity();
    tree_.assign(2 * leaves_, Box{inf, inf, -inf, -inf}); // empty: infinitely far
    for (std::size_t b = 0; b < blocks; ++b) {
        Box& q = tree_[leaves_ + b];
        for (std::size_t i = b * block_size; i < std::min(samples_.size(), (b + 1) * block_size); ++i) {
            q.x0 = std::min(q.x0, samples_[i].x);
            q.y0 = std::min(q.y0, samples_[i].y);
            q.x1 = std::max(q.x1, samples_[i].x);
            q.y1 = std::max(q.y1, samples_[i].y);
        }
    }
    for (std::size_t n = leaves_ - 1; n >= 1; --n) {
        const Box& l = tree_[2 * n];
        const Box& r = tree_[2 * n + 1];
        tree_[n] = {std::min(l.x0, r.x0), std::min(l.y0, r.y0), std::max(l.x1, r.x1), std::max(l.y1, r.y1)};
    }
}

std::size_t IndexedAlignment::primitive_at(double s) const {
    // upper_bound hands a joint to the later primitive and skips zero-length ones.
    const auto it = std::upper_bound(s_starts_.begin(), s_starts_.end(), s);
    return it == s_starts_.begin() ? 0 : static_cast<std::size_t>(it - s_starts_.begin()) - 1;
}

Pose IndexedAlignment::evaluate(double s) const {
    if (alignment_.primitives.empty()) {
        Pose p = alignment_.start;
        p.curvature = 0.0;
        return p;
    }
    s = std::clamp(s, 0.0, length_);
    const std::size_t i = primitive_at(s);
    return geometry::evaluate(starts_[i], alignment_.primitives[i], s - s_starts_[i]);
}

double IndexedAlignment::refine(double x, double y, double lo, double hi, double guess) const {
    const Residual r_lo = residual(evaluate(lo), x, y);
    const Residual r_hi = residual(evaluate(hi), x, y);
    if (r_lo.along <= 0.0 && r_hi.along >= 0.0) {
        return r_lo.distance <= r_hi.distance ? lo : hi; // a local maximum lies between
    }
    if (r_lo.along <= 0.0) {
        return lo;
    }
    if (r_hi.along >= 0.0) {
        return hi;
    }
    // The bracket keeps along(lo) > 0 > along(hi); Newton steps that leave it
    // (near a curvature jump, or far from the curve) fall back to bisection.
    double s = guess;
    for (int iter = 0; iter < 100; ++iter) {
        const Residual r = residual(evaluate(s), x, y);
        if (r.along == 0.0) {
            return s;
        }
        (r.along > 0.0 ? lo : hi) = s;
        double next = 0.5 * (lo + hi);
        if (r.slope < 0.0) {
            const double newton = s - r.along / r.slope;
            if (newton > lo && newton < hi) {
                next = newton;
            }
        }
        const bool done = std::abs(next - s) < 1e-11 || hi - lo < 1e-11;
        s = next;
        if (done) {
            break;
        }
    }
    return s;
}

std::size_t IndexedAlignment::nearest_sample(double x, double y, std::size_t first, std::size_t last) const {
    // The nearest sample in [first, last], the lowest index among equals:
    // exactly what a scan of every sample finds, but a subtree whose box lies
    // farther than the best so far is skipped, and the nearer child is
    // searched first. A flat scan of the blocks made measuring a long
    // chain's fit quadratic in its length.
    std::size_t best = first;
    double best_d2 = std::numeric_limits<double>::infinity();
    const std::size_t b0 = first / block_size, b1 = last / block_size;
    auto box_d2 = [&](std::size_t n) {
        const Box& q = tree_[n];
        const double dx = std::max({q.x0 - x, 0.0, x - q.x1});
        const double dy = std::max({q.y0 - y, 0.0, y - q.y1});
        return dx * dx + dy * dy;
    };
    auto scan_block = [&](std::size_t b) {
        for (std::size_t i = std::max(first, b * block_size); i < std::min(last + 1, (b + 1) * block_size); ++i) {
            const double dx = samples_[i].x - x;
            const double dy = samples_[i].y - y;
            const double d2 = dx * dx + dy * dy;
            if (d2 < best_d2 || (d2 == best_d2 && i < best)) {
                best_d2 = d2;
                best = i;
            }
        }
    };
    // Depth-first with an explicit stack (at most two entries per level);
    // node n covers blocks [lo, hi].
    struct Visit {
        std::size_t node, lo, hi;
        double d2;
    };
    std::array<Visit, 2 * 64> stack;
    std::size_t top = 0;
    stack[top++] = {1, 0, leaves_ - 1, box_d2(1)};
    while (top > 0) {
        const Visit v = stack[--top];
        if (v.hi < b0 || v.lo > b1 || v.d2 > best_d2) {
            continue;
        }
        if (v.node >= leaves_) {
            scan_block(v.lo);
            continue;
        }
        const std::size_t mid = v.lo + (v.hi - v.lo) / 2;
        Visit l{2 * v.node, v.lo, mid, box_d2(2 * v.node)};
        Visit r{2 * v.node + 1, mid + 1, v.hi, box_d2(2 * v.node + 1)};
        if (r.d2 < l.d2) { // pushed last, searched first
            std::swap(l, r);
        }
        stack[top++] = r;
        stack[top++] = l;
    }
    return best;
}

Projection IndexedAlignment::project_samples(double x, double y, std::size_t first, std::size_t last) const {
    return refined(x, y, nearest_sample(x, y, first, last));
}

Projection IndexedAlignment::refined(double x, double y, std::size_t best) const {
    const double lo = samples_[best == 0 ? 0 : best - 1].s;
    const double hi = samples_[std::min(best + 1, samples_.size() - 1)].s;
    const double s = refine(x, y, lo, hi, samples_[best].s);
    const Residual r = residual(evaluate(s), x, y);
    return {s, r.offset, r.distance};
}

std::optional<Projection> IndexedAlignment::project_near(double x, double y, double radius) const {
    // The foot of (x, y) lies at most half a step along from a sample.
    const std::size_t best = nearest_sample(x, y, 0, samples_.size() - 1);
    if (std::hypot(samples_[best].x - x, samples_[best].y - y) > radius + step_) {
        return std::nullopt;
    }
    return refined(x, y, best);
}

Projection IndexedAlignment::project(double x, double y) const {
    return project_samples(x, y, 0, samples_.size() - 1);
}

Projection IndexedAlignment::project_within(double x, double y, double s_lo, double s_hi) const {
    auto by_s = [](const Sample& a, double v) { return a.s < v; };
    const auto lo = std::lower_bound(samples_.begin(), samples_.end(), s_lo, by_s);
    const auto hi = std::lower_bound(samples_.begin(), samples_.end(), s_hi, by_s);
    const std::size_t first = lo == samples_.begin() ? 0 : static_cast<std::size_t>(lo - samples_.begin()) - 1;
    const std::size_t last = std::min(samples_.size() - 1, static_cast<std::size_t>(hi - samples_.begin()));
    return project_samples(x, y, first, last);
}

} // namespace railodd::geometry
