// Where a switch lies within a metre of a knot of its through track's
// design, the track is cut at the knot (track_fit.cpp, at_knot_near): cut
// where the switch node projects, one of the two edges began or ended with
// a piece of an element under a metre, a sliver no design has (VDE 8.2: 45
// track elements under a metre, Cologne about 300).
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
// scatter, and a switch node `after` metres into the transition, from
// which a branch runs off straight to the right at 1:9. The fit puts the
// transition's start 1.5-3 m in: switches 1.5, 2 and 2.5 m in left pieces
// of 0.87, 0.43 and 0.10 m.
std::string switch_at_curve(double after) {
    Alignment through;
    through.start = {0.0, 0.0, 0.0, 0.0};
    through.primitives = {make_line(300.0), make_spiral(60.0, 0.0, 1.0 / 600.0), make_arc(240.0, 1.0 / 600.0)};
    std::string text;
    std::vector<int> main, branch;
    int id = 1;
    const double at = 300.0 + after;
    for (double s = 0.0; s <= 600.0; s += 12.0) {
        const Pose q = evaluate(through, s);
        const double off = 0.03 * ((id * 7) % 5 - 2) / 2.0;
        text += node(id, {q.x - off * std::sin(q.hdg), q.y + off * std::cos(q.hdg)});
        main.push_back(id++);
        if (s < at && s + 12.0 > at) {
            const Pose w = evaluate(through, at);
            text += node(id, {w.x, w.y});
            main.push_back(id);
            branch.push_back(id++);
            for (double d = 12.0; d <= 150.0; d += 12.0) {
                const double h = w.hdg - std::atan(1.0 / 9.0);
                text += node(id, {w.x + d * std::cos(h), w.y + d * std::sin(h)});
                branch.push_back(id++);
            }
        }
    }
    return "<?xml version=\"1.0\"?>\n<osm version=\"0.6\">\n" + text + way(1000, main) + way(1001, branch) + "</osm>\n";
}

} // namespace

TEST(SwitchKnots, ATrackIsCutAtItsKnotBesideASwitch) {
    const auto dir = test::scratch_dir();
    for (const double after : {1.0, 1.5, 2.0, 2.5}) {
        SCOPED_TRACE("switch " + std::to_string(after) + " m into the transition");
        const ingest::IngestResult in = ingest::read_osm(test::write_file(dir / "switch.osm", switch_at_curve(after)), {});
        const TrackGraph g = build_track_graph(in.tracks, in.features);
        const FittedNetwork net = fit_track_graph(g, FitOptions{});
        ASSERT_EQ(net.edges.size(), 3u);
        for (const FittedEdge& e : net.edges) {
            for (const Primitive& p : e.alignment.primitives) {
                EXPECT_GE(p.length, 1.0) << "edge " << e.edge;
            }
        }
        ASSERT_EQ(net.branch_links.size(), 1u);
        EXPECT_LT(net.branch_links.front().gap_m, 1e-6);
        EXPECT_LT(net.branch_links.front().curvature, 1e-9);
    }
}
