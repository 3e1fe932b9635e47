// The corner construction: lines joined by clothoid corners are G2 at every
// joint, pass within the deviation bound of every mapped vertex, and begin /
// end exactly with given poses; a switch whose branch needs it keeps the
// branch link G2.
#include "design_splice.hpp"
#include "railodd/geometry/corner_fit.hpp"
#include "railodd/geometry/track_fit.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

using namespace railodd;
using namespace railodd::geometry;

namespace {

double angle_diff(double a, double b) { return std::abs(std::remainder(a - b, 2 * std::numbers::pi)); }

// Every joint: the end of one primitive (evaluated on its own) against the
// alignment's pose at the joint, which belongs to the next primitive.
void expect_g2(const Alignment& a) {
    ASSERT_NO_THROW(validate(a));
    const std::vector<Pose> starts = primitive_starts(a);
    const std::vector<double> s = primitive_s(a);
    for (std::size_t i = 0; i + 1 < a.primitives.size(); ++i) {
        SCOPED_TRACE("joint after primitive " + std::to_string(i));
        const Primitive& p = a.primitives[i];
        const Pose end = evaluate(starts[i], p, p.length);
        const Pose next = evaluate(a, s[i + 1]);
        EXPECT_LT(std::hypot(end.x - next.x, end.y - next.y), 1e-6);
        EXPECT_LT(angle_diff(end.hdg, next.hdg), 1e-9);
        EXPECT_LT(std::abs(p.curv_end - a.primitives[i + 1].curv_start), 1e-9);
        EXPECT_LT(std::abs(end.curvature - next.curvature), 1e-9);
    }
}

void expect_pose(const Pose& got, const Pose& want) {
    EXPECT_LT(std::hypot(got.x - want.x, got.y - want.y), 1e-9);
    EXPECT_LT(angle_diff(got.hdg, want.hdg), 1e-9);
    EXPECT_LT(std::abs(got.curvature - want.curvature), 1e-9);
}

double max_distance(const Alignment& a, const std::vector<Point>& pts) {
    double worst = 0.0;
    for (double d : distances(a, pts)) {
        worst = std::max(worst, d);
    }
    return worst;
}

// A tram-like track: a long straight, a right-angle corner drawn as one
// vertex, a tight corner drawn as a dense arc (R 15 m, nodes 3 m apart),
// a kink and a reverse turn.
std::vector<Point> tram_polyline() {
    std::vector<Point> p{{0, 0}, {120, 0}, {120, 60}};
    const double r = 15.0;
    for (double t = 0.2; t < std::numbers::pi / 2; t += 0.2) {
        p.push_back({120 - r + r * std::cos(t), 60 + r * std::sin(t)});
    }
    for (const Point& q : {Point{100, 75}, Point{80, 76}, Point{60, 75}, Point{40, 90}, Point{40, 140}}) {
        p.push_back(q);
    }
    return p;
}

} // namespace

TEST(GeometryCornerFit, SharpCornerIsG2AndPassesCloseToTheVertex) {
    const std::vector<Point> pts{{0, 0}, {100, 0}, {100, 100}};
    const Alignment a = corner_polyline(pts, std::nullopt, std::nullopt, {});
    expect_g2(a);
    EXPECT_LE(max_distance(a, pts), 0.25 + 1e-9);
    expect_pose(evaluate(a, 0.0), {0, 0, 0, 0});
    expect_pose(evaluate(a, length(a)), {100, 100, std::numbers::pi / 2, 0});
    double peak = 0.0;
    for (const auto& p : a.primitives) {
        peak = std::max(peak, std::abs(p.curv_start));
    }
    EXPECT_GT(peak, 0.0);
    EXPECT_LT(peak, 1.0 / 0.25); // a real corner, not a turn on the spot
}

