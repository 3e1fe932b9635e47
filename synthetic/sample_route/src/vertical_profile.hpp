#pragma once
// The designed track elevation: constant grades between points of vertical
// intersection (PVI), rounded by parabolic vertical curves of one radius, the
// way railway gradient profiles are specified.
#include <vector>

namespace railodd::sample {

struct Pvi {
    double s; // chainage, m
    double z; // elevation of the intersection of the adjoining grades, m
};

class VerticalProfile {
public:
    // Throws std::invalid_argument if the PVIs are not increasing in s or two
    // vertical curves would overlap.
    VerticalProfile(std::vector<Pvi> pvis, double vertical_radius);

    double elevation(double s) const;
    double grade(double s) const; // dz/ds

    const std::vector<Pvi>& pvis() const noexcept { return pvis_; }
    double vertical_radius() const noexcept { return radius_; }
    // Half-length of the vertical curve at interior PVI i (0 at both ends).
    double tangent_length(std::size_t i) const;

private:
    double segment_grade(std::size_t i) const; // grade from PVI i to i + 1

    std::vector<Pvi> pvis_;
    double radius_;
};

} // namespace railodd::sample
