// Land use along the track: a straight 2 km track through a town, a gap,
// and a forest with a village inside it. The tagger samples every 25 m, the
// smallest area wins, runs of one kind merge, unmapped land stays untagged,
// and the summary counts km per kind.
#include "odd_pipeline_support.hpp"

#include <cmath>
#include <map>

using namespace railodd;
using namespace railodd::test;

namespace {

ingest::LandUseArea rectangle(std::int64_t id, const std::string& kind, double x0, double y0, double x1, double y1) {
    return {"way", id, kind, "landuse=test", {{{x0, y0}, {x1, y0}, {x1, y1}, {x0, y1}}}, (x1 - x0) * (y1 - y0)};
}

std::vector<const odd::TaggedElement*> land_use(const odd::OddProfile& p) {
    std::vector<const odd::TaggedElement*> out;
    for (const auto& e : p.elements) {
        if (e.element == "Scenery/Surroundings/Land use") {
            out.push_back(&e);
        }
    }
    return out;
}

std::string kind_of(const odd::TaggedElement& e) { return std::get<std::string>(*e.find("kind")); }

} // namespace

TEST(OddLandUse, SmallestAreaWinsAndUnmappedLandStaysUntagged) {
    Pipeline p(write_file(scratch_dir() / "track.opl", straight_track_opl()));
    // The local frame is centred on the track: it runs along y = 0 from x = -1000 to 1000.
    p.ingest.land_use = {rectangle(10, "urban", -1100, -200, -400, 200),
                         rectangle(20, "forest", -100, -500, 1100, 500),
                         rectangle(30, "suburban", 200, -100, 400, 100)};
    const odd::OddProfile profile = p.tag();
    const auto lu = land_use(profile);
    ASSERT_EQ(lu.size(), 4u);
    // Along the alignment, whichever way it runs: town, forest, village, forest.
    const bool east = kind_of(*lu.front()) == "urban";
    const std::vector<std::string> expected = east ? std::vector<std::string>{"urban", "forest", "suburban", "forest"}
                                                   : std::vector<std::string>{"forest", "suburban", "forest", "urban"};
    std::map<std::string, double> metres;
    for (std::size_t i = 0; i < lu.size(); ++i) {
        EXPECT_EQ(kind_of(*lu[i]), expected[i]) << i;
        metres[kind_of(*lu[i])] += lu[i]->chainage_end - lu[i]->chainage_start;
        EXPECT_EQ(lu[i]->osm_ids.front(), "way:1") << "the track's way first";
        EXPECT_EQ(lu[i]->source, "osm");
    }
    EXPECT_NEAR(metres["urban"], 600.0, 30.0);
    EXPECT_NEAR(metres["suburban"], 200.0, 30.0);
    EXPECT_NEAR(metres["forest"], 900.0, 50.0);
    // The 300 m between town and forest are not covered: nothing is claimed there.
    const auto& s = profile.summary["landuse_km_by_kind"];
    EXPECT_NEAR(s["urban"].get<double>(), 0.6, 0.03);
    EXPECT_EQ(s["rural"].get<double>(), 0.0) << "unmapped land is not assumed rural";
    EXPECT_EQ(s.size(), 7u) << "every kind of the taxonomy listed";
    const auto& village = *lu[east ? 2 : 1];
    EXPECT_NE(std::find(village.osm_ids.begin(), village.osm_ids.end(), "way:30"), village.osm_ids.end());
}

TEST(OddLandUse, HolesOfMultipolygonsAreOutside) {
    Pipeline p(write_file(scratch_dir() / "track.opl", straight_track_opl()));
    ingest::LandUseArea wood = rectangle(40, "forest", -1100, -500, 1100, 500);
    wood.osm_type = "relation";
    wood.rings.push_back({{-250, -100}, {250, -100}, {250, 100}, {-250, 100}}); // a clearing
    p.ingest.land_use = {wood};
    const auto profile = p.tag();
    const auto lu = land_use(profile);
    ASSERT_EQ(lu.size(), 2u);
    EXPECT_NEAR(lu[1]->chainage_start - lu[0]->chainage_end, 500.0, 30.0);
    EXPECT_EQ(lu[0]->osm_ids.back(), "relation:40");
}
