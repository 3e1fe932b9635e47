// `railodd convert --relation ID`: the ODD profile along an OSM route
// relation, chainage following its member ways in member order. On a small
// line of three ways (the middle one mapped against the travel direction) the
// route runs them in order, forwards or backwards as the relation says, a
// signal lands at its distance from the relation's start, a member missing
// from the selection is a gap listed in report.json, and a relation without
// track members is refused naming it. Then the sample route's relation.
#include "railodd/util/errors.hpp"
#include "odd_profile_rows.hpp"
#include "test_support.hpp"

#include <nlohmann/json.hpp>

#include <cmath>

using namespace railodd;
using namespace railodd::test;

namespace {

// n1..n13 along 48.0 N, about 100 m apart: w1 n1-n5, w2 n9-n5 (mapped
// westwards), w3 n9-n13; a signal on n3, 200 m from n1.
std::string line_opl() {
    std::string opl;
    for (int i = 1; i <= 13; ++i) {
        // Appended piecewise: GCC 12 warns falsely (-Wrestrict) on one long concatenation.
        opl.append("n").append(std::to_string(i)).append(" v1 x").append(std::to_string(10.0 + 0.0013443 * (i - 1)));
        opl.append(" y48.0").append(i == 3 ? " Trailway=signal,railway:signal:main=DE-ESO:hp" : "").append("\n");
    }
    opl += "n20 v1 x10.0 y48.001\nn21 v1 x10.01 y48.001\n";
    opl += "w1 v1 Trailway=rail Nn1,n2,n3,n4,n5\n"
           "w2 v1 Trailway=rail Nn9,n8,n7,n6,n5\n"
           "w3 v1 Trailway=rail Nn9,n10,n11,n12,n13\n"
           "w4 v1 Thighway=service Nn20,n21\n"
           "r1 v1 Ttype=route,route=train,name=Test%20%line,from=West,to=East Mw1@,w2@,w3@,w4@\n"
           "r2 v1 Ttype=route,route=train,name=Test%20%line%20%back Mw3@,w2@,w1@\n"
           "r3 v1 Ttype=route,route=train,name=Gap Mw1@,w3@\n"
           "r4 v1 Ttype=route,route=train,name=Road Mw4@\n";
    return opl;
}

struct Converted {
    CommandResult run;
    nlohmann::json report, profile;
};

Converted convert(const fs::path& input, const fs::path& out, const std::string& options) {
    Converted c;
    c.run = run_command(std::string{RAILODD_BIN} + " convert " + quoted(input) + " --no-timings -o " + quoted(out) +
                        " " + options);
    if (c.run.exit_code == 0) {
        c.report = nlohmann::json::parse(read_file(out / "report.json"));
        c.profile = with_element_objects(nlohmann::json::parse(read_file(out / "odd_profile.json")));
    }
    return c;
}

double signal_chainage(const nlohmann::json& profile) {
    for (const auto& e : profile["elements"]) {
        if (e["odd_element"] == "Scenery/Trackside equipment/Signal") {
            return e["chainage_start"];
        }
    }
    return -1.0;
}

} // namespace

