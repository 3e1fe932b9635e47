// Anchoring templates on a hand-made profile whose geometry is known: which
// places satisfy a requirement, the lane positions around them, and the
// chainage-to-road mapping on forward and reversed route pieces.
#include "railodd/odd/taxonomy.hpp"
#include "railodd/scenario/anchors.hpp"

#include "odd_profile_support.hpp"

#include <gtest/gtest.h>

using namespace railodd;
using namespace railodd::scenario;
using railodd::test::tagged;

namespace {

const std::string straight = "Scenery/Track geometry/Horizontal/Straight";
const std::string curve = "Scenery/Track geometry/Horizontal/Curve";
const std::string crossing = "Scenery/Crossings/Level crossing";

// One track: road 1 from chainage 0 to 1000 (a 250 m curve at 100-350), road 2
// from 1000 to 1600 (its s from 0); crossings at 450 (open) and 1200 (full).
odd::OddProfile profile() {
    odd::OddProfile p;
    p.elements = {
        tagged(straight, "sc.geo.hz.straight", {}, "1", 0, 100, 0, 100, {"way:1"}),
        tagged(curve, "sc.geo.hz.curve", {{"radius", 250.0}}, "1", 100, 350, 100, 350, {"way:1"}),
        tagged(straight, "sc.geo.hz.straight", {}, "1", 350, 1000, 350, 1000, {"way:1"}),
        tagged(straight, "sc.geo.hz.straight", {}, "2", 0, 600, 1000, 1600, {"way:2"}),
        tagged("Operational Conditions/Speed/Speed limit", "op.speed.limit", {{"maxspeed", 120.0}}, "1", 0, 1000, 0,
               1000, {"way:1"}),
        tagged(crossing, "sc.xing.level", {{"barrier", std::string{"no"}}}, "1", 450, 450, 450, 450, {"node:5"}),
        tagged(crossing, "sc.xing.level", {{"barrier", std::string{"full"}}}, "2", 200, 200, 1200, 1200, {"node:6"}),
    };
    return p;
}

Template crossing_after_curve(double within, double max_radius) {
    Template t;
    t.id = "t";
    t.anchor.element = crossing;
    ContextRequirement c;
    c.element = curve;
    c.within_m = within;
    c.where.push_back({"radius", std::nullopt, max_radius, {}, 0});
    t.context.push_back(c);
    t.ego.run_up_m = 400;
    t.ego.min_run_up_m = 100;
    t.ego.overrun_m = 200;
    return t;
}

} // namespace

TEST(ScenarioAnchors, LineIndexMapsChainageToRoadAndS) {
    const auto p = profile();
    const LineIndex lines(p);
    EXPECT_DOUBLE_EQ(lines.start(0), 0.0);
    EXPECT_DOUBLE_EQ(lines.end(0), 1600.0);
    const auto a = lines.at(0, 1200.0);
    ASSERT_TRUE(a);
    EXPECT_EQ(a->road_id, "2");
    EXPECT_DOUBLE_EQ(a->s, 200.0);
    EXPECT_EQ(a->lane_id, -1);
    EXPECT_FALSE(a->reversed);
    EXPECT_FALSE(lines.at(0, 1700.0));
    EXPECT_FALSE(lines.at(3, 10.0));
    const auto w = lines.waypoints(0, 300.0, 1300.0);
    ASSERT_EQ(w.size(), 3u);
    EXPECT_EQ(w[0].road_id, "1");
    EXPECT_DOUBLE_EQ(w[0].s, 300.0);
    EXPECT_EQ(w[1].road_id, "2");
    EXPECT_DOUBLE_EQ(w[1].s, 150.0); // the middle of road 2's run, chainage 1000-1300
    EXPECT_EQ(w[2].road_id, "2");
    EXPECT_DOUBLE_EQ(w[2].s, 300.0);
}

