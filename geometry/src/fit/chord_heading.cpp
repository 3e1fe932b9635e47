#include "chord_heading.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace railodd::geometry::fit {

std::vector<double> chainage(const std::vector<Point2>& p) {
    std::vector<double> t(p.size(), 0.0);
    for (std::size_t i = 1; i < p.size(); ++i) {
        t[i] = t[i - 1] + std::hypot(p[i].x - p[i - 1].x, p[i].y - p[i - 1].y);
    }
    return t;
}

ChordHeading::ChordHeading(const std::vector<Point2>& p, double min_chord) {
    const std::vector<double> t = chainage(p);
    std::size_t from = 0;
    for (std::size_t i = 1; i < p.size(); ++i) {
        const double len = std::hypot(p[i].x - p[from].x, p[i].y - p[from].y);
        if (len < min_chord && i + 1 < p.size()) {
            continue;
        }
        if (len < 1e-6) {
            continue;
        }
        double h = std::atan2(p[i].y - p[from].y, p[i].x - p[from].x);
        if (!hdg_.empty()) {
            h += 2 * std::numbers::pi * std::round((hdg_.back() - h) / (2 * std::numbers::pi));
        }
        mid_.push_back(0.5 * (t[i] + t[from]));
        hdg_.push_back(h);
        from = i;
    }
    if (hdg_.empty()) {
        // Every chord too short to trust (or the points coincide with the
        // first): the overall direction is the best guess there is.
        mid_.push_back(0.5 * t.back());
        hdg_.push_back(std::atan2(p.back().y - p.front().y, p.back().x - p.front().x));
    }
}

double ChordHeading::at(double s) const {
    if (mid_.size() == 1 || s <= mid_.front()) {
        return hdg_.front();
    }
    if (s >= mid_.back()) {
        return hdg_.back();
    }
    const auto it = std::upper_bound(mid_.begin(), mid_.end(), s);
    const std::size_t j = static_cast<std::size_t>(it - mid_.begin());
    const double f = (s - mid_[j - 1]) / (mid_[j] - mid_[j - 1]);
    return hdg_[j - 1] + f * (hdg_[j] - hdg_[j - 1]);
}

} // namespace railodd::geometry::fit
