// Where OpenSCENARIO's LanePosition lies on a map read by xodr_check
// (MapRoad::lane_position): lane centres from the widths of the lanes inside
// them, the road's lane offset, the position's own offset, left positive.
#include "railodd/xodr_check/map_lines.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <unistd.h>

using namespace railodd::xodr_check;
namespace fs = std::filesystem;

namespace {

// Road 7 heads north from (10, 20); lane 1 is 3 m wide, lane -1 3.5 m, lane
// -2 widens 0.01 m per metre from 3 m; the lanes are shifted 0.5 m left.
const char* map = R"(<?xml version="1.0"?>
<OpenDRIVE><header revMajor="1" revMinor="6"/>
<road id="7" length="100" junction="-1">
  <planView><geometry s="0" x="10" y="20" hdg="1.5707963267948966" length="100"><line/></geometry></planView>
  <lanes>
    <laneOffset s="0" a="0.5" b="0" c="0" d="0"/>
    <laneSection s="0">
      <left><lane id="1" type="driving"><width sOffset="0" a="3" b="0" c="0" d="0"/></lane></left>
      <center><lane id="0" type="none"/></center>
      <right>
        <lane id="-1" type="driving"><width sOffset="0" a="3.5" b="0" c="0" d="0"/></lane>
        <lane id="-2" type="driving"><width sOffset="0" a="3" b="0.01" c="0" d="0"/></lane>
      </right>
    </laneSection>
  </lanes>
</road>
</OpenDRIVE>)";

MapRoad road() {
    const fs::path file = fs::temp_directory_path() / ("lane_position_" + std::to_string(getpid()) + ".xodr");
    std::ofstream(file) << map;
    MapLines lines = read_map_lines(file);
    fs::remove(file);
    return lines.roads.at(0);
}

} // namespace

TEST(XodrLanePosition, LaneCentresOffsetsAndTheRoadsHeading) {
    const MapRoad r = road();
    // Heading north, left is -x: t = 0.5 + 1.5 for lane 1.
    const auto l1 = r.lane_position(1, 40.0, 0.0);
    ASSERT_TRUE(l1);
    EXPECT_NEAR(l1->x, 10.0 - 2.0, 1e-9);
    EXPECT_NEAR(l1->y, 60.0, 1e-9);
    const auto r1 = r.lane_position(-1, 40.0, 0.0);
    ASSERT_TRUE(r1);
    EXPECT_NEAR(r1->x, 10.0 - (0.5 - 1.75), 1e-9);
    // Lane -2 at s 40 is 3.4 m wide; 0.2 m left of its centre.
    const auto r2 = r.lane_position(-2, 40.0, 0.2);
    ASSERT_TRUE(r2);
    EXPECT_NEAR(r2->x, 10.0 - (0.5 - 3.5 - 1.7 + 0.2), 1e-9);
    EXPECT_FALSE(r.lane_position(-3, 40.0, 0.0));
}
