#pragma once
// Plane geometry on recorded trajectories: the ego's path as a polyline with
// chainage, projections onto it, sight along it, distances between boxes.
#include "railodd/scenario/play.hpp"

#include <vector>

namespace railodd::scenario::play {

// The ego's recorded positions as a polyline (points at least 0.5 m apart)
// with chainage from its first point. On its rail lane the ego runs on the
// track centre, so this is the track as the player drew it.
class Path {
public:
    explicit Path(const std::vector<Sample>& ego);
    struct Foot {
        double chainage = 0.0;
        double distance = 0.0; // unsigned, from the polyline
    };
    Foot project(double x, double y) const;
    double length() const { return c_.empty() ? 0.0 : c_.back(); }
    bool empty() const { return x_.size() < 2; }

    // How far back from the point at `chainage` the track can be seen: the
    // longest stretch before it over which the line of sight from a point on
    // the track to it stays within `corridor` m of the track (the inside of a
    // curve is where cuttings, vegetation and masts stand). `limited` is true
    // where the curve limits it, false where the recorded path ran out first.
    double sight_back(double chainage, double corridor, bool& limited) const;

private:
    std::vector<double> x_, y_, c_;
};

// Smallest distance between two boxes (centre x, y, heading h, length,
// width); 0 where they overlap.
struct Box {
    double x = 0.0, y = 0.0, h = 0.0, length = 0.0, width = 0.0;
};
double box_distance(const Box& a, const Box& b);

// The run's criticality figures (play_criticality.cpp).
Criticality criticality(const nlohmann::json& scenario, const Trajectories& run, const Path& path, const Options& o);

} // namespace railodd::scenario::play
