// The OpenDRIVE map of the embedded sample route, checked on the model before
// it is written: every edge's roads tile its fitted centreline, every link and
// junction connection is continuous in position, heading and curvature, the
// three switches, two stations, tunnel, bridge and level crossing are there,
// and writing is deterministic.
#include "railodd/geometry/crossings.hpp"
#include "railodd/geometry/feature_attachment.hpp"
#include "railodd/geometry/profiles.hpp"
#include "railodd/geometry/road_fit.hpp"
#include "railodd/ingest/osm_reader.hpp"
#include "railodd/sample/sample_route.hpp"
#include "railodd/xodr/map_builder.hpp"
#include "railodd/xodr/xml_writer.hpp"
#include "test_support.hpp"

#include <cmath>
#include <map>
#include <numbers>
#include <set>

#include <unistd.h> // getpid: one folder per test process (CTest runs tests in parallel; a folder has one writer)

using namespace railodd;

namespace {

struct Fixture {
    ingest::IngestResult ingest;
    geometry::TrackGraph tracks, roads;
    geometry::FittedNetwork fitted, fitted_roads;
    std::vector<geometry::VerticalProfile> profiles;
    std::vector<std::vector<geometry::CantStretch>> cants;
    geometry::Attachment attachment;
    geometry::Crossings crossings;
    xodr::MapBuild build;
};

const Fixture& fixture() {
    static const Fixture f = [] {
        Fixture x;
        const auto dir = test::fs::temp_directory_path() / "railodd-tests" / ("xodr-sample-route-" + std::to_string(::getpid()));
        const sample::SampleFiles files = sample::write_sample_route(dir);
        x.ingest = ingest::read_osm(files.osm, {});
        x.tracks = geometry::build_track_graph(x.ingest.tracks, x.ingest.features);
        x.fitted = geometry::fit_track_graph(x.tracks, geometry::FitOptions{});
        x.profiles = geometry::fit_profiles(x.tracks, x.fitted, x.ingest.tracks, x.ingest.projection, nullptr);
        x.cants = geometry::fit_cants(x.tracks, x.fitted, x.ingest.tracks, geometry::CantOptions{true});
        x.roads = geometry::build_track_graph(x.ingest.roads, {});
        x.fitted_roads = geometry::fit_road_graph(x.roads, geometry::RoadFitOptions{});
        std::vector<geometry::IndexedAlignment> ia;
        for (const auto& e : x.fitted.edges) {
            ia.emplace_back(e.alignment, 2.0);
        }
        x.attachment = geometry::attach_features(x.tracks, ia, x.ingest.features, 50.0, 500.0);
        x.crossings = geometry::find_crossings(x.tracks, x.ingest.tracks, x.ingest.roads, x.ingest.features);
        const geometry::FittedMap g{x.tracks, x.fitted, x.profiles, x.cants, x.attachment, x.crossings, x.roads,
                                    x.fitted_roads, {}};
        const xodr::MapInput in{x.ingest, g};
        x.build = xodr::build_map(in, xodr::MapOptions{});
        return x;
    }();
    return f;
}

geometry::Alignment alignment_of(const xodr::Road& r) {
    geometry::Alignment a;
    a.start = {r.plan_view.front().x, r.plan_view.front().y, r.plan_view.front().hdg, 0.0};
    for (const auto& g : r.plan_view) {
        a.primitives.push_back({g.kind == xodr::PlanGeometry::Kind::line  ? geometry::PrimitiveKind::line
                                : g.kind == xodr::PlanGeometry::Kind::arc ? geometry::PrimitiveKind::arc
                                                                          : geometry::PrimitiveKind::spiral,
                                g.length, g.curv_start, g.curv_end});
    }
    return a;
}

// Pose at a road end, facing out of the road.
geometry::Pose end_pose(const xodr::Road& r, xodr::Contact c) {
    const geometry::Alignment a = alignment_of(r);
    geometry::Pose p = geometry::evaluate(a, c == xodr::Contact::start ? 0.0 : geometry::length(a));
    if (c == xodr::Contact::start) {
        p.hdg += std::numbers::pi;
        p.curvature = -p.curvature;
    }
    return p;
}

// Two road ends meet G2: same point, opposite outward headings, curvatures
// cancelling. Split pieces start at re-evaluated poses: 1e-7 rad is rounding.
void expect_g2(const geometry::Pose& a, const geometry::Pose& b, const std::string& what) {
    EXPECT_LT(std::hypot(a.x - b.x, a.y - b.y), 1e-6) << what;
    EXPECT_LT(std::abs(std::remainder(a.hdg - b.hdg - std::numbers::pi, 2 * std::numbers::pi)), 1e-7) << what;
    EXPECT_LT(std::abs(a.curvature + b.curvature), 1e-9) << what;
}

const xodr::Road& road(const xodr::Map& m, const std::string& id) {
    for (const auto& r : m.roads) {
        if (r.id == id) {
            return r;
        }
    }
    throw std::runtime_error("no road " + id);
}

} // namespace