// A kink of a milliradian between two straights (Krems has one): at the
// widest radius, 1000 m, its corner was three pieces of 0.5 m; widened
// until each is a metre, it still passes the vertex within a millimetre.
TEST(GeometryCornerFit, ASlightKinkTakesPiecesOfAMetre) {
    const std::vector<Point> pts{{0, 0}, {400, 0}, {400 + 400 * std::cos(0.001), 400 * std::sin(0.001)}};
    const Alignment a = corner_polyline(pts, std::nullopt, std::nullopt, {});
    expect_g2(a);
    ASSERT_EQ(a.primitives.size(), 5u);
    for (std::size_t i = 1; i < 4; ++i) {
        EXPECT_GE(a.primitives[i].length, 1.0 - 1e-9) << i;
    }
    EXPECT_LE(max_distance(a, pts), 1e-3);
}

TEST(GeometryCornerFit, TramTrackIsG2WithinTheBound) {
    const std::vector<Point> pts = tram_polyline();
    for (const double bound : {0.1, 0.25, 0.5}) {
        SCOPED_TRACE(bound);
        const Alignment a = corner_polyline(pts, std::nullopt, std::nullopt, {1000.0, bound});
        expect_g2(a);
        EXPECT_LE(max_distance(a, pts), bound + 1e-9);
    }
}

TEST(GeometryCornerFit, TiedEndsAreMetExactly) {
    const std::vector<Point> pts = tram_polyline();
    // Poses off the polyline, turned against it and curved, as a through
    // track's pose at a switch is.
    const Pose start{0.3, -0.2, 0.04, 1.0 / 300};
    const Pose end{40.2, 140.1, std::numbers::pi / 2 - 0.03, -1.0 / 250};
    const Alignment a = corner_polyline(pts, start, end, {});
    expect_g2(a);
    expect_pose(evaluate(a, 0.0), start);
    expect_pose(evaluate(a, length(a)), end);
    const std::vector<Point> inner(pts.begin() + 1, pts.end() - 1);
    EXPECT_LE(max_distance(a, inner), 0.25 + 1e-9);
}

TEST(GeometryCornerFit, TiedEndsOfATwoNodeTrack) {
    const std::vector<Point> pts{{0, 0}, {30, 4}};
    const Pose start{0, 0, 0.0, 1.0 / 190};
    const Pose end{30, 4, 0.1, 0.0};
    const Alignment a = corner_polyline(pts, start, end, {});
    expect_g2(a);
    expect_pose(evaluate(a, 0.0), start);
    expect_pose(evaluate(a, length(a)), end);
}

TEST(GeometryCornerFit, SpikesBecomeHairpinsThroughTheirTips) {
    // The way runs out to (50, 0.5), doubles back to (40, 0) and goes on:
    // two spikes in a row, each rounded by a hairpin through its tip.
    for (const std::vector<Point>& pts : {std::vector<Point>{{0, 0}, {50, 0.5}, {40, 0}, {100, 0}},
                                          std::vector<Point>{{0, 0}, {30, 0}, {0, 0.1}, {-5, 20}}}) {
        const Alignment a = corner_polyline(pts, std::nullopt, std::nullopt, {});
        expect_g2(a);
        EXPECT_LE(max_distance(a, pts), 0.25 + 1e-9);
    }
}

namespace {

ingest::NodeRef node(std::int64_t id, double x, double y) {
    ingest::NodeRef n;
    n.id = id;
    n.xy = {x, y};
    return n;
}

ingest::Way way(std::int64_t id, std::vector<ingest::NodeRef> nodes) {
    ingest::Way w;
    w.id = id;
    w.tags = {{"railway", "tram"}};
    w.node_count = nodes.size();
    w.parts.push_back(std::move(nodes));
    return w;
}

} // namespace

