// railodd::xodr_check across links, on small handwritten maps broken by hand:
// road / junction id collisions, contactPoint consistency, elevation (height
// and grade) continuity across links and duplicate junction connections.
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

// A road with one <elevation> record z(s) = a + b s.
std::string road(const RoadSpec& spec, double a, double b) {
    std::string xml = road_xml(spec);
    const std::string profile = "<elevationProfile><elevation s=\"0\" a=\"" + num(a) + "\" b=\"" + num(b) +
                                "\" c=\"0\" d=\"0\"/></elevationProfile>\n";
    return xml.insert(xml.find("</planView>\n") + 12, profile);
}

// The parts of the good map, each replaceable by a broken one. All on the x
// axis, rising 1 % eastwards:
//   road 1 (0..100) -> junction 100 [connecting road 10 (100..120)] -> road 2 (120..170)
//   road 2 end == road 3 end: road 3 runs back west from x=220 (head to head).
struct Map {
    std::string road1 = road({"1", 100, line_geometry(0, 0, 0, 100), "rail", link("successor", "junction", "100")},
                             0.0, 0.01);
    std::string road10 = road({"10", 20, line_geometry(100, 0, 0, 20), "rail",
                               link("predecessor", "road", "1", "end") + link("successor", "road", "2", "start"), "100"},
                              1.0, 0.01);
    std::string road2 = road({"2", 50, line_geometry(120, 0, 0, 50), "rail",
                              link("predecessor", "junction", "100") + link("successor", "road", "3", "end")},
                             1.2, 0.01);
    // Along its own s road 3 runs west, so it falls: -1 % along s is +1 % eastwards.
    std::string road3 = road({"3", 50, line_geometry(220, 0, pi, 50), "rail", link("successor", "road", "2", "end")},
                             2.2, -0.01);
    std::string junction_id = "100";
    std::string connections = "<connection id=\"0\" incomingRoad=\"1\" connectingRoad=\"10\" contactPoint=\"start\">"
                              "<laneLink from=\"-1\" to=\"-1\"/></connection>";

    std::string xml() const {
        return document(road1 + road10 + road2 + road3 + "<junction id=\"" + junction_id + "\" name=\"j\">" +
                        connections + "</junction>\n");
    }
};

xc::CheckResult check(const Map& m) { return xc::check_text(m.xml(), "continuity.xodr"); }

std::size_t count(const xc::CheckResult& r, const std::string& check) {
    std::size_t n = 0;
    for (const auto& f : r.findings) {
        n += f.check == check ? 1 : 0;
    }
    return n;
}

bool says(const xc::Finding* f, const std::string& text) {
    return f && f->message.find(text) != std::string::npos;
}

} // namespace

TEST(XodrCheckContinuity, CorrectTinyMapPassesEveryCheck) {
    const auto r = check(Map{});
    EXPECT_TRUE(r.passed()) << listing(r);
    EXPECT_EQ(r.findings.size(), 0u) << listing(r);
    // 1 -> 10, 10 -> 2, 2 = 3 head to head; connection 0 is the same ends as 10 <- 1.
    EXPECT_LT(r.summary.link_height_m.value, 1e-9);
    EXPECT_LT(r.summary.link_grade.value, 1e-12);
    EXPECT_EQ(r.summary.junctions, 1u);
}