TEST(XodrRailNetwork, RoadsTileEveryFittedTrack) {
    const Fixture& f = fixture();
    ASSERT_EQ(f.build.rail.pieces.size(), f.tracks.edges.size());
    for (std::size_t e = 0; e < f.tracks.edges.size(); ++e) {
        const auto& pieces = f.build.rail.pieces[e];
        ASSERT_FALSE(pieces.empty()) << "edge " << e;
        double total = 0.0;
        for (const auto& p : pieces) {
            total += f.build.map.roads[p.road].length();
            const auto& r = f.build.map.roads[p.road];
            ASSERT_EQ(r.lane_sections.size(), 1u);
            EXPECT_EQ(r.lane_sections[0].right.size(), 1u);
            EXPECT_TRUE(r.lane_sections[0].left.empty());
            EXPECT_EQ(r.lane_sections[0].right[0].type, "rail");
            // The single lane is centred on the reference line (the track axis).
            EXPECT_DOUBLE_EQ(r.lane_offset * 2.0, r.lane_sections[0].right[0].width);
            EXPECT_NEAR(r.lane_sections[0].right[0].width, 1.435 + 0.072, 1e-12);
        }
        EXPECT_NEAR(total, geometry::length(f.fitted.edges[e].alignment), 1e-6) << "edge " << e;
    }
}

TEST(XodrRailNetwork, SwitchesBecomeJunctionsWithContinuousConnections) {
    const Fixture& f = fixture();
    EXPECT_EQ(f.build.rail.switches, 3u) << "the loop's two switches and the spur's";
    EXPECT_EQ(f.build.rail.junctions, 3u);
    EXPECT_TRUE(f.build.rail.unlinked.empty());
    std::size_t connections = 0;
    for (const auto& j : f.build.map.junctions) {
        if (j.type != "default") {
            continue;
        }
        for (const auto& c : j.connections) {
            const xodr::Road& in = road(f.build.map, c.incoming_road);
            const xodr::Road& cr = road(f.build.map, c.connecting_road);
            if (!in.rail) {
                continue;
            }
            ++connections;
            EXPECT_EQ(cr.junction, j.id);
            EXPECT_EQ(c.contact, xodr::Contact::start) << "the incoming road is the one at the connecting road's start";
            // The incoming road's end that points at this junction.
            const bool at_start = in.predecessor.type == xodr::ElementType::junction && in.predecessor.id == j.id;
            expect_g2(end_pose(in, at_start ? xodr::Contact::start : xodr::Contact::end), end_pose(cr, c.contact),
                      "junction " + j.id + " connection " + c.id);
        }
    }
    // Per switch: one connecting road per leg a train can take from the
    // stem, each named by one connection (readers add the way back).
    EXPECT_EQ(connections, 6u);
}

