// railodd::xodr_check links, junctions and rail extensions on small
// handwritten documents.
#include "xodr_check_support.hpp"

#include <gtest/gtest.h>

#include <numbers>

using namespace railodd::test;
namespace xc = railodd::xodr_check;

namespace {

constexpr double pi = std::numbers::pi;

std::string link(const std::string& which, const std::string& type, const std::string& id,
                 const std::string& contact = "") {
    std::string l = "<" + which + " elementType=\"" + type + "\" elementId=\"" + id + "\"";
    if (!contact.empty()) {
        l += " contactPoint=\"" + contact + "\"";
    }
    return l + "/>";
}

// Road 1: a 50 m arc of curvature 1/100 from the origin heading east.
RoadSpec arc_road(const std::string& link_xml, const std::string& lane_type = "rail") {
    return {"1", 50, arc_geometry(0, 0, 0, 0.01, 50), lane_type, link_xml};
}

RefPose arc_end() { return ref_arc({0, 0, 0, 0.01}, 0.01, 50); }

xc::CheckResult check(const std::string& body) { return xc::check_text(document(body), "links.xodr"); }

} // namespace

TEST(XodrCheckLinks, MissingLinkTargetFails) {
    const auto r = check(road_xml(arc_road(link("predecessor", "junction", "5") + link("successor", "road", "99", "start"))));
    ASSERT_EQ(r.errors(), 2u) << listing(r);
    // Document order: the predecessor (at s=0) first, then the successor (at the road's end).
    EXPECT_EQ(r.findings[0].check, "link_target");
    EXPECT_NE(r.findings[0].message.find("junction '5'"), std::string::npos) << r.findings[0].message;
    EXPECT_DOUBLE_EQ(r.findings[0].s, 0.0);
    EXPECT_EQ(r.findings[1].check, "link_target");
    EXPECT_EQ(r.findings[1].id, "1");
    EXPECT_NE(r.findings[1].message.find("road '99'"), std::string::npos) << r.findings[1].message;
    EXPECT_DOUBLE_EQ(r.findings[1].s, 50.0);
}

TEST(XodrCheckLinks, EndToStartLinkPassesWhenRoadsMeetAndIsComparedOnce) {
    const RefPose e = arc_end();
    const std::string body =
        road_xml(arc_road(link("successor", "road", "2", "start"))) +
        road_xml({"2", 30, arc_geometry(e.x, e.y, e.hdg, 0.01, 30), "rail", link("predecessor", "road", "1", "end")});
    const auto r = check(body);
    EXPECT_TRUE(r.passed()) << listing(r);
    EXPECT_EQ(r.summary.links_checked, 1u);
    EXPECT_LT(r.summary.gap_m.value, 1e-9);
}

TEST(XodrCheckLinks, EndToEndLinkPassesWithReversedRoad) {
    // Road 2 is the arc's continuation driven backwards: it starts 30 m further
    // on, heads back, and bends the other way (curvature -1/100).
    const RefPose e = arc_end();
    const RefPose f = ref_arc(e, 0.01, 30);
    const std::string body = road_xml(arc_road(link("successor", "road", "2", "end"))) +
                             road_xml({"2", 30, arc_geometry(f.x, f.y, f.hdg + pi, -0.01, 30), "rail",
                                       link("successor", "road", "1", "end")});
    const auto r = check(body);
    EXPECT_TRUE(r.passed()) << listing(r);
    EXPECT_EQ(r.summary.links_checked, 1u);
}

TEST(XodrCheckLinks, EndToEndCurvatureJumpFailsOnRailOnly) {
    // A straight road ending at the arc's end, head to head: G1 but not G2.
    const RefPose e = arc_end();
    const auto body = [&](const std::string& lanes) {
        return road_xml(arc_road(link("successor", "road", "2", "end"), lanes)) +
               road_xml({"2", 30, line_geometry(e.x + 30 * std::cos(e.hdg), e.y + 30 * std::sin(e.hdg), e.hdg + pi, 30),
                         lanes, link("successor", "road", "1", "end")});
    };
    const auto rail = check(body("rail"));
    const auto* f = find(rail, "link_curvature", "1");
    ASSERT_NE(f, nullptr) << listing(rail);
    EXPECT_NEAR(rail.summary.rail_curvature_jump.value, 0.01, 1e-12);
    EXPECT_EQ(rail.errors(), 1u) << listing(rail);
    EXPECT_TRUE(check(body("driving")).passed());
}

