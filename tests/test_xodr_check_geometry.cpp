// railodd::xodr_check plan-view evaluation and continuity checks on small
// handwritten documents whose records are computed here independently.
#include "test_support.hpp"
#include "xodr_check_support.hpp"

#include "railodd/util/errors.hpp"
#include "railodd/xodr_check/geometry_eval.hpp"

#include <numbers>

using namespace railodd::test;
namespace xc = railodd::xodr_check;

namespace {

std::string rail_road(const std::vector<Rec>& recs, const std::string& lane_type = "rail", const std::string& extra = "") {
    return document(road_xml({"1", total_length(recs), geometries_xml(recs), lane_type, "", "-1", extra}));
}

xc::GeometryRecord to_record(const Rec& r) {
    xc::GeometryRecord g;
    g.kind = r.kind == "line" ? xc::GeometryKind::line : r.kind == "arc" ? xc::GeometryKind::arc : xc::GeometryKind::spiral;
    g.s = r.s, g.x = r.start.x, g.y = r.start.y, g.hdg = r.start.hdg, g.length = r.length;
    g.curvature = r.start.k, g.curv_start = r.start.k, g.curv_end = r.k_end;
    return g;
}

} // namespace

TEST(XodrCheckGeometry, SpiralMatchesReferenceIntegrationOverAKilometre) {
    const RefPose p{12.5, -3.0, 0.7, -1.0 / 2000.0};
    const RefPose ref = ref_spiral(p, p.k, 1.0 / 300.0, 1000.0);
    const xc::Pose got = xc::evaluate(to_record({"spiral", 0, 1000.0, p, 1.0 / 300.0}), 1000.0);
    EXPECT_LT(std::hypot(got.x - ref.x, got.y - ref.y), 1e-7);
    EXPECT_NEAR(got.hdg, ref.hdg, 1e-12);
    EXPECT_NEAR(got.curvature, 1.0 / 300.0, 1e-15);
}

TEST(XodrCheckGeometry, ArcAndLineAreExact) {
    const RefPose p{1.0, 2.0, -0.4, 0.0};
    const RefPose arc = ref_arc({p.x, p.y, p.hdg, 0.01}, 0.01, 150.0);
    const xc::Pose got = xc::evaluate(to_record({"arc", 0, 150.0, {p.x, p.y, p.hdg, 0.01}, 0.01}), 150.0);
    EXPECT_NEAR(got.x, arc.x, 1e-10);
    EXPECT_NEAR(got.y, arc.y, 1e-10);
    EXPECT_NEAR(got.hdg, arc.hdg, 1e-14);
    // A vanishing curvature must not blow up the chord formula.
    const xc::Pose flat = xc::evaluate(to_record({"arc", 0, 100.0, {0, 0, 0, 1e-15}, 1e-15}), 100.0);
    EXPECT_NEAR(flat.x, 100.0, 1e-9);
}

TEST(XodrCheckGeometry, RailAlignmentWithClothoidsPasses) {
    const auto recs = rail_alignment({500.0, -200.0, 0.3, 0.0});
    const auto r = xc::check_text(rail_road(recs), "align.xodr");
    EXPECT_TRUE(r.passed()) << listing(r);
    EXPECT_EQ(r.findings.size(), 0u) << listing(r);
    EXPECT_EQ(r.summary.rail_roads, 1u);
    EXPECT_EQ(r.summary.geometries_by_kind.at("line"), 2u);
    EXPECT_EQ(r.summary.geometries_by_kind.at("spiral"), 2u);
    EXPECT_EQ(r.summary.geometries_by_kind.at("arc"), 1u);
    EXPECT_LT(r.summary.gap_m.value, 1e-7);
    EXPECT_LT(r.summary.heading_jump_rad.value, 1e-12);
    EXPECT_LT(r.summary.rail_curvature_jump.value, 1e-15);
    EXPECT_EQ(r.summary.version, "1.7");
}

TEST(XodrCheckGeometry, FiveMillimetreGapFailsNamingRoadAndS) {
    auto recs = rail_alignment({0, 0, 0, 0});
    recs[2].start.x += 0.005; // the arc starts 5 mm off the spiral's end
    const auto r = xc::check_text(rail_road(recs), "gap.xodr");
    EXPECT_FALSE(r.passed());
    const auto* f = find(r, "geometry_gap", "1");
    ASSERT_NE(f, nullptr) << listing(r);
    EXPECT_EQ(f->object, "road");
    EXPECT_DOUBLE_EQ(f->s, 160.0);
    EXPECT_NE(f->message.find("0.005"), std::string::npos) << f->message;
    EXPECT_NEAR(r.summary.gap_m.value, 0.005, 1e-6);
    EXPECT_NE(r.summary.gap_m.where.find("road 1 s=160.000"), std::string::npos) << r.summary.gap_m.where;
}

