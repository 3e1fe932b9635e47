#include "vertical_profile.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

namespace railodd::sample {

VerticalProfile::VerticalProfile(std::vector<Pvi> pvis, double vertical_radius)
    : pvis_(std::move(pvis)), radius_(vertical_radius) {
    if (pvis_.size() < 2 || !(radius_ > 0.0)) {
        throw std::invalid_argument("vertical profile: need two PVIs and a positive radius");
    }
    for (std::size_t i = 1; i < pvis_.size(); ++i) {
        if (!(pvis_[i].s > pvis_[i - 1].s)) {
            throw std::invalid_argument("vertical profile: PVI " + std::to_string(i) +
                                        " at s " + std::to_string(pvis_[i].s) + " does not increase");
        }
        const double room = pvis_[i].s - pvis_[i - 1].s;
        if (tangent_length(i - 1) + tangent_length(i) > room) {
            throw std::invalid_argument("vertical profile: vertical curves at PVIs " +
                                        std::to_string(i - 1) + " and " + std::to_string(i) +
                                        " overlap");
        }
    }
}

double VerticalProfile::segment_grade(std::size_t i) const {
    return (pvis_[i + 1].z - pvis_[i].z) / (pvis_[i + 1].s - pvis_[i].s);
}

double VerticalProfile::tangent_length(std::size_t i) const {
    if (i == 0 || i + 1 >= pvis_.size()) {
        return 0.0;
    }
    return 0.5 * radius_ * std::abs(segment_grade(i) - segment_grade(i - 1));
}

double VerticalProfile::elevation(double s) const {
    s = std::clamp(s, pvis_.front().s, pvis_.back().s);
    for (std::size_t i = 1; i + 1 < pvis_.size(); ++i) {
        const double t = tangent_length(i);
        if (std::abs(s - pvis_[i].s) <= t && t > 0.0) {
            const double g1 = segment_grade(i - 1);
            const double g2 = segment_grade(i);
            const double u = s - (pvis_[i].s - t);
            return pvis_[i].z - g1 * t + g1 * u + (g2 - g1) * u * u / (4.0 * t);
        }
    }
    std::size_t i = 0;
    while (i + 2 < pvis_.size() && s > pvis_[i + 1].s) {
        ++i;
    }
    return pvis_[i].z + segment_grade(i) * (s - pvis_[i].s);
}

double VerticalProfile::grade(double s) const {
    s = std::clamp(s, pvis_.front().s, pvis_.back().s);
    for (std::size_t i = 1; i + 1 < pvis_.size(); ++i) {
        const double t = tangent_length(i);
        if (std::abs(s - pvis_[i].s) <= t && t > 0.0) {
            const double g1 = segment_grade(i - 1);
            const double g2 = segment_grade(i);
            return g1 + (g2 - g1) * (s - (pvis_[i].s - t)) / (2.0 * t);
        }
    }
    for (std::size_t i = 0; i + 1 < pvis_.size(); ++i) {
        if (s <= pvis_[i + 1].s) {
            return segment_grade(i);
        }
    }
    return segment_grade(pvis_.size() - 2);
}

} // namespace railodd::sample