TEST(XodrCheckLinks, LinkedRoadsThatDoNotMeetFail) {
    const RefPose e = arc_end();
    const std::string gap = road_xml(arc_road(link("successor", "road", "2", "start"))) +
                            road_xml({"2", 30, arc_geometry(e.x, e.y + 1.0, e.hdg, 0.01, 30)});
    const auto r1 = check(gap);
    const auto* f = find(r1, "link_gap", "1");
    ASSERT_NE(f, nullptr) << listing(r1);
    EXPECT_NE(f->message.find("road 1 end / road 2 start"), std::string::npos) << f->message;

    // Same place, wrong direction: an end->start link where road 2 heads back.
    const std::string turned = road_xml(arc_road(link("successor", "road", "2", "start"))) +
                               road_xml({"2", 30, arc_geometry(e.x, e.y, e.hdg + pi, -0.01, 30)});
    EXPECT_NE(find(check(turned), "link_heading", "1"), nullptr);
    // A wrong contact point: road 2's end is 30 m away.
    const std::string wrong_end = road_xml(arc_road(link("successor", "road", "2", "end"))) +
                                  road_xml({"2", 30, arc_geometry(e.x, e.y, e.hdg, 0.01, 30)});
    EXPECT_NE(find(check(wrong_end), "link_gap", "1"), nullptr);
}

namespace {

// Incoming road 1 (0,0)->(100,0) into junction 100; connecting road 10 from
// (100, dy) eastwards, in the junction; road 2 leaves it.
std::string junction_doc(double dy, const std::string& lane_link = "<laneLink from=\"-1\" to=\"-1\"/>") {
    return road_xml({"1", 100, line_geometry(0, 0, 0, 100), "rail", link("successor", "junction", "100")}) +
           road_xml({"10", 20, line_geometry(100, dy, 0, 20), "rail",
                     link("predecessor", "road", "1", "end") + link("successor", "road", "2", "start"), "100"}) +
           road_xml({"2", 50, line_geometry(120, dy, 0, 50), "rail", link("predecessor", "junction", "100")}) +
           "<junction id=\"100\" name=\"j\">"
           "<connection id=\"0\" incomingRoad=\"1\" connectingRoad=\"10\" contactPoint=\"start\">" +
           lane_link + "</connection></junction>\n";
}

} // namespace

TEST(XodrCheckLinks, JunctionConnectionThatTouchesPasses) {
    const auto r = check(junction_doc(0.0));
    EXPECT_TRUE(r.passed()) << listing(r);
    EXPECT_EQ(r.summary.junctions, 1u);
    EXPECT_EQ(r.summary.connections, 1u);
    EXPECT_EQ(r.summary.links_checked, 3u); // 10<-1, 10->2, connection 0
}

TEST(XodrCheckLinks, JunctionConnectionThatDoesNotTouchFails) {
    const auto r = check(junction_doc(0.5));
    const auto* f = find(r, "connection_gap", "100");
    ASSERT_NE(f, nullptr) << listing(r);
    EXPECT_EQ(f->object, "junction");
    EXPECT_NE(f->message.find("road 10 start / road 1 end"), std::string::npos) << f->message;
}

TEST(XodrCheckLinks, JunctionLaneLinkToMissingLaneFails) {
    const auto r = check(junction_doc(0.0, "<laneLink from=\"-1\" to=\"-3\"/>"));
    const auto* f = find(r, "lane_link", "100");
    ASSERT_NE(f, nullptr) << listing(r);
    EXPECT_NE(f->message.find("to=-3"), std::string::npos);
    EXPECT_EQ(r.errors(), 1u) << listing(r);
}

TEST(XodrCheckLinks, ConnectingRoadOutsideJunctionAndUnlinkedIncomingFail) {
    std::string body = junction_doc(0.0);
    body.replace(body.find("junction=\"100\""), 14, "junction=\"-1\"");
    body.replace(body.find("elementType=\"junction\" elementId=\"100\""), 38, "elementType=\"road\" elementId=\"10\" contactPoint=\"start\"");
    const auto r = check(body);
    EXPECT_NE(find(r, "connection_junction", "100"), nullptr) << listing(r);
    EXPECT_NE(find(r, "connection_incoming_link", "100"), nullptr) << listing(r);
}