TEST(XodrCheckContinuity, JunctionIdEqualToARoadIdIsAnError) {
    Map m;
    // Junction "2" while road 2 exists: a reader resolving elementId by road id
    // first takes road 1's and road 2's links into the junction for links to road 2.
    m.junction_id = "2";
    m.road1 = road({"1", 100, line_geometry(0, 0, 0, 100), "rail", link("successor", "junction", "2")}, 0.0, 0.01);
    m.road10 = road({"10", 20, line_geometry(100, 0, 0, 20), "rail",
                     link("predecessor", "road", "1", "end") + link("successor", "road", "2", "start"), "2"},
                    1.0, 0.01);
    m.road2 = road({"2", 50, line_geometry(120, 0, 0, 50), "rail",
                    link("predecessor", "junction", "2") + link("successor", "road", "3", "end")},
                   1.2, 0.01);
    const auto r = check(m);
    const auto* f = find(r, "id_collision", "2");
    ASSERT_NE(f, nullptr) << listing(r);
    EXPECT_EQ(f->object, "junction");
    EXPECT_EQ(f->severity, xc::Severity::error);
    EXPECT_TRUE(says(f, "road 2 ('r2')")) << f->message;
    EXPECT_TRUE(says(f, "the 2 link(s) naming this junction read as links to road 2")) << f->message;
    EXPECT_EQ(r.errors(), 1u) << listing(r);
    EXPECT_FALSE(r.passed());
}

TEST(XodrCheckContinuity, HeightStepBetweenLinkedRoadsIsAnError) {
    Map m;
    // Road 3 at 447 m above road 2 (the OSM ele on some roads only, without a DEM).
    m.road3 = road({"3", 50, line_geometry(220, 0, pi, 50), "rail", link("successor", "road", "2", "end")}, 449.2,
                   -0.01);
    const auto r = check(m);
    ASSERT_EQ(count(r, "link_height"), 1u) << listing(r); // both roads name the link: compared once
    const auto* f = find(r, "link_height");
    EXPECT_TRUE(says(f, "height step 447 m (limit 0.05 m)")) << f->message;
    EXPECT_TRUE(says(f, "road 2 end (z=1.700 m) / road 3 end (z=448.700 m)")) << f->message;
    EXPECT_NEAR(r.summary.link_height_m.value, 447.0, 1e-9);
    EXPECT_EQ(r.errors(), 1u) << listing(r);
}

TEST(XodrCheckContinuity, SmallHeightDifferenceIsWithinTolerance) {
    Map m;
    m.road3 = road({"3", 50, line_geometry(220, 0, pi, 50), "rail", link("successor", "road", "2", "end")}, 2.23,
                   -0.01);
    const auto r = check(m);
    EXPECT_TRUE(r.passed()) << listing(r);
    EXPECT_NEAR(r.summary.link_height_m.value, 0.03, 1e-9);
}

TEST(XodrCheckContinuity, GradeKinkIsAnErrorTakingTheDirectionIntoAccount) {
    Map m;
    // End -> start: road 2 leaves the junction road at the right height but 3 % instead of 1 %.
    m.road2 = road({"2", 50, line_geometry(120, 0, 0, 50), "rail",
                    link("predecessor", "junction", "100") + link("successor", "road", "3", "end")},
                   1.2, 0.03);
    m.road3 = road({"3", 50, line_geometry(220, 0, pi, 50), "rail", link("successor", "road", "2", "end")}, 4.2,
                   -0.03);
    auto r = check(m);
    const auto* f = find(r, "link_grade", "10");
    ASSERT_NE(f, nullptr) << listing(r);
    EXPECT_TRUE(says(f, "grade change 0.02 (limit 0.01) at road 10 end (grade +0.01000) / road 2 start (grade "
                        "+0.03000)")) << f->message;
    EXPECT_EQ(r.errors(), 1u) << listing(r); // 2 = 3 head to head still agree

    // Head to head (end = end): road 3 rising +1 % along its own s falls 1 % seen from road 2,
    // a kink of 2 % although both grades read +0.01 along s.
    Map h;
    h.road3 = road({"3", 50, line_geometry(220, 0, pi, 50), "rail", link("successor", "road", "2", "end")}, 1.2, 0.01);
    r = check(h);
    ASSERT_EQ(count(r, "link_grade"), 1u) << listing(r);
    f = find(r, "link_grade");
    EXPECT_TRUE(says(f, "grade change 0.02 (limit 0.01) at road 2 end (grade +0.01000) / road 3 end (grade "
                        "-0.01000)")) << f->message;
    EXPECT_NEAR(r.summary.link_grade.value, 0.02, 1e-12);
    EXPECT_EQ(count(r, "link_height"), 0u) << listing(r);
}

