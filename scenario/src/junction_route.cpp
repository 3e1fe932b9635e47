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
        // Travelled the way its own road runs, or against it.
        const auto links = [&](const ConnectingRoad& r) {
            return own.from == before ? r.from == before && r.to == after : r.from == after && r.to == before;
        };
        if (links(own)) {
            continue;
        }
        const auto other = std::find_if(roads.begin(), roads.end(),
                                        [&](const ConnectingRoad& r) { return r.junction == own.junction && links(r); });
        if (other != roads.end()) {
            const double share = own.length > 0.0 ? route[i].s / own.length : 0.5;
            route[i].road_id = other->id;
            route[i].s = std::clamp(share, 0.0, 1.0) * other->length;
        }
    }
}

} // namespace railodd::scenario