TEST(GeometryCornerFit, BranchTurningOnTheSpotKeepsARailwayFitAndItsSwitchLinkG2) {
    // A curved through track (R 500 m) with a switch at node 10; the branch
    // leaves it and turns by 2.3 rad on the spot 40 m further on, which no
    // railway-grade curve (R >= 10 m) passes within 2 m of. Corners through
    // it (every node within 0.5 m) turned at R 1-5 m, which no vehicle
    // runs: the railway fit is kept and the chain reported beyond its limit.
    std::vector<ingest::NodeRef> through;
    for (int i = 0; i <= 20; ++i) {
        const double t = (i - 10) * 20.0 / 500.0;
        through.push_back(node(i, 500 * std::sin(t), 500 * (1 - std::cos(t))));
    }
    const ingest::NodeRef sw = through[10];
    const ingest::Way branch = way(2, {sw, node(100, 20, -3), node(101, 40, -8), node(102, 25, -19),
                                      node(103, 10, -30), node(104, -5, -41)});
    const TrackGraph g = build_track_graph({way(1, through), branch}, {});
    FitOptions o;
    o.noise_sigma_m = 0.1;
    const FittedNetwork net = fit_track_graph(g, o);
    EXPECT_TRUE(net.corner_chains.empty());
    ASSERT_EQ(net.beyond_limit_chains.size(), 1u);
    ASSERT_EQ(net.branch_links.size(), 1u);
    const LinkReport& l = net.branch_links.front();
    EXPECT_EQ(l.chain, net.beyond_limit_chains.front());
    EXPECT_LT(l.gap_m, 1e-9);
    EXPECT_LT(l.heading_rad, 1e-9);
    EXPECT_LT(l.curvature, 1e-9);
    for (const auto& e : net.edges) {
        expect_g2(e.alignment);
        EXPECT_TRUE(drivable(e.alignment));
    }
}

TEST(GeometryCornerFit, BranchMeetingItsTrackAtAnAngleMeetsItExactly) {
    // A siding runs parallel 12 m from a straight main line and joins it at
    // node 12 at a mapped angle of 0.54 rad over the last 20 m; tied to the
    // main line's heading there, no single railway fit follows the siding
    // within 2 m. Corners spliced on did, turning at R 6 m twice; a track
    // turns no tighter than R 10 m: the tied railway fit is kept (6 m off
    // the kink's nodes) and the chain reported beyond its limit.
    std::vector<ingest::NodeRef> main_line;
    for (int i = 0; i <= 24; ++i) {
        main_line.push_back(node(i, 50.0 * i, 0.0));
    }
    const ingest::Way siding = way(2, {node(100, 0, 12), node(101, 150, 12), node(102, 300, 12), node(103, 450, 12),
                                       node(104, 580, 12), node(105, 590, 6), main_line[12]});
    const TrackGraph g = build_track_graph({way(1, main_line), siding}, {});
    FitOptions o;
    o.noise_sigma_m = 0.1;
    const FittedNetwork net = fit_track_graph(g, o);
    EXPECT_TRUE(net.corner_chains.empty());
    EXPECT_EQ(net.beyond_limit_chains.size(), 1u);
    ASSERT_EQ(net.branch_links.size(), 1u);
    const LinkReport& l = net.branch_links.front();
    EXPECT_LT(l.gap_m, 1e-9);
    EXPECT_LT(l.heading_rad, 1e-9);
    EXPECT_LT(l.curvature, 1e-9);
    for (const auto& e : net.edges) {
        expect_g2(e.alignment);
        EXPECT_TRUE(drivable(e.alignment));
    }
}

// A curve mapped densely (R 200 m, nodes 2 m apart, ±3 cm of scatter),
// tied to its switch at the start: a corner at every node was a few
// decimetres long (Cologne's spliced ends: 24 % of their elements under a
// metre). The corners stand on the vertices Douglas-Peucker keeps at half
// the bound, every node still within it.
TEST(GeometryCornerFit, ADenselyMappedCurveTakesFewCorners) {
    std::vector<Point> pts;
    const double r = 200.0;
    for (int i = 0; i <= 40; ++i) {
        const double t = 2.0 * i / r, e = 0.03 * ((i * 7) % 5 - 2) / 2.0;
        pts.push_back({(r - e) * std::sin(t), r - (r - e) * std::cos(t)});
    }
    const Alignment a = corner_polyline(pts, Pose{0.0, 0.0, 0.0, 0.0}, std::nullopt, {});
    expect_g2(a);
    EXPECT_LE(max_distance(a, pts), 0.25 + 1e-9);
    EXPECT_LE(a.primitives.size(), 30u); // 121 with a corner at every node, 115 under a metre
    for (const Primitive& p : a.primitives) {
        // A straight the corners' rooms leave between them can be short
        // (here one of 2 mm); the corners are not.
        EXPECT_TRUE(p.kind == PrimitiveKind::line || p.length >= 1.0) << p.length;
    }
}
