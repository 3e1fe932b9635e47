// The checks and figures of `railodd play` on small recorded runs written
// here: a train on a straight and on a curve, a car driving onto a level
// crossing; each defect a player run can show (off the lane, a jump, NaN, a
// road user placed beside the railway, a hazard too late) fails its check.
#include "railodd/scenario/play.hpp"
#include "railodd/util/errors.hpp"

#include "play_geometry.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <sstream>

using namespace railodd::scenario::play;
using json = nlohmann::json;

namespace {

const char* header = "time, id, name, x, y, z, h, p, r, roadId, laneId, offset, t, s, speed, wheel_angle, wheel_rot\n";

struct Row {
    double t;
    std::string name;
    double x, y, h;
    std::string road;
    int lane;
    double offset, s, speed;
};

std::string csv(const std::vector<Row>& rows) {
    std::ostringstream o;
    o << header;
    for (const Row& r : rows) {
        o << r.t << ", 0, " << r.name << ", " << r.x << ", " << r.y << ", 0, " << r.h << ", 0, 0, " << r.road << ", "
          << r.lane << ", " << r.offset << ", " << r.offset << ", " << r.s << ", " << r.speed << ", 0, 0\n";
    }
    return o.str();
}

// Ego on road 1 along +x at 20 m/s from x = 0 for 40 s (dt 0.5). A car on
// road 14 (crossing the track at x = 600) drives from y = -10 to y = 0 at
// 2.5 m/s, starting at t = 20; it stands there after t = 24.
std::vector<Row> crossing_run() {
    std::vector<Row> rows;
    for (int i = 0; i <= 80; ++i) {
        const double t = 0.5 * i;
        rows.push_back({t, "Ego", 20.0 * t, 0.0, 0.0, "1", -1, 0.0, 20.0 * t, 20.0});
        const double moved = std::clamp(2.5 * (t - 20.0), 0.0, 10.0);
        const double v = t > 20.0 && t <= 24.0 ? 2.5 : 0.0;
        rows.push_back({t, "Car", 600.0, -10.0 + moved, M_PI / 2, "14", -1, 0.0, 40.0 + moved, v});
    }
    return rows;
}

json crossing_manifest() {
    return json::parse(R"({
      "id": "x_0001",
      "anchor": {"road_id": "1", "s": 600.0},
      "ego": {"start": {"road_id": "1", "lane_id": -1, "s": 0.0}, "route_roads": ["1"],
              "length_m": 20.0, "width_m": 3.0, "max_deceleration": 1.0},
      "actors": [{"name": "Car", "kind": "vehicle", "place": "crossing_approach",
                  "start": {"road_id": "14", "lane_id": -1, "s": 40.0}, "move_to": "on_track",
                  "target": {"road_id": "14", "lane_id": -1, "s": 50.0}, "speed_mps": 2.5,
                  "hazard_before_m": 110.0, "length_m": 4.0, "width_m": 2.0}],
      "perturbations": []
    })");
}

Trajectories read(const std::vector<Row>& rows) {
    std::istringstream in(csv(rows));
    return read_trajectories(in, "run.csv");
}

const Check* find(const Analysis& a, const std::string& name) {
    for (const auto& c : a.checks) {
        if (c.name == name) {
            return &c;
        }
    }
    return nullptr;
}

bool passed(const Analysis& a, const std::string& name) {
    const Check* c = find(a, name);
    EXPECT_NE(c, nullptr) << "no check '" << name << "'";
    return c && c->passed;
}

} // namespace