TEST(ScenarioAnchors, ReversedRoutePieceRunsAgainstS) {
    odd::OddProfile p;
    p.along_route = true;
    auto e = tagged(straight, "sc.geo.hz.straight", {}, "5", 0, 100, 0, 100, {"way:9"});
    e.reversed = true;
    e.track = 4;
    auto f = tagged(straight, "sc.geo.hz.straight", {}, "6", 0, 50, 100, 150, {"way:9"});
    f.track = 7; // another edge: on a route every element lies on the one line
    p.elements = {e, f};
    const LineIndex lines(p);
    const auto a = lines.at(0, 30.0);
    ASSERT_TRUE(a);
    EXPECT_EQ(a->road_id, "5");
    EXPECT_DOUBLE_EQ(a->s, 70.0);
    EXPECT_TRUE(a->reversed);
    const auto b = lines.at(0, 120.0);
    ASSERT_TRUE(b);
    EXPECT_EQ(b->road_id, "6");
    EXPECT_DOUBLE_EQ(b->s, 20.0);
}

TEST(ScenarioAnchors, ContextMustEndWithinReachBeforeTheAnchor) {
    const auto p = profile();
    const LineIndex lines(p);
    // The curve ends at 350: 100 m before the first crossing, 850 m before the second.
    const auto near = find_anchors(p, lines, crossing_after_curve(200, 300));
    ASSERT_EQ(near.anchors.size(), 1u);
    const Anchor& a = near.anchors[0];
    EXPECT_EQ(p.elements[a.element].osm_ids, std::vector<std::string>{"node:5"});
    EXPECT_DOUBLE_EQ(a.chainage, 450.0);
    ASSERT_EQ(a.context.size(), 1u);
    EXPECT_EQ(p.elements[a.context[0]].element, curve);
    EXPECT_DOUBLE_EQ(a.start_chainage, 50.0);
    EXPECT_DOUBLE_EQ(a.end_chainage, 650.0);
    EXPECT_DOUBLE_EQ(a.speed_limit_kmh, 120.0);
    EXPECT_EQ(a.place.road_id, "1");
    EXPECT_DOUBLE_EQ(a.place.s, 450.0);

    EXPECT_EQ(find_anchors(p, lines, crossing_after_curve(900, 300)).anchors.size(), 2u);
    EXPECT_TRUE(find_anchors(p, lines, crossing_after_curve(900, 200)).anchors.empty()); // radius too large
}

TEST(ScenarioAnchors, ConditionsAndRunUp) {
    const auto p = profile();
    const LineIndex lines(p);
    Template t;
    t.anchor.element = crossing;
    t.anchor.where.push_back({"barrier", std::nullopt, std::nullopt, {"full", "half"}, 0});
    t.ego.run_up_m = 5000; // more than the track has: starts where the track begins
    t.ego.min_run_up_m = 100;
    auto r = find_anchors(p, lines, t);
    ASSERT_EQ(r.anchors.size(), 1u);
    EXPECT_EQ(r.anchors[0].place.road_id, "2");
    EXPECT_DOUBLE_EQ(r.anchors[0].start_chainage, 0.0);
    EXPECT_DOUBLE_EQ(r.anchors[0].end_chainage, 1400.0);
    EXPECT_TRUE(std::isnan(r.anchors[0].speed_limit_kmh)); // the limit is mapped on road 1 only

    t.anchor.where.clear();
    t.ego.min_run_up_m = 500; // the open crossing at 450 has too little track before it
    r = find_anchors(p, lines, t);
    ASSERT_EQ(r.anchors.size(), 1u);
    ASSERT_EQ(r.skipped.size(), 1u);
    EXPECT_EQ(p.elements[r.skipped[0].element].osm_ids, std::vector<std::string>{"node:5"});
    EXPECT_NE(r.skipped[0].reason.find("450 m of track before the anchor"), std::string::npos) << r.skipped[0].reason;
}

TEST(ScenarioAnchors, MatchesElementsBelowThePath) {
    const auto p = profile();
    ElementMatch m;
    m.element = "Scenery/Track geometry/Horizontal";
    EXPECT_TRUE(matches(p.elements[1], m));
    m.element = "Scenery/Track geometry/Horiz"; // a prefix of a name is not a parent
    EXPECT_FALSE(matches(p.elements[1], m));
}

