// Where a switch (or a diamond crossing) lies within a metre of a knot of
// its through track's design, the track is cut at the knot (track_fit.cpp,
// at_knot_near): cut where the node projects, one of the two edges began or
// ended with a piece of an element under a metre, a sliver no design has
// (VDE 8.2: 45 track elements under a metre, Cologne about 300; at
// crossings and joins, Munich 6 of its 9).
#include "railodd/geometry/track_fit.hpp"
#include "railodd/ingest/osm_reader.hpp"
#include "test_support.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

using namespace railodd;
using namespace railodd::geometry;

namespace {

std::string node(int id, const Point& p) {
    const double lat = 48.0 + p.y / 111320.0, lon = 10.0 + p.x / (111320.0 * std::cos(48.0 * 3.14159265358979 / 180.0));
    return "<node id=\"" + std::to_string(id) + "\" version=\"1\" lat=\"" + std::to_string(lat) + "\" lon=\"" +
           std::to_string(lon) + "\"/>\n";
}

std::string way(int id, const std::vector<int>& refs) {
    std::string w = "<way id=\"" + std::to_string(id) + "\" version=\"1\">";
    for (const int r : refs) {
        w += "<nd ref=\"" + std::to_string(r) + "\"/>";
    }
    return w + "<tag k=\"railway\" v=\"rail\"/></way>\n";
}

// A through track, straight for 300 m and then into a curve (a 60 m
// transition to R 600 m), mapped every 12 m with a few centimetres of
// scatter, and a node `after` metres into the transition, from which a
// branch runs off straight to the right at 1:9 (a switch), or through which
// a straight track crosses at 45 degrees (a diamond crossing). The fit puts
// the transition's start 1.5-3 m in: switches 1.5, 2 and 2.5 m in left
// pieces of 0.87, 0.43 and 0.10 m.
std::string track_at_curve(double after, bool crossing) {
    Alignment through;
    through.start = {0.0, 0.0, 0.0, 0.0};
    through.primitives = {make_line(300.0), make_spiral(60.0, 0.0, 1.0 / 600.0), make_arc(240.0, 1.0 / 600.0)};
    std::string text;
    std::vector<int> main, other;
    int id = 1;
    const double at = 300.0 + after;
    for (double s = 0.0; s <= 600.0; s += 12.0) {
        const Pose q = evaluate(through, s);
        const double off = 0.03 * ((id * 7) % 5 - 2) / 2.0;
        text += node(id, {q.x - off * std::sin(q.hdg), q.y + off * std::cos(q.hdg)});
        main.push_back(id++);
        if (s < at && s + 12.0 > at) {
            const Pose w = evaluate(through, at);
            const double h = w.hdg - (crossing ? std::atan(1.0) : std::atan(1.0 / 9.0));
            const int shared = id++;
            text += node(shared, {w.x, w.y});
            main.push_back(shared);
            for (double d = crossing ? -120.0 : 0.0; d <= 150.0; d += 12.0) {
                if (d == 0.0) {
                    other.push_back(shared);
                    continue;
                }
                text += node(id, {w.x + d * std::cos(h), w.y + d * std::sin(h)});
                other.push_back(id++);
            }
        }
    }
    return "<?xml version=\"1.0\"?>\n<osm version=\"0.6\">\n" + text + way(1000, main) + way(1001, other) + "</osm>\n";
}

FittedNetwork fit_text(const std::string& osm) {
    const auto dir = test::scratch_dir();
    const ingest::IngestResult in = ingest::read_osm(test::write_file(dir / "track.osm", osm), {});
    return fit_track_graph(build_track_graph(in.tracks, in.features), FitOptions{});
}

void expect_no_piece_under_a_metre(const FittedNetwork& net) {
    for (const FittedEdge& e : net.edges) {
        for (const Primitive& p : e.alignment.primitives) {
            EXPECT_GE(p.length, 1.0) << "edge " << e.edge;
        }
    }
}

} // namespace

TEST(SwitchKnots, ATrackIsCutAtItsKnotBesideASwitch) {
    for (const double after : {1.0, 1.5, 2.0, 2.5}) {
        SCOPED_TRACE("switch " + std::to_string(after) + " m into the transition");
        const FittedNetwork net = fit_text(track_at_curve(after, false));
        ASSERT_EQ(net.edges.size(), 3u);
        expect_no_piece_under_a_metre(net);
        ASSERT_EQ(net.branch_links.size(), 1u);
        EXPECT_LT(net.branch_links.front().gap_m, 1e-6);
        EXPECT_LT(net.branch_links.front().curvature, 1e-9);
    }
}

TEST(SwitchKnots, ATrackIsCutAtItsKnotBesideADiamondCrossing) {
    for (const double after : {1.0, 1.5, 2.0, 2.5}) {
        SCOPED_TRACE("crossing " + std::to_string(after) + " m into the transition");
        const FittedNetwork net = fit_text(track_at_curve(after, true));
        ASSERT_EQ(net.edges.size(), 4u);
        ASSERT_EQ(net.chains.size(), 2u);
        expect_no_piece_under_a_metre(net);
        // Each track is still one continuous design across the crossing.
        for (const Chain& ch : net.chains) {
            ASSERT_EQ(ch.items.size(), 2u);
            const FittedEdge& a = net.edges[ch.items[0].edge];
            const FittedEdge& b = net.edges[ch.items[1].edge];
            const Pose end = evaluate(a.alignment, length(a.alignment));
            EXPECT_LT(std::hypot(end.x - b.alignment.start.x, end.y - b.alignment.start.y), 1e-6);
        }
    }
}