TEST(XodrCheckLinks, SwitchNamingMissingRoadFails) {
    const std::string sw = "<railroad><switch name=\"W1\" id=\"w1\" position=\"dynamic\">"
                           "<mainTrack id=\"1\" s=\"0\" dir=\"+\"/><sideTrack id=\"77\" s=\"0\" dir=\"+\"/>"
                           "</switch></railroad>";
    RoadSpec road = arc_road("");
    road.extra = sw;
    const auto r = check(road_xml(road));
    const auto* f = find(r, "switch_track", "1");
    ASSERT_NE(f, nullptr) << listing(r);
    EXPECT_NE(f->message.find("'77'"), std::string::npos) << f->message;
    EXPECT_EQ(r.summary.switches, 1u);
    EXPECT_EQ(r.errors(), 1u) << listing(r);
}

TEST(XodrCheckLinks, StationSegmentsSignalsAndObjectsStayOnTheirRoads) {
    RoadSpec road = arc_road("");
    road.extra = "<objects><object id=\"o1\" s=\"49\" t=\"0\" zOffset=\"0\" type=\"pole\"/></objects>"
                 "<signals><signal id=\"s1\" s=\"50.5\" t=\"2\" zOffset=\"0\" dynamic=\"yes\" orientation=\"+\"/></signals>";
    const std::string station = "<station id=\"st1\" name=\"Halt\"><platform id=\"p1\">"
                                "<segment roadId=\"1\" sStart=\"10\" sEnd=\"40\" side=\"right\"/>"
                                "<segment roadId=\"1\" sStart=\"30\" sEnd=\"60\" side=\"left\"/>"
                                "<segment roadId=\"8\" sStart=\"0\" sEnd=\"1\" side=\"left\"/>"
                                "</platform></station>\n";
    const auto r = check(road_xml(road) + station);
    EXPECT_NE(find(r, "signal_s", "1"), nullptr) << listing(r);
    EXPECT_EQ(find(r, "object_s"), nullptr) << listing(r);
    EXPECT_EQ(r.summary.stations, 1u);
    std::size_t segment_errors = 0;
    for (const auto& f : r.findings) {
        segment_errors += f.check == "station_segment" && f.id == "st1";
    }
    EXPECT_EQ(segment_errors, 2u) << listing(r); // sEnd beyond 50 m, and road 8
}

TEST(XodrCheckLinks, CrossingJunctionListsExistingRoads) {
    const std::string crossing = "<junction id=\"200\" type=\"crossing\"><roadSection id=\"a\" roadId=\"1\" sStart=\"10\" "
                                 "sEnd=\"20\"/><roadSection id=\"b\" roadId=\"42\"/></junction>\n";
    const auto r = xc::check_text(document(road_xml(arc_road("")) + crossing, 8), "crossing.xodr");
    const auto* f = find(r, "crossing_road", "200");
    ASSERT_NE(f, nullptr) << listing(r);
    EXPECT_NE(f->message.find("'42'"), std::string::npos);
    EXPECT_EQ(r.errors(), 1u) << listing(r);
    EXPECT_EQ(r.summary.version, "1.8");
}

// Integers no int can hold (a lane link's from, found by fuzz_xodr_reader as
// -2e109) are findings naming the attribute, not a conversion.
TEST(XodrCheckLinks, LaneLinkBeyondIntRangeIsAFindingNotAConversion) {
    for (const char* value : {"-2e109", "2147483648", "1e300"}) {
        SCOPED_TRACE(value);
        const auto r = check(junction_doc(0.0, std::string{"<laneLink from=\""} + value + "\" to=\"-1\"/>"));
        bool named = false;
        for (const auto& f : r.findings) {
            named = named || (f.check == "attribute" && f.message.find("@from is out of range: '" + std::string{value}) !=
                                                            std::string::npos);
        }
        EXPECT_TRUE(named) << listing(r);
    }
    const auto ok = check(junction_doc(0.0, "<laneLink from=\"-1\" to=\"-1\"/>"));
    for (const auto& f : ok.findings) {
        EXPECT_NE(f.check, "attribute") << listing(ok);
    }
}

// The header's revision numbers the same way (revMinor of 58 eights, found by
// fuzz_xodr_reader after the lane link's fix).
TEST(XodrCheckLinks, HeaderRevisionBeyondIntRangeIsAFinding) {
    std::string doc = document(road_xml(arc_road("")));
    doc.replace(doc.find("revMinor=\"7\""), 12, "revMinor=\"" + std::string(58, '8') + "\"");
    const auto r = xc::check_text(doc, "rev.xodr");
    bool named = false;
    for (const auto& f : r.findings) {
        named = named || (f.check == "attribute" && f.message.find("@revMinor is out of range") != std::string::npos);
    }
    EXPECT_TRUE(named) << listing(r);
}