TEST(XodrCheckGeometry, HeadingJumpFails) {
    auto recs = rail_alignment({0, 0, 0, 0});
    recs[4].start.hdg += 1e-3;
    const auto r = xc::check_text(rail_road(recs), "hdg.xodr");
    const auto* f = find(r, "geometry_heading", "1");
    ASSERT_NE(f, nullptr) << listing(r);
    EXPECT_DOUBLE_EQ(f->s, 300.0);
    EXPECT_EQ(find(r, "geometry_gap"), nullptr) << listing(r);
}

TEST(XodrCheckGeometry, HeadingsCompareModuloTwoPi) {
    auto recs = rail_alignment({0, 0, 0, 0});
    recs[4].start.hdg += 2.0 * std::numbers::pi;
    const auto r = xc::check_text(rail_road(recs), "wrap.xodr");
    EXPECT_TRUE(r.passed()) << listing(r);
}

TEST(XodrCheckGeometry, CurvatureJumpFailsOnRailRoadOnly) {
    // A line straight into an arc: tangent-continuous, curvature jumps 0 -> 1/300.
    const RefPose end = ref_line({0, 0, 0, 0}, 100);
    const std::vector<Rec> recs{{"line", 0, 100, {0, 0, 0, 0}, 0}, {"arc", 100, 50, {end.x, end.y, end.hdg, 1.0 / 300}, 0}};
    const auto rail = xc::check_text(rail_road(recs, "rail"), "rail.xodr");
    ASSERT_NE(find(rail, "geometry_curvature", "1"), nullptr) << listing(rail);
    EXPECT_NEAR(rail.summary.rail_curvature_jump.value, 1.0 / 300, 1e-12);
    const auto tram = xc::check_text(rail_road(recs, "tram"), "tram.xodr");
    EXPECT_NE(find(tram, "geometry_curvature", "1"), nullptr) << listing(tram);
    const auto driving = xc::check_text(rail_road(recs, "driving"), "driving.xodr");
    EXPECT_TRUE(driving.passed()) << listing(driving);
    EXPECT_EQ(driving.summary.rail_roads, 0u);
}

TEST(XodrCheckGeometry, SChainAndRoadLengthMustAgree) {
    auto recs = rail_alignment({0, 0, 0, 0});
    recs[3].s += 0.5;
    const std::string body = road_xml({"7", total_length(recs) + 2.0, geometries_xml(recs)});
    const auto r = xc::check_text(document(body), "chain.xodr");
    EXPECT_NE(find(r, "geometry_s_chain", "7"), nullptr) << listing(r);
    EXPECT_NE(find(r, "road_length", "7"), nullptr) << listing(r);
}

TEST(XodrCheckGeometry, ParamPoly3ArcLengthAndNormalizedAreTheSameCurve) {
    // u(p) = p, v(p) = c p^2 + d p^3 over p in [0, L]; normalized: p' = p / L.
    const double L = 80.0, c = 1.5e-3, d = -1.0e-5;
    xc::GeometryRecord arc_len;
    arc_len.kind = xc::GeometryKind::param_poly3;
    arc_len.x = 10, arc_len.y = 20, arc_len.hdg = 1.1, arc_len.length = L;
    arc_len.bu = 1.0, arc_len.cv = c, arc_len.dv = d;
    xc::GeometryRecord norm = arc_len;
    norm.normalized = true;
    norm.bu = L, norm.cv = c * L * L, norm.dv = d * L * L * L;
    for (double s : {0.0, 13.0, 40.0, 79.5, 80.0}) {
        const xc::Pose a = xc::evaluate(arc_len, s);
        const xc::Pose b = xc::evaluate(norm, s);
        EXPECT_NEAR(a.x, b.x, 1e-9) << s;
        EXPECT_NEAR(a.y, b.y, 1e-9) << s;
        EXPECT_NEAR(a.hdg, b.hdg, 1e-12) << s;
        EXPECT_NEAR(a.curvature, b.curvature, 1e-12) << s;
    }
    // The end pose in closed form, then a line continuing from it passes.
    const double v = c * L * L + d * L * L * L, dv = 2 * c * L + 3 * d * L * L;
    const double ex = 10 + L * std::cos(1.1) - v * std::sin(1.1);
    const double ey = 20 + L * std::sin(1.1) + v * std::cos(1.1);
    for (const std::string& coeffs :
         {"aU=\"0\" bU=\"1\" cU=\"0\" dU=\"0\" aV=\"0\" bV=\"0\" cV=\"" + num(c) + "\" dV=\"" + num(d) + "\" pRange=\"arcLength\"",
          "aU=\"0\" bU=\"" + num(L) + "\" cU=\"0\" dU=\"0\" aV=\"0\" bV=\"0\" cV=\"" + num(c * L * L) + "\" dV=\"" +
              num(d * L * L * L) + "\" pRange=\"normalized\""}) {
        const std::string geoms = "<geometry s=\"0\" x=\"10\" y=\"20\" hdg=\"1.1\" length=\"80\"><paramPoly3 " + coeffs +
                                  "/></geometry>\n" +
                                  geometry_xml({"line", L, 20, {ex, ey, 1.1 + std::atan(dv), 0}, 0});
        const auto r = xc::check_text(document(road_xml({"3", L + 20, geoms, "driving"})), "pp3.xodr");
        EXPECT_EQ(r.errors(), 0u) << coeffs << "\n" << listing(r);
        EXPECT_EQ(r.summary.geometries_by_kind.at("paramPoly3"), 1u);
    }
}

