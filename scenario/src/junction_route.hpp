#pragma once
// A route through a switch on the connecting road that leads where it goes.
#include "railodd/scenario/concrete.hpp"
#include "railodd/scenario/generator.hpp"

#include <vector>

namespace railodd::scenario {

// Each waypoint on a connecting road that does not link the waypoints
// before and after it takes the connecting road of the same junction that
// does (at the same share of its length), where the map has one.
void take_connecting_roads(std::vector<LanePlacement>& route, const std::vector<ConnectingRoad>& roads);

} // namespace railodd::scenario
