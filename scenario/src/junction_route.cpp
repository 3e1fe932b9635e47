// The profile runs a track on through its switch on the main track's
// connecting road (odd_tagging tags that one), so a line continued onto the
// switch's other leg still names it; the player, routing by road, then takes
// the main track (Munich: 84, 199, 37 with 199 leading to 16, not 37).
#include "junction_route.hpp"

#include <algorithm>

namespace railodd::scenario {

void take_connecting_roads(std::vector<LanePlacement>& route, const std::vector<ConnectingRoad>& roads) {
    for (std::size_t i = 1; i + 1 < route.size(); ++i) {
        // A scan, not an index: a route has a few dozen waypoints, and an
        // index built per scenario would cost more than it saves.
        const auto it = std::find_if(roads.begin(), roads.end(),
                                     [&](const ConnectingRoad& r) { return r.id == route[i].road_id; });
        if (it == roads.end()) {
            continue;
        }
        const ConnectingRoad& own = *it;
        const std::string& before = route[i - 1].road_id;
        const std::string& after = route[i + 1].road_id;
        // Travelled the way a connecting road runs, or against it. Where the
        // named one links neither way (it leaves a crossing's other incoming
        // road: Munich's crossing 1688834624, 93 -> 105 named for 97 -> 105),
        // the one running the way of travel first.
        const auto along = [&](const ConnectingRoad& r) { return r.from == before && r.to == after; };
        const auto against = [&](const ConnectingRoad& r) { return r.from == after && r.to == before; };
        if (along(own) || against(own)) {
            continue;
        }
        const auto in_junction = [&](const auto& links) {
            return std::find_if(roads.begin(), roads.end(),
                                [&](const ConnectingRoad& r) { return r.junction == own.junction && links(r); });
        };
        auto other = in_junction(along);
        if (other == roads.end()) {
            other = in_junction(against);
        }
        if (other != roads.end()) {
            const double share = own.length > 0.0 ? route[i].s / own.length : 0.5;
            route[i].road_id = other->id;
            route[i].s = std::clamp(share, 0.0, 1.0) * other->length;
        }
    }
}

} // namespace railodd::scenario
