// A route through a switch takes the connecting road that leads where it
// goes (scenario/src/junction_route.cpp), as the player routes by road.
#include "junction_route.hpp"

#include <gtest/gtest.h>

using namespace railodd::scenario;

namespace {

// Munich's switch: junction 6905 links road 84 to 16 by 199 and to 37 by
// 201 (both 20 m), and road 88 to 16 by 200 (5.9 m).
const std::vector<ConnectingRoad> roads{{"199", "6905", "84", "16", 20.0},
                                        {"200", "6905", "88", "16", 5.9},
                                        {"201", "6905", "84", "37", 20.0}};

std::vector<LanePlacement> route(std::vector<std::pair<std::string, double>> at) {
    std::vector<LanePlacement> out;
    for (const auto& [road, s] : at) {
        LanePlacement p;
        p.road_id = road;
        p.s = s;
        out.push_back(p);
    }
    return out;
}

} // namespace

TEST(ScenarioJunctionRoute, TheOtherLegsConnectingRoadIsTaken) {
    auto r = route({{"84", 42.0}, {"199", 10.0}, {"37", 9.0}});
    take_connecting_roads(r, roads);
    EXPECT_EQ(r[1].road_id, "201");
    EXPECT_DOUBLE_EQ(r[1].s, 10.0);
    EXPECT_EQ(r[0].road_id, "84");
    EXPECT_EQ(r[2].road_id, "37");
}

TEST(ScenarioJunctionRoute, AgainstTheConnectingRoadsDirection) {
    auto r = route({{"37", 9.0}, {"199", 5.0}, {"84", 42.0}});
    take_connecting_roads(r, roads);
    EXPECT_EQ(r[1].road_id, "201");
    EXPECT_DOUBLE_EQ(r[1].s, 5.0);
}

TEST(ScenarioJunctionRoute, ARouteThatIsLinkedStaysAndOneWithoutALinkToo) {
    auto linked = route({{"84", 42.0}, {"199", 10.0}, {"16", 9.0}});
    take_connecting_roads(linked, roads);
    EXPECT_EQ(linked[1].road_id, "199");
    // No connecting road of the junction links 88 to 37: the route is left
    // as it is (the play check says where the train went).
    auto unlinked = route({{"88", 3.0}, {"200", 2.0}, {"37", 9.0}});
    take_connecting_roads(unlinked, roads);
    EXPECT_EQ(unlinked[1].road_id, "200");
}

// Munich's crossing 1688834624: roads 93 and 97 both lead to 105 and 106.
// A route from 97 named the connecting road from 93 (215), which links its
// two neighbours neither way; the one from 97 to 105 (217) is taken.
TEST(ScenarioJunctionRoute, ACrossingsConnectingRoadFromTheOtherIncomingRoad) {
    const std::vector<ConnectingRoad> crossing{{"215", "6912", "93", "105", 5.6},
                                               {"216", "6912", "93", "106", 5.5},
                                               {"217", "6912", "97", "105", 5.7},
                                               {"218", "6912", "97", "106", 5.8}};
    auto r = route({{"97", 4.2}, {"215", 2.8}, {"105", 5.6}});
    take_connecting_roads(r, crossing);
    EXPECT_EQ(r[1].road_id, "217");
    EXPECT_NEAR(r[1].s, 2.8 / 5.6 * 5.7, 1e-12);
    // Against the roads' direction, from 105 back to 97.
    auto back = route({{"105", 5.6}, {"216", 2.0}, {"97", 4.2}});
    take_connecting_roads(back, crossing);
    EXPECT_EQ(back[1].road_id, "217");
}