namespace {

// A station throat: the stem (track 0, road 10, node 1 -> 2) ends at the
// switch (node 2); the main track (track 1, road 11) runs on straight to node
// 3, the branch (track 2, road 12) was drawn from node 4 towards the switch,
// so a train taking it runs against its s. The switch sits on the main
// track's start, facing.
odd::OddProfile throat() {
    odd::OddProfile p;
    auto on = [](odd::TaggedElement e, std::size_t track) {
        e.track = track;
        return e;
    };
    p.elements = {
        on(tagged(straight, "sc.geo.hz.straight", {}, "10", 0, 500, 0, 500, {"way:10"}), 0),
        on(tagged(straight, "sc.geo.hz.straight", {}, "11", 0, 600, 0, 600, {"way:11"}), 1),
        on(tagged(curve, "sc.geo.hz.curve", {{"radius", 300.0}}, "12", 0, 400, 0, 400, {"way:12"}), 2),
        on(tagged("Scenery/Track layout/Switch", "sc.lay.switch", {{"direction", std::string{"facing"}}}, "11", 0, 0, 0,
                  0, {"node:2"}),
           1),
    };
    const double pi = 3.14159265358979;
    p.track_ends = {{0, 1, 2, 0.0, 0.0}, {1, 2, 3, 0.0, 0.0}, {2, 4, 2, pi + 0.2, pi + 0.1}};
    return p;
}

} // namespace

TEST(ScenarioAnchors, LinesRunOnAcrossTheSwitchThroughOrDiverging) {
    const auto p = throat();
    const LineIndex lines(p);
    // Through: the main track, continued back onto the stem.
    EXPECT_DOUBLE_EQ(lines.start(1), -500.0);
    EXPECT_DOUBLE_EQ(lines.end(1), 600.0);
    EXPECT_EQ(lines.at(1, -100.0)->road_id, "10");
    EXPECT_DOUBLE_EQ(lines.at(1, -100.0)->s, 400.0);
    EXPECT_EQ(lines.at(1, 100.0)->road_id, "11");
    // Diverging: the stem, then the branch against its s.
    const auto d = lines.diverging(3);
    ASSERT_TRUE(d);
    EXPECT_FALSE(lines.diverging(0)) << "not a switch";
    EXPECT_DOUBLE_EQ(lines.start(*d), -500.0);
    EXPECT_DOUBLE_EQ(lines.end(*d), 400.0);
    const auto b = lines.at(*d, 100.0);
    ASSERT_TRUE(b);
    EXPECT_EQ(b->road_id, "12");
    EXPECT_DOUBLE_EQ(b->s, 300.0);
    EXPECT_TRUE(b->reversed);
    EXPECT_EQ(lines.at(*d, -100.0)->road_id, "10");
    const auto w = lines.waypoints(*d, -300.0, 300.0); // start, the middle of the branch's run, end
    ASSERT_EQ(w.size(), 3u);
    EXPECT_EQ(w[1].road_id, "12");
    EXPECT_EQ(w.front().road_id, "10");
    EXPECT_EQ(w.back().road_id, "12");
    EXPECT_DOUBLE_EQ(w.back().s, 100.0);

    // The switch's other track, measured from the switch: the branch, against its s.
    const auto on_branch = lines.branch_place(3, 100.0);
    ASSERT_TRUE(on_branch);
    EXPECT_EQ(on_branch->road_id, "12");
    EXPECT_DOUBLE_EQ(on_branch->s, 300.0);
    EXPECT_FALSE(lines.branch_place(3, 450.0)) << "the branch is 400 m long";
    EXPECT_FALSE(lines.branch_place(0, 10.0)) << "not a switch";

    // A template that runs onto the diverging track anchors on that line.
    Template t;
    t.id = "div";
    t.anchor.element = "Scenery/Track layout/Switch";
    t.anchor.diverging = true;
    t.ego.run_up_m = 300;
    t.ego.min_run_up_m = 100;
    t.ego.overrun_m = 200;
    const auto anchoring = find_anchors(p, lines, t, 35.0);
    ASSERT_EQ(anchoring.anchors.size(), 1u);
    const Anchor& a = anchoring.anchors[0];
    EXPECT_EQ(a.line, *d);
    EXPECT_DOUBLE_EQ(a.start_chainage, -300.0);
    EXPECT_DOUBLE_EQ(a.end_chainage, 200.0);
    EXPECT_EQ(lines.at(a.line, a.end_chainage)->road_id, "12");
    t.anchor.diverging = false;
    const auto through = find_anchors(p, lines, t, 35.0);
    ASSERT_EQ(through.anchors.size(), 1u);
    EXPECT_EQ(lines.at(through.anchors[0].line, through.anchors[0].end_chainage)->road_id, "11");

    // Without the branch in the profile there is no diverging run, and the
    // place is listed with the reason.
    auto no_branch = p;
    no_branch.track_ends.pop_back();
    const LineIndex plain(no_branch);
    EXPECT_FALSE(plain.diverging(3));
    t.anchor.diverging = true;
    const auto none = find_anchors(no_branch, plain, t, 35.0);
    EXPECT_TRUE(none.anchors.empty());
    ASSERT_EQ(none.skipped.size(), 1u);
    EXPECT_NE(none.skipped[0].reason.find("no diverging track"), std::string::npos);
}

