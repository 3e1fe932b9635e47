// Vertical curves from the vertical profile: on a synthetic profile over a
// straight 2 km track with a crest of radius 10 km (grade +15 to -15 permille
// over 300 m) and a sag of radius 5 km, the tagger finds both stretches,
// recovers their radii within 2 % and their kinds, and tags nothing on the
// constant grades.
#include "odd_pipeline_support.hpp"

#include <cmath>

using namespace railodd;
using namespace railodd::test;

namespace {

// z(s) = a + b ds + c ds^2 per stretch; c = -1 / (2 R) on a crest.
std::vector<geometry::ElevationPoly> crest_and_sag() {
    const double g = 0.015, crest_r = 10000.0, sag_r = 5000.0;
    std::vector<geometry::ElevationPoly> polys{{0.0, 0.0, g, 0.0, 0.0}};
    polys.push_back({600.0, 600.0 * g, g, -1.0 / (2.0 * crest_r), 0.0});
    polys.push_back({900.0, 600.0 * g + 300.0 * g - 300.0 * 300.0 / (2.0 * crest_r), -g, 0.0, 0.0});
    const double z1300 = polys.back().a - 400.0 * g;
    polys.push_back({1300.0, z1300, -g, 1.0 / (2.0 * sag_r), 0.0});
    polys.push_back({1450.0, z1300 - 150.0 * g + 150.0 * 150.0 / (2.0 * sag_r), g, 0.0, 0.0});
    return polys;
}

} // namespace

TEST(OddVerticalCurve, RadiusAndKindRecoveredOnTheirStretches) {
    Pipeline p(write_file(scratch_dir() / "track.opl", straight_track_opl()));
    ASSERT_EQ(p.profiles.size(), 1u);
    p.profiles[0].polys = crest_and_sag();
    p.profiles[0].source = geometry::ElevationSource::dem;
    const odd::OddProfile profile = p.tag();
    std::vector<const odd::TaggedElement*> curves;
    for (const auto& e : profile.elements) {
        if (e.element == "Scenery/Track geometry/Vertical/Vertical curve") {
            curves.push_back(&e);
        }
    }
    ASSERT_EQ(curves.size(), 2u);
    const auto& crest = *curves[0];
    EXPECT_EQ(std::get<std::string>(*crest.find("kind")), "crest");
    EXPECT_NEAR(std::get<double>(*crest.find("radius")), 10000.0, 200.0);
    EXPECT_EQ(std::get<std::string>(*crest.find("radius_class")), "wide");
    EXPECT_NEAR(crest.chainage_start, 600.0, 10.0);
    EXPECT_NEAR(crest.chainage_end, 900.0, 10.0);
    EXPECT_EQ(crest.source, "dem");
    const auto& sag = *curves[1];
    EXPECT_EQ(std::get<std::string>(*sag.find("kind")), "sag");
    EXPECT_NEAR(std::get<double>(*sag.find("radius")), 5000.0, 100.0);
    EXPECT_EQ(std::get<std::string>(*sag.find("radius_class")), "normal");
    EXPECT_NEAR(sag.chainage_start, 1300.0, 10.0);
    EXPECT_NEAR(sag.chainage_end, 1450.0, 10.0);
}

TEST(OddVerticalCurve, NoneWithoutElevationData) {
    Pipeline p(write_file(scratch_dir() / "track.opl", straight_track_opl()));
    p.profiles[0].polys = crest_and_sag();
    p.profiles[0].source = geometry::ElevationSource::flat; // an assumption, not a measured profile
    for (const auto& e : p.tag().elements) {
        EXPECT_NE(e.element, "Scenery/Track geometry/Vertical/Vertical curve");
    }
}