TEST(XodrCheckContinuity, WrongContactPointIsAnError) {
    Map m;
    // Road 2's successor says road 3's start, but road 3's end is the one at road 2's end.
    m.road2 = road({"2", 50, line_geometry(120, 0, 0, 50), "rail",
                    link("predecessor", "junction", "100") + link("successor", "road", "3", "start")},
                   1.2, 0.01);
    const auto r = check(m);
    const auto* f = find(r, "contact_point", "2");
    ASSERT_NE(f, nullptr) << listing(r);
    EXPECT_TRUE(says(f, "successor to road 3 has contactPoint 'start', but that end lies 50.000 m from road 2 end "
                        "and its end 0.000 m")) << f->message;
    // Road 3's successor names road 2's end, which names road 3's start back.
    const auto* back = find(r, "link_reverse", "3");
    ASSERT_NE(back, nullptr) << listing(r);
    EXPECT_TRUE(says(back, "successor names road 2 end, but road 2's successor names road 3 start, not road 3 end"))
        << back->message;
    EXPECT_NE(find(r, "link_gap", "2"), nullptr) << listing(r); // the links check measures the same gap
}

TEST(XodrCheckContinuity, LinkThatIsNotNamedBackIsAnError) {
    Map m;
    // Road 3's successor names road 2's start, while road 2's end names road 3's end.
    m.road3 = road({"3", 50, line_geometry(220, 0, pi, 50), "rail", link("successor", "road", "2", "start")}, 2.2,
                   -0.01);
    const auto r = check(m);
    const auto* f = find(r, "link_reverse", "2");
    ASSERT_NE(f, nullptr) << listing(r);
    EXPECT_TRUE(says(f, "successor names road 3 end, but road 3's successor names road 2 start, not road 2 end"))
        << f->message;
    EXPECT_NE(find(r, "contact_point", "3"), nullptr) << listing(r);
}

TEST(XodrCheckContinuity, WrongConnectionContactPointIsAnError) {
    Map m;
    m.connections = "<connection id=\"0\" incomingRoad=\"1\" connectingRoad=\"10\" contactPoint=\"end\">"
                    "<laneLink from=\"-1\" to=\"-1\"/></connection>";
    const auto r = check(m);
    const auto* f = find(r, "contact_point", "100");
    ASSERT_NE(f, nullptr) << listing(r);
    EXPECT_EQ(f->object, "junction");
    EXPECT_TRUE(says(f, "connection 0: contactPoint 'end' names road 10 end, which lies 20.000 m from road 1 end, "
                        "but its start lies 0.000 m from it")) << f->message;
    // Road 10's successor (its end) names road 2, not the incoming road.
    const auto* own = find(r, "connection_link", "100");
    ASSERT_NE(own, nullptr) << listing(r);
    EXPECT_TRUE(says(own, "connecting road 10's successor (at its contactPoint end) names road 2 start, not road 1 end"))
        << own->message;
}

TEST(XodrCheckContinuity, ConnectingRoadWithoutALinkToItsIncomingRoadIsAnError) {
    Map m;
    m.road10 = road({"10", 20, line_geometry(100, 0, 0, 20), "rail", link("successor", "road", "2", "start"), "100"},
                    1.0, 0.01);
    const auto r = check(m);
    const auto* f = find(r, "connection_link", "100");
    ASSERT_NE(f, nullptr) << listing(r);
    EXPECT_TRUE(says(f, "predecessor (at its contactPoint start) is missing")) << f->message;
    EXPECT_EQ(r.errors(), 1u) << listing(r);
}