// A ring of two tracks (a tram's turning loop closed on itself): a line
// does not run on round it to a node it passes already, where the player,
// routed over one junction twice, takes the loop again (Munich).
TEST(ScenarioAnchors, LinesDoNotRunRoundALoopBackToANodeTheyPass) {
    odd::OddProfile p;
    auto on = [](odd::TaggedElement e, std::size_t track) {
        e.track = track;
        return e;
    };
    p.elements = {on(tagged(straight, "sc.geo.hz.straight", {}, "20", 0, 500, 0, 500, {"way:20"}), 0),
                  on(tagged(curve, "sc.geo.hz.curve", {{"radius", 100.0}}, "21", 0, 600, 0, 600, {"way:21"}), 1)};
    p.track_ends = {{0, 1, 2, 0.0, 0.0}, {1, 2, 1, 0.0, 0.0}};
    const LineIndex lines(p);
    EXPECT_DOUBLE_EQ(lines.start(0), 0.0);
    EXPECT_DOUBLE_EQ(lines.end(0), 500.0);
    // An open end still runs on: the ring cut at node 1 into a line 1 -> 2 -> 3.
    p.track_ends = {{0, 1, 2, 0.0, 0.0}, {1, 2, 3, 0.0, 0.0}};
    const LineIndex open(p);
    EXPECT_DOUBLE_EQ(open.end(0), 1100.0);
}

// The stop trigger fires within 5 m of the run's end: an end that would lie
// a few metres into a road (here 2 m into road 3, after a 3 m junction road)
// moves back to where the train stops on a road of its route.
TEST(ScenarioAnchors, RunsDoNotEndJustInsideARoad) {
    odd::OddProfile p;
    p.elements = {
        tagged(straight, "sc.geo.hz.straight", {}, "1", 0, 1000, 0, 1000, {"way:1"}),
        tagged(straight, "sc.geo.hz.straight", {}, "2", 0, 3, 1000, 1003, {"way:2"}),
        tagged(straight, "sc.geo.hz.straight", {}, "3", 0, 600, 1003, 1603, {"way:3"}),
        tagged(crossing, "sc.xing.level", {{"barrier", std::string{"full"}}}, "1", 805, 805, 805, 805, {"node:5"}),
    };
    const LineIndex lines(p);
    EXPECT_DOUBLE_EQ(lines.road_entry(0, 1005.0), 1003.0);
    EXPECT_DOUBLE_EQ(lines.road_entry(0, 1001.0), 1000.0);
    EXPECT_DOUBLE_EQ(lines.road_entry(0, 500.0), 0.0);
    Template t;
    t.id = "t";
    t.anchor.element = crossing;
    t.ego.run_up_m = 400;
    t.ego.min_run_up_m = 100;
    t.ego.overrun_m = 200; // would end at 1005: 2 m into road 3
    const auto a = find_anchors(p, lines, t, 35.0);
    ASSERT_EQ(a.anchors.size(), 1u);
    EXPECT_DOUBLE_EQ(a.anchors[0].end_chainage, 999.5);
    EXPECT_EQ(lines.at(0, a.anchors[0].end_chainage)->road_id, "1");
    t.ego.overrun_m = 250; // 1055: well inside road 3, kept
    EXPECT_DOUBLE_EQ(find_anchors(p, lines, t, 35.0).anchors[0].end_chainage, 1055.0);
}
