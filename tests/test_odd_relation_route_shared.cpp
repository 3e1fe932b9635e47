// With the shared data (label `shared`): `railodd convert --relation` on a real
// route relation, the S1 Bamberg - Hartmannshof through the Lauf extract
// (clipped at the extract's edges), and the land use along it.
#include "odd_profile_rows.hpp"
#include "test_support.hpp"

#include <nlohmann/json.hpp>

#include <iostream>

using namespace railodd::test;

TEST(OddRelationRouteShared, LaufS1) {
    RAILODD_REQUIRE_SHARED_DATA();
    const fs::path dir = scratch_dir();
    const auto run = run_command(std::string{RAILODD_BIN} + " convert " +
                                 quoted(shared_data() / "osm" / "gh_lauf-200115.osm.pbf") + " --no-timings -o " +
                                 quoted(dir / "out") + " --relation 539311 --road-corridor 0");
    ASSERT_EQ(run.exit_code, 0) << run.output;
    const auto report = nlohmann::json::parse(read_file(dir / "out" / "report.json"));
    const auto profile = with_element_objects(nlohmann::json::parse(read_file(dir / "out" / "odd_profile.json")));
    const auto& route = report["route"];
    const double length = route["length_m"];
    std::cout << "S1 in the Lauf extract: " << length << " m over " << route["pieces"].size() << " pieces, "
              << route["ways_on_route"] << " of " << route["member_ways"] << " member ways, " << route["gaps"].size()
              << " gaps\n";
    // The line crosses the extract from its south edge to its east edge: about 2.7 km of it.
    EXPECT_GT(length, 2500.0);
    EXPECT_EQ(route["ways_on_route"], report["output"]["track_ways"]) << "every member track in the extract is run";
    EXPECT_TRUE(route["gaps"].empty());
    EXPECT_FALSE(profile["elements"].empty());
    for (const auto& e : profile["elements"]) {
        EXPECT_LE(e["chainage_end"].get<double>(), length + 0.0005) << e.dump(); // written to the mm
    }
    double land_use = 0.0;
    for (const auto& [kind, km] : profile["summary"]["landuse_km_by_kind"].items()) {
        land_use += km.get<double>();
    }
    std::cout << "land use along it: " << profile["summary"]["landuse_km_by_kind"].dump() << '\n';
    EXPECT_GT(land_use, 0.5) << "Lauf maps residential, farmland and forest along the line";
}