TEST(XodrCheckContinuity, HeightStepAtAJunctionContactIsComparedOnce) {
    Map m;
    // The connecting road starts 2 m above road 1's end; it also links to road 1, so one finding.
    m.road10 = road({"10", 20, line_geometry(100, 0, 0, 20), "rail",
                     link("predecessor", "road", "1", "end") + link("successor", "road", "2", "start"), "100"},
                    3.0, 0.01);
    auto r = check(m);
    EXPECT_EQ(count(r, "link_height") + count(r, "connection_height"), 2u) << listing(r); // 1 -> 10 and 10 -> 2
    EXPECT_NE(find(r, "link_height", "10"), nullptr) << listing(r);

    // Without that link the connection's contact is compared instead.
    m.road10 = road({"10", 20, line_geometry(100, 0, 0, 20), "rail", link("successor", "road", "2", "start"), "100"},
                    3.0, 0.01);
    r = check(m);
    const auto* f = find(r, "connection_height", "100");
    ASSERT_NE(f, nullptr) << listing(r);
    EXPECT_TRUE(says(f, "height step 2 m (limit 0.05 m) at road 1 end (z=1.000 m) / road 10 start (z=3.000 m)"))
        << f->message;
}

TEST(XodrCheckContinuity, DuplicateConnectionsAreErrors) {
    Map m;
    // Connecting road 10 named again from its other end, and the first connection repeated.
    m.connections += "<connection id=\"1\" incomingRoad=\"2\" connectingRoad=\"10\" contactPoint=\"end\">"
                     "<laneLink from=\"-1\" to=\"-1\"/></connection>"
                     "<connection id=\"2\" incomingRoad=\"1\" connectingRoad=\"10\" contactPoint=\"start\">"
                     "<laneLink from=\"-1\" to=\"-1\"/></connection>";
    // Road 2's start links to the junction already; connection 1 is otherwise sound.
    const auto r = check(m);
    ASSERT_EQ(count(r, "duplicate_connection"), 2u) << listing(r);
    std::vector<const xc::Finding*> dups;
    for (const auto& f : r.findings) {
        if (f.check == "duplicate_connection") {
            dups.push_back(&f);
        }
    }
    EXPECT_EQ(dups[0]->id, "100");
    EXPECT_TRUE(says(dups[0], "connection 1 names connecting road 10 again (from incoming road 2; connection 0 "
                              "names it from incoming road 1)")) << dups[0]->message;
    EXPECT_TRUE(says(dups[1], "connection 2 repeats connection 0 (incoming road 1, connecting road 10)"))
        << dups[1]->message;
    EXPECT_EQ(r.errors(), 2u) << listing(r);
}

TEST(XodrCheckContinuity, DirectJunctionRepeatsOnlyTheSamePair) {
    // 1.8 direct junction 50: road 1 splits into roads 2 and 3 and road 4 merges into road 2.
    const auto direct = [](const std::string& connections) {
        return document("<junction id=\"50\" type=\"direct\">" + connections + "</junction>\n", 8);
    };
    const std::string ok = "<connection id=\"0\" incomingRoad=\"1\" linkedRoad=\"2\" contactPoint=\"start\"/>"
                           "<connection id=\"1\" incomingRoad=\"1\" linkedRoad=\"3\" contactPoint=\"start\"/>"
                           "<connection id=\"2\" incomingRoad=\"4\" linkedRoad=\"2\" contactPoint=\"start\"/>";
    EXPECT_EQ(count(xc::check_text(direct(ok), "direct.xodr"), "duplicate_connection"), 0u);
    const auto r = xc::check_text(
        direct(ok + "<connection id=\"3\" incomingRoad=\"4\" linkedRoad=\"2\" contactPoint=\"start\"/>"), "direct.xodr");
    ASSERT_EQ(count(r, "duplicate_connection"), 1u) << listing(r);
    EXPECT_TRUE(says(find(r, "duplicate_connection"), "connection 3 repeats connection 2 (incoming road 4, linked road 2)"))
        << listing(r);
}