TEST(ScenarioPlay, ACleanRunPassesEveryCheckWithExactFigures) {
    const Analysis a = analyse(crossing_manifest(), read(crossing_run()), {}, {});
    for (const auto& c : a.checks) {
        EXPECT_TRUE(c.passed) << c.name << ": " << c.detail;
    }
    EXPECT_TRUE(a.passed());
    const Criticality& c = a.criticality;
    EXPECT_DOUBLE_EQ(c.ego_speed_mps, 20.0);
    // 1 s reaction, then 20^2 / (2 * 1.0).
    EXPECT_DOUBLE_EQ(c.stopping_distance_m, 20.0 + 200.0);
    // A straight: nothing limits the view but the recorded run-up (600 m).
    EXPECT_EQ(c.sight_limited_by, "recorded run-up");
    EXPECT_NEAR(c.sight_distance_m, 600.0, 0.5);
    EXPECT_TRUE(c.can_stop);
    ASSERT_EQ(c.actors.size(), 1u);
    // The car (2 m wide) enters the clearance (1.5 + 0.5 + 1.0 m) at y = -3,
    // at t = 22.8: between samples, so the first at t = 23.0 (y = -2.5),
    // when the train's front is at 460 + 10 = 470: 130 m short.
    ASSERT_TRUE(c.actors[0].onset_s);
    EXPECT_DOUBLE_EQ(*c.actors[0].onset_s, 23.0);
    EXPECT_NEAR(*c.actors[0].distance_at_onset_m, 130.0, 1e-6);
    EXPECT_NEAR(*c.actors[0].ttc_at_onset_s, 6.5, 1e-6);
    // On the track at t = 24.0 with the front at 490: 110 m short, as timed.
    EXPECT_NEAR(*c.actors[0].distance_at_arrival_m, 110.0, 1e-6);
    EXPECT_DOUBLE_EQ(c.actors[0].min_distance_m, 0.0) << "the train runs into the car";
}

TEST(ScenarioPlay, EachDefectFailsItsCheck) {
    const json m = crossing_manifest();
    {
        auto rows = crossing_run();
        rows[10].offset = 0.2; // the ego 0.2 m off its lane centre
        EXPECT_FALSE(passed(analyse(m, read(rows), {}, {}), "ego on its rail lane"));
    }
    {
        auto rows = crossing_run();
        rows[21].x += 15.0; // the car (odd rows) jumps
        EXPECT_FALSE(passed(analyse(m, read(rows), {}, {}), "no jumps"));
    }
    {
        auto rows = crossing_run();
        rows[30].y = std::nan("");
        EXPECT_FALSE(passed(analyse(m, read(rows), {}, {}), "no NaN"));
    }
    {
        auto rows = crossing_run();
        for (auto& r : rows) {
            r.road = r.name == "Ego" && r.t > 35.0 ? "7" : r.road; // runs onto a road off its route
        }
        EXPECT_FALSE(passed(analyse(m, read(rows), {}, {}), "ego follows its route"));
    }
    {
        json beside = m;
        beside["actors"][0]["start"]["road_id"] = "1"; // the old way: an offset from the rail road
        EXPECT_FALSE(passed(analyse(beside, read(crossing_run()), {}, {}), "Car starts on the crossing road"));
    }
    {
        json late = m;
        late["actors"][0]["hazard_before_m"] = 300.0;
        EXPECT_FALSE(passed(analyse(late, read(crossing_run()), {}, {}), "Car on time"));
    }
    {
        PlayerLog log;
        log.errors.push_back("[0.0] [error] Failed to load road network");
        EXPECT_FALSE(passed(analyse(m, read(crossing_run()), log, {}), "player errors"));
    }
}

TEST(ScenarioPlay, ACarThatNeverReachesTheTrackIsNoHazard) {
    auto rows = crossing_run();
    for (auto& r : rows) {
        if (r.name == "Car") {
            r.y = std::min(r.y, -6.0); // stops 6 m short of the track centre
            r.s = std::min(r.s, 44.0);
        }
    }
    const Analysis a = analyse(crossing_manifest(), read(rows), {}, {});
    EXPECT_FALSE(passed(a, "Car in the clearance before the train"));
    EXPECT_FALSE(passed(a, "Car reaches its target"));
    // The car's front to the train's side (the heading pi/2 is written to 6 digits).
    EXPECT_NEAR(a.criticality.actors[0].min_distance_m, 6.0 - 1.5 - 2.0, 1e-4);
}

// On an arc of radius R with obstructions c beside the track, the line of
// sight is the chord whose sagitta is c: about sqrt(8 R c).
TEST(ScenarioPlay, SightDistanceInACurveIsTheChordOfItsSagitta) {
    const double R = 500.0, c = 3.5;
    std::vector<Sample> ego;
    for (int i = 0; i <= 1200; ++i) {
        const double a = i / R; // 1 m steps along the arc
        ego.push_back({0.05 * i, R * std::sin(a), R * (1 - std::cos(a)), a, "1", -1, 0.0, double(i), 20.0});
    }
    const Path path(ego);
    bool limited = false;
    const double sight = path.sight_back(1000.0, c, limited);
    EXPECT_TRUE(limited);
    EXPECT_NEAR(sight, std::sqrt(8 * R * c), 2.0);
}

