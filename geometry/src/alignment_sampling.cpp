// Chainages for drawing an alignment as a polyline within a chord tolerance.
#include "railodd/geometry/alignment.hpp"
#include "railodd/geometry/indexed_alignment.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace railodd::geometry {

namespace {

// Curvature of a primitive at ds into it (linear along a spiral).
double curvature_at(const Primitive& p, double ds) {
    if (p.length <= 0.0) {
        return p.curv_start;
    }
    return p.curv_start + (p.curv_end - p.curv_start) * std::clamp(ds / p.length, 0.0, 1.0);
}

// Stations strictly inside (a, b) of one primitive, a and b measured into it.
void stations_inside(const Primitive& p, double a, double b, double max_sagitta, double offset,
                     std::vector<double>& out) {
    const double k = std::max(std::abs(curvature_at(p, a)), std::abs(curvature_at(p, b)));
    if (k <= 0.0 || b <= a) {
        return;
    }
    const double step = std::sqrt(8.0 * max_sagitta / k);
    const auto n = static_cast<long>(std::ceil((b - a) / step));
    for (long i = 1; i < n; ++i) {
        out.push_back(offset + a + (b - a) * static_cast<double>(i) / static_cast<double>(n));
    }
}

} // namespace

namespace {

// Stations from primitive `first`, which starts at `at` (<= s0): a scan from
// the alignment's start made drawing every element of a long chain quadratic
// (200,000 primitives: 80 s).
std::vector<double> stations_from(const Alignment& alignment, std::size_t first, double at, double s0, double s1,
                                  double max_sagitta) {
    if (!(max_sagitta > 0.0) || !(s1 >= s0)) {
        throw std::invalid_argument("chord_stations: needs s0 <= s1 and a positive sagitta");
    }
    std::vector<double> out{s0};
    if (s1 == s0) {
        return out;
    }
    for (std::size_t i = first; i < alignment.primitives.size(); ++i) {
        const Primitive& p = alignment.primitives[i];
        const double end = at + p.length;
        if (end > s0 && at < s1) {
            stations_inside(p, std::max(s0, at) - at, std::min(s1, end) - at, max_sagitta, at, out);
            if (end < s1 && end > out.back()) {
                out.push_back(end); // the joint: where the curvature's slope changes
            }
        }
        if (end >= s1) {
            break;
        }
        at = end;
    }
    out.push_back(s1);
    return out;
}

} // namespace

std::vector<double> chord_stations(const Alignment& alignment, double s0, double s1, double max_sagitta) {
    return stations_from(alignment, 0, 0.0, s0, s1, max_sagitta);
}

std::vector<double> IndexedAlignment::chord_stations(double s0, double s1, double max_sagitta) const {
    const std::size_t first = alignment_.primitives.empty() ? 0 : primitive_at(s0);
    return stations_from(alignment_, first, first < s_starts_.size() ? s_starts_[first] : 0.0, s0, s1, max_sagitta);
}

} // namespace railodd::geometry