TEST(OddRelationRoute, ChainageFollowsTheMembersInOrder) {
    const fs::path dir = scratch_dir();
    const fs::path in = write_file(dir / "line.opl", line_opl());
    const Converted fwd = convert(in, dir / "r1", "--relation 1");
    ASSERT_EQ(fwd.run.exit_code, 0) << fwd.run.output;
    const auto& route = fwd.report["route"];
    EXPECT_EQ(route["relation"], 1);
    EXPECT_EQ(route["name"], "Test line");
    EXPECT_EQ(route["from"], "West");
    EXPECT_EQ(route["member_ways"], 4);
    EXPECT_EQ(route["ways_on_route"], 3);
    EXPECT_TRUE(route["gaps"].empty());
    EXPECT_NEAR(route["length_m"].get<double>(), 1201.0, 5.0);
    EXPECT_EQ(fwd.profile["route"]["description"], "relation 1: Test line");
    EXPECT_NEAR(signal_chainage(fwd.profile), 200.0, 3.0);
    for (const auto& e : fwd.profile["elements"]) {
        EXPECT_GE(e["chainage_start"].get<double>(), -1e-6) << e.dump();
        EXPECT_LE(e["chainage_end"].get<double>(), 1206.0) << e.dump();
    }

    const Converted back = convert(in, dir / "r2", "--relation 2");
    ASSERT_EQ(back.run.exit_code, 0) << back.run.output;
    EXPECT_NEAR(back.report["route"]["length_m"].get<double>(), 1201.0, 5.0);
    EXPECT_NEAR(signal_chainage(back.profile), 1001.0, 3.0) << "the relation starts at the east end";
}

TEST(OddRelationRoute, MembersThatDoNotMeetAreAListedGap) {
    const fs::path dir = scratch_dir();
    const Converted gap = convert(write_file(dir / "line.opl", line_opl()), dir / "r3", "--relation 3");
    ASSERT_EQ(gap.run.exit_code, 0) << gap.run.output;
    const auto& route = gap.report["route"];
    ASSERT_EQ(route["gaps"].size(), 1u);
    const auto& g = route["gaps"][0];
    EXPECT_EQ(g["after_way"], 1);
    EXPECT_EQ(g["before_way"], 3);
    EXPECT_FALSE(g["bridged"]) << "w2 is not in the relation, so not in the selection";
    EXPECT_NEAR(g["distance_m"].get<double>(), 400.0, 5.0);
    EXPECT_NEAR(g["chainage"].get<double>(), 400.0, 5.0);
    EXPECT_NEAR(route["length_m"].get<double>(), 800.0, 5.0) << "the gap adds no chainage";
}

TEST(OddRelationRoute, RelationWithoutTracksIsRefusedNamingIt) {
    const fs::path dir = scratch_dir();
    const fs::path in = write_file(dir / "line.opl", line_opl());
    const Converted road = convert(in, dir / "r4", "--relation 4");
    EXPECT_EQ(road.run.exit_code, exit_input) << road.run.output;
    EXPECT_NE(road.run.output.find("relation 4 has no railway track member"), std::string::npos) << road.run.output;
    EXPECT_NE(road.run.output.find("line.opl"), std::string::npos) << road.run.output;
    const Converted missing = convert(in, dir / "r9", "--relation 9");
    EXPECT_EQ(missing.run.exit_code, exit_input) << missing.run.output;
    EXPECT_NE(missing.run.output.find("relation 9 is not in the file"), std::string::npos) << missing.run.output;
}

TEST(OddRelationRoute, SampleRouteRelationRunsTheMainLine) {
    const fs::path dir = scratch_dir();
    const auto s = run_command(std::string{RAILODD_BIN} + " sample -o " + quoted(dir / "in"));
    ASSERT_EQ(s.exit_code, 0) << s.output;
    const auto truth = nlohmann::json::parse(read_file(dir / "in" / "sample_route_truth.json"));
    const auto id = truth["route_relation"].get<std::int64_t>();
    const Converted c = convert(dir / "in" / "sample_route.osm", dir / "out", "--relation " + std::to_string(id));
    ASSERT_EQ(c.run.exit_code, 0) << c.run.output;
    const auto& route = c.report["route"];
    EXPECT_TRUE(route["gaps"].empty());
    EXPECT_NEAR(route["length_m"].get<double>(), 9330.0, 30.0) << "the whole main line";
    EXPECT_EQ(c.profile["summary"]["tunnels"]["count"], 1);
    EXPECT_EQ(c.profile["summary"]["bridges"]["count"], 1);
    EXPECT_EQ(c.profile["summary"]["switches"], 0) << "never into the passing loop or the spur";
}