TEST(ScenarioPlay, BoxDistance) {
    EXPECT_DOUBLE_EQ(box_distance({0, 0, 0, 4, 2}, {10, 0, 0, 4, 2}), 6.0);
    EXPECT_DOUBLE_EQ(box_distance({0, 0, 0, 4, 2}, {3, 0.5, 0.3, 4, 2}), 0.0);
    // A diamond with corners (3, 5), (5, 3), ...: its edge x + y = 8 is
    // 6 / sqrt(2) from the square's corner (1, 1).
    EXPECT_NEAR(box_distance({0, 0, 0, 2, 2}, {5, 5, M_PI / 4, 2 * std::sqrt(2.0), 2 * std::sqrt(2.0)}), 6 / std::sqrt(2.0),
                1e-9);
}

TEST(ScenarioPlay, ReadsRecordingsAndLogs) {
    std::istringstream bad(std::string{header} + "0.0, 0, Ego, 1, 2\n");
    try {
        read_trajectories(bad, "run.csv");
        FAIL() << "a short row was read";
    } catch (const railodd::InputError& e) {
        EXPECT_EQ(e.where(), "run.csv:2");
    }
    std::istringstream no_header("a, b\n");
    EXPECT_THROW(read_trajectories(no_header, "run.csv"), railodd::InputError);
    std::istringstream log("[] [error] Unsupported geo reference attr: +no_defs\n"
                           "[] [warn] Unknown userData key: osm\n[] [warn] Unknown userData key: osm\n"
                           "[1.0] [error] Entity X not found\n");
    const PlayerLog l = read_player_log(log);
    EXPECT_EQ(l.ignorable_errors.size(), 1u);
    ASSERT_EQ(l.errors.size(), 1u);
    EXPECT_NE(l.errors[0].find("Entity X"), std::string::npos);
    EXPECT_EQ(l.warnings.size(), 1u) << "distinct warnings";
}

// Krems: a road user's target on a crossing road cut back beside the track;
// the player reported it on the other road there (2382, at its own s). Placed
// on the map (target x, y, as play does from the scenario's map), the target
// is judged by where the actor ended, not by the road the player names.
TEST(ScenarioPlay, ATargetPlacedOnTheMapIsJudgedWhereTheActorEnds) {
    auto rows = crossing_run();
    for (auto& r : rows) {
        if (r.name == "Car" && r.y > -1.0) {
            r.road = "2382";
            r.s = 3.0;
        }
    }
    json m = crossing_manifest();
    m["actors"][0].erase("move_to"); // not the on-track rule: the target alone
    EXPECT_FALSE(passed(analyse(m, read(rows), {}, {}), "Car reaches its target"));
    m["actors"][0]["target"]["x"] = 600.0;
    m["actors"][0]["target"]["y"] = 0.8;
    EXPECT_TRUE(passed(analyse(m, read(rows), {}, {}), "Car reaches its target"));
    m["actors"][0]["target"]["y"] = 4.0;
    EXPECT_FALSE(passed(analyse(m, read(rows), {}, {}), "Car reaches its target"));
}

// The player may report the road a crossing road ends on once the car is at
// its target there (within its 1.5 m); anywhere else that is leaving its
// road's lane.
TEST(ScenarioPlay, ARoadUserAtItsTargetMayStandOnTheNextRoad) {
    auto rows = crossing_run();
    for (auto& r : rows) {
        if (r.name == "Car" && r.y > -1.0) {
            r.road = "2382";
            r.s = 0.1;
        }
    }
    json m = crossing_manifest();
    m["actors"][0]["target"]["x"] = 600.0;
    m["actors"][0]["target"]["y"] = 0.0;
    EXPECT_TRUE(passed(analyse(m, read(rows), {}, {}), "Car stays on its road's lane"));
    m["actors"][0]["target"]["y"] = 5.0;
    EXPECT_FALSE(passed(analyse(m, read(rows), {}, {}), "Car stays on its road's lane"));
    m["actors"][0]["target"].erase("x");
    m["actors"][0]["target"].erase("y");
    EXPECT_FALSE(passed(analyse(m, read(rows), {}, {}), "Car stays on its road's lane"));
}