TEST(XodrCheckGeometry, Poly3IsEvaluatedAlongArcLength) {
    // v(u) = c u^2: the end of an s-long record lies where the graph's arc length is s.
    const double c = 0.004, s = 60.0;
    xc::GeometryRecord g;
    g.kind = xc::GeometryKind::poly3;
    g.length = s, g.c = c;
    const xc::Pose p = xc::evaluate(g, s);
    // Arc length of y = c x^2 from 0 to u, closed form.
    const auto arc = [&](double u) {
        const double t = 2 * c * u;
        return (t * std::sqrt(1 + t * t) + std::asinh(t)) / (4 * c);
    };
    EXPECT_NEAR(arc(p.x), s, 1e-9);
    EXPECT_NEAR(p.y, c * p.x * p.x, 1e-12);
    EXPECT_NEAR(p.hdg, std::atan(2 * c * p.x), 1e-12);
    EXPECT_NEAR(p.curvature, 2 * c / std::pow(1 + 4 * c * c * p.x * p.x, 1.5), 1e-12);
}

TEST(XodrCheckGeometry, ElevationJumpFails) {
    const auto recs = rail_alignment({0, 0, 0, 0});
    const std::string elev = "<elevationProfile><elevation s=\"0\" a=\"100\" b=\"0.01\" c=\"0\" d=\"0\"/>"
                             "<elevation s=\"100\" a=\"101\" b=\"0.01\" c=\"0\" d=\"0\"/>"
                             "<elevation s=\"200\" a=\"102.01\" b=\"0\" c=\"0\" d=\"0\"/></elevationProfile>";
    const std::string body = road_xml({"1", total_length(recs), geometries_xml(recs)});
    const std::string xml = document(body);
    // Elevation belongs before <lanes>; insert after </planView>.
    std::string with = xml;
    with.insert(with.find("</planView>") + 11, elev);
    const auto r = xc::check_text(with, "elev.xodr");
    const auto* f = find(r, "elevation_gap", "1");
    ASSERT_NE(f, nullptr) << listing(r);
    EXPECT_DOUBLE_EQ(f->s, 200.0);
    EXPECT_NEAR(r.summary.elevation_gap_m.value, 0.01, 1e-9);
    EXPECT_EQ(r.errors(), 1u) << listing(r);
}

TEST(XodrCheckGeometry, BadNumbersAndUnknownRecordsAreFindings) {
    const std::string geoms = "<geometry s=\"0\" x=\"abc\" y=\"0\" hdg=\"0\" length=\"10\"><line/></geometry>"
                              "<geometry s=\"10\" x=\"10\" y=\"0\" hdg=\"0\" length=\"10\"><clothoid/></geometry>";
    const auto r = xc::check_text(document(road_xml({"1", 20, geoms})), "bad.xodr");
    EXPECT_NE(find(r, "attribute", "1"), nullptr) << listing(r);
    EXPECT_NE(find(r, "geometry_kind", "1"), nullptr) << listing(r);
    EXPECT_FALSE(r.passed());
}

TEST(XodrCheckGeometry, UnreadableInputThrowsNamingTheFile) {
    try {
        xc::check_text("<OpenDRIVE><header", "broken.xodr");
        FAIL() << "no exception";
    } catch (const railodd::InputError& e) {
        EXPECT_NE(std::string{e.what()}.find("broken.xodr"), std::string::npos) << e.what();
    }
    EXPECT_THROW(xc::check_text("<osm/>", "osm.xodr"), railodd::InputError);
    const auto dir = scratch_dir();
    EXPECT_THROW(xc::check_file(dir / "missing.xodr"), railodd::InputError);
}
