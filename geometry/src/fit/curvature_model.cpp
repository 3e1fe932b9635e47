#include "curvature_model.hpp"

#include <algorithm>
#include <limits>

namespace railodd::geometry::fit {

Primitive CurvatureModel::segment(std::size_t j) const {
    const double a = knot_curvature(j);
    const double b = knot_curvature(j + 1);
    const bool tied = knot_var[j] >= 0 && knot_var[j] == knot_var[j + 1];
    if (tied || a == b) {
        return a == 0.0 ? make_line(lengths[j]) : make_arc(lengths[j], a);
    }
    return make_spiral(lengths[j], a, b);
}

Alignment CurvatureModel::to_alignment() const {
    Alignment a;
    a.start = start;
    a.start.curvature = knot_curvature(0);
    a.primitives.reserve(segments());
    for (std::size_t j = 0; j < segments(); ++j) {
        a.primitives.push_back(segment(j));
    }
    return a;
}

std::vector<Pose> CurvatureModel::knot_poses() const {
    std::vector<Pose> poses;
    poses.reserve(segments() + 1);
    Pose p = start;
    p.curvature = knot_curvature(0);
    poses.push_back(p);
    for (std::size_t j = 0; j < segments(); ++j) {
        p = evaluate(p, segment(j), lengths[j]);
        poses.push_back(p);
    }
    return poses;
}

void CurvatureModel::push_segment(double length, bool free_length, int end_var, double end_fixed) {
    lengths.push_back(length);
    length_free.push_back(free_length ? 1 : 0);
    knot_var.push_back(end_var);
    knot_fixed.push_back(end_fixed);
}

ParameterMap::ParameterMap(const CurvatureModel& m) {
    const std::size_t last = m.segments() == 0 ? 0 : m.segments() - 1;
    if (m.start_free) {
        for (std::size_t i = 0; i < 3; ++i) {
            slots_.push_back({Kind::start, i, {0, last}});
        }
    }
    for (std::size_t j = 0; j < m.segments(); ++j) {
        if (m.length_free[j]) {
            slots_.push_back({Kind::length, j, {j, j}});
        }
    }
    for (std::size_t v = 0; v < m.curv.size(); ++v) {
        std::size_t lo = std::numeric_limits<std::size_t>::max(), hi = 0;
        for (std::size_t k = 0; k < m.knot_var.size(); ++k) {
            if (m.knot_var[k] == static_cast<int>(v)) {
                // Knot k bounds segments k - 1 and k.
                lo = std::min(lo, k == 0 ? 0 : k - 1);
                hi = std::max(hi, std::min(k, last));
            }
        }
        if (lo <= hi) {
            slots_.push_back({Kind::curvature, v, {lo, hi}});
        }
    }
}

std::vector<double> ParameterMap::get(const CurvatureModel& m) const {
    std::vector<double> v;
    v.reserve(slots_.size());
    for (const Slot& s : slots_) {
        switch (s.kind) {
        case Kind::start: v.push_back(s.index == 0 ? m.start.x : s.index == 1 ? m.start.y : m.start.hdg); break;
        case Kind::length: v.push_back(m.lengths[s.index]); break;
        case Kind::curvature: v.push_back(m.curv[s.index]); break;
        }
    }
    return v;
}

void ParameterMap::set(CurvatureModel& m, const std::vector<double>& v) const {
    for (std::size_t i = 0; i < slots_.size(); ++i) {
        set_one(m, i, v[i]);
    }
}

void ParameterMap::set_one(CurvatureModel& m, std::size_t i, double value) const {
    const Slot& s = slots_[i];
    switch (s.kind) {
    case Kind::start: (s.index == 0 ? m.start.x : s.index == 1 ? m.start.y : m.start.hdg) = value; break;
    case Kind::length: m.lengths[s.index] = value; break;
    case Kind::curvature: m.curv[s.index] = value; break;
    }
}

} // namespace railodd::geometry::fit