// What CARLA's loader needs to walk the map: it takes a link's element for a
// road whenever a road has that id, and follows lane ids (a right lane runs
// along s), never contactPoint, so every link must run end -> start.
TEST(XodrRailNetwork, OneIdSpaceAndEveryLinkRunsEndToStart) {
    const Fixture& f = fixture();
    std::set<std::string> road_ids;
    for (const auto& r : f.build.map.roads) {
        road_ids.insert(r.id);
    }
    std::map<std::string, int> named; // connecting road -> connections naming it
    for (const auto& j : f.build.map.junctions) {
        EXPECT_EQ(road_ids.count(j.id), 0u) << "junction " << j.id << " has a road's id";
        for (const auto& c : j.connections) {
            ++named[c.connecting_road];
        }
    }
    for (const auto& [id, n] : named) {
        EXPECT_EQ(n, 1) << "connecting road " << id;
    }
    std::size_t links = 0;
    for (const auto& r : f.build.map.roads) {
        if (!r.rail) {
            continue;
        }
        if (r.successor.type == xodr::ElementType::road) {
            EXPECT_EQ(r.successor.contact, xodr::Contact::start) << "road " << r.id;
            ++links;
        }
        if (r.predecessor.type == xodr::ElementType::road) {
            EXPECT_EQ(r.predecessor.contact, xodr::Contact::end) << "road " << r.id;
            ++links;
        }
    }
    EXPECT_GT(links, 6u);
    EXPECT_EQ(f.fitted.reversing_links, 0u);
}

TEST(XodrRailNetwork, RoadLinksAreContinuous) {
    const Fixture& f = fixture();
    std::size_t links = 0;
    for (const auto& r : f.build.map.roads) {
        if (!r.rail) {
            continue;
        }
        for (const auto& [link, contact] : {std::pair{&r.predecessor, xodr::Contact::start}, std::pair{&r.successor, xodr::Contact::end}}) {
            if (link->type != xodr::ElementType::road) {
                continue;
            }
            ++links;
            expect_g2(end_pose(r, contact), end_pose(road(f.build.map, link->id), link->contact), "road " + r.id);
        }
    }
    EXPECT_GT(links, 0u);
}

TEST(XodrRailNetwork, SwitchNamesItsMainAndSideTrackAtTheSwitchPoint) {
    const Fixture& f = fixture();
    std::size_t switches = 0;
    for (const auto& r : f.build.map.roads) {
        for (const auto& sw : r.switches) {
            ++switches;
            const xodr::Road& main = road(f.build.map, sw.main_track.road_id);
            const xodr::Road& side = road(f.build.map, sw.side_track.road_id);
            EXPECT_NE(main.junction, "-1");
            EXPECT_EQ(main.junction, side.junction);
            const auto pm = geometry::evaluate(alignment_of(main), sw.main_track.s);
            const auto ps = geometry::evaluate(alignment_of(side), sw.side_track.s);
            EXPECT_LT(std::hypot(pm.x - ps.x, pm.y - ps.y), 1e-6) << "both tracks leave the same point";
        }
    }
    EXPECT_EQ(switches, 3u);
}

TEST(XodrRailNetwork, FeaturesOfTheSampleRouteAreOnTheMap) {
    const Fixture& f = fixture();
    EXPECT_EQ(f.build.stations, 2u) << "a station with a platform and a halt";
    EXPECT_EQ(f.build.structures, 2u) << "one tunnel, one bridge";
    EXPECT_EQ(f.build.level_crossings, 1u);
    EXPECT_GE(f.build.signals, 4u);
    EXPECT_TRUE(f.build.features_not_written.empty());
}

TEST(XodrRailNetwork, WritingIsDeterministic) {
    const Fixture& f = fixture();
    for (const auto rev : {xodr::Revision::v1_6, xodr::Revision::v1_7, xodr::Revision::v1_8}) {
        EXPECT_EQ(xodr::write_xodr(f.build.map, rev), xodr::write_xodr(f.build.map, rev));
    }
    const std::string text = xodr::write_xodr(f.build.map, xodr::Revision::v1_7);
    EXPECT_NE(text.find("<header revMajor=\"1\" revMinor=\"7\""), std::string::npos);
    EXPECT_NE(text.find("+proj=tmerc"), std::string::npos);
    EXPECT_NE(text.find("<userData code=\"osm\" value=\"way:"), std::string::npos);
}
