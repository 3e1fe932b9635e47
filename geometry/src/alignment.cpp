// Chaining primitives into an alignment.
#include "railodd/geometry/alignment.hpp"
#include "railodd/geometry/indexed_alignment.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace railodd::geometry {

void validate(const Alignment& alignment) {
    for (std::size_t i = 0; i < alignment.primitives.size(); ++i) {
        validate(alignment.primitives[i], i);
    }
}

double length(const Alignment& alignment) {
    double total = 0.0;
    for (const auto& p : alignment.primitives) {
        total += p.length;
    }
    return total;
}

std::vector<double> primitive_s(const Alignment& alignment) {
    std::vector<double> s;
    s.reserve(alignment.primitives.size());
    double at = 0.0;
    for (const auto& p : alignment.primitives) {
        s.push_back(at);
        at += p.length;
    }
    return s;
}

std::vector<Pose> primitive_starts(const Alignment& alignment) {
    std::vector<Pose> starts;
    starts.reserve(alignment.primitives.size());
    Pose pose = alignment.start;
    for (const auto& p : alignment.primitives) {
        pose.curvature = p.curv_start;
        starts.push_back(pose);
        pose = evaluate(pose, p, p.length);
    }
    return starts;
}

Pose evaluate(const Alignment& alignment, double s) {
    if (alignment.primitives.empty()) {
        Pose p = alignment.start;
        p.curvature = 0.0;
        return p;
    }
    s = std::clamp(s, 0.0, length(alignment));
    Pose pose = alignment.start;
    double at = 0.0;
    const std::size_t last = alignment.primitives.size() - 1;
    for (std::size_t i = 0;; ++i) {
        const Primitive& p = alignment.primitives[i];
        // Strict comparison hands a joint to the following primitive.
        if (s < at + p.length || i == last) {
            pose.curvature = p.curv_start;
            return evaluate(pose, p, s - at);
        }
        pose = evaluate(pose, p, p.length);
        at += p.length;
    }
}

Alignment reversed(const Alignment& alignment) {
    Alignment r;
    r.start = evaluate(alignment, length(alignment));
    r.start.hdg = std::remainder(r.start.hdg + std::numbers::pi, 2.0 * std::numbers::pi);
    r.primitives.reserve(alignment.primitives.size());
    for (auto it = alignment.primitives.rbegin(); it != alignment.primitives.rend(); ++it) {
        Primitive p = *it;
        p.curv_start = -it->curv_end;
        p.curv_end = -it->curv_start;
        r.primitives.push_back(p);
    }
    r.start.curvature = r.primitives.empty() ? 0.0 : r.primitives.front().curv_start;
    return r;
}

Projection project_point(const Alignment& alignment, double x, double y) {
    return IndexedAlignment(alignment).project(x, y);
}

} // namespace railodd::geometry
