// check_spec(): the shipped example spec against a hand-made profile, entries
// with allowed: false (also on an ancestor), unlisted elements outside, and
// unknown attributes that are not violations.
#include "railodd/odd/odd_spec.hpp"
#include "railodd/odd/spec_check.hpp"

#include "odd_profile_support.hpp"
#include "test_support.hpp"

#include <gtest/gtest.h>

using namespace railodd::odd;
using namespace railodd::test;

namespace {

const fs::path data_dir = fs::path{RAILODD_SOURCE_DIR} / "data/odd";

const Taxonomy& taxonomy() {
    static const Taxonomy t = load_taxonomy(data_dir / "railway_odd.yaml");
    return t;
}

SpecVerdict check_inline(const std::string& yaml) {
    const auto file = write_file(scratch_dir() / "spec.yaml", yaml);
    return check_spec(sample_profile(), load_odd_spec(file, taxonomy()), taxonomy());
}

} // namespace

TEST(OddSpecCheck, ExampleSpecRejectsTightCurveOpenCrossingAndSteepGradient) {
    const auto spec = load_odd_spec(data_dir / "example_odd_spec.yaml", taxonomy());
    const auto v = check_spec(sample_profile(), spec, taxonomy());
    EXPECT_FALSE(v.passed);
    ASSERT_EQ(v.violations.size(), 3u) << verdict_text(v);
    EXPECT_EQ(v.violations[0].element, "Scenery/Track geometry/Vertical/Gradient");
    EXPECT_EQ(v.violations[0].attribute, "gradient");
    EXPECT_EQ(v.violations[0].value, "30");
    EXPECT_EQ(v.violations[0].constraint, "gradient <= 25 permille");
    EXPECT_EQ(v.violations[0].road_id, "12");
    EXPECT_EQ(v.violations[0].chainage_end, 400.0);
    EXPECT_EQ(v.violations[1].element, "Scenery/Track geometry/Horizontal/Curve");
    EXPECT_EQ(v.violations[1].value, "250");
    EXPECT_EQ(v.violations[1].constraint, "radius >= 300 m");
    EXPECT_EQ(v.violations[1].road_id, "12");
    EXPECT_EQ(v.violations[1].chainage_start, 100.0);
    EXPECT_EQ(v.violations[1].chainage_end, 350.0);
    EXPECT_EQ(v.violations[1].osm_ids, std::vector<std::string>{"way:1"});
    EXPECT_EQ(v.violations[2].element, "Scenery/Crossings/Level crossing");
    EXPECT_EQ(v.violations[2].attribute, "barrier");
    EXPECT_EQ(v.violations[2].value, "no");
    EXPECT_EQ(v.violations[2].chainage_start, 450.0);
    EXPECT_EQ(v.violations[2].osm_ids, std::vector<std::string>{"node:5"});
    EXPECT_GT(v.violations[2].spec_line, 0);
    EXPECT_EQ(v.elements_outside, 3u);
    EXPECT_EQ(v.elements_checked, 8u);

    // The open crossing lacks `lights`: unknown, not a second violation.
    const auto& crossing = v.entries[3];
    EXPECT_EQ(crossing.path, "Scenery/Crossings/Level crossing");
    EXPECT_EQ(crossing.matched, 2u);
    EXPECT_EQ(crossing.outside, 1u);
    EXPECT_EQ(crossing.unknown, 1u);
    EXPECT_EQ(crossing.unknown_attributes, std::vector<std::string>{"lights"});
    EXPECT_EQ(v.entries[0].matched, 2u); // curves
    EXPECT_EQ(v.entries[0].outside, 1u);

    // Gradient 0-400 and curve 100-350 overlap: one stretch; the crossing another.
    ASSERT_EQ(v.stretches.size(), 2u);
    EXPECT_EQ(v.stretches[0].chainage_start, 0.0);
    EXPECT_EQ(v.stretches[0].chainage_end, 400.0);
    EXPECT_EQ(v.stretches[0].violations, 2u);
    EXPECT_EQ(v.stretches[0].road_ids, std::vector<std::string>{"12"});
    EXPECT_EQ(v.stretches[1].chainage_start, 450.0);

    const auto text = verdict_text(v);
    EXPECT_NE(text.find("OUTSIDE ODD"), std::string::npos) << text;
    EXPECT_NE(text.find("road 12 s 100.0-350.0  Scenery/Track geometry/Horizontal/Curve: radius 250 m, spec radius >= "
                        "300 m"),
              std::string::npos)
        << text;
    const auto j = verdict_json(v);
    EXPECT_EQ(j["violations"].size(), 3u);
    EXPECT_FALSE(j["passed"].get<bool>());
}

TEST(OddSpecCheck, AllowedFalseOnTheElementOrAnAncestor) {
    const auto direct = check_inline("odd_spec: t\nelements:\n  - path: Scenery/Crossings/Level crossing\n"
                                     "    allowed: false\n");
    ASSERT_EQ(direct.violations.size(), 2u);
    EXPECT_EQ(direct.violations[0].constraint, "not allowed");
    EXPECT_EQ(direct.violations[1].osm_ids, (std::vector<std::string>{"node:6", "way:7"}));
    EXPECT_EQ(direct.violations[1].road_id, "13");
    EXPECT_EQ(direct.violations[1].spec_line, 3);

    const auto ancestor = check_inline("odd_spec: t\nelements:\n  - path: Scenery/Crossings\n    allowed: false\n");
    ASSERT_EQ(ancestor.violations.size(), 2u);
    EXPECT_EQ(ancestor.violations[0].spec_element, "Scenery/Crossings");
    EXPECT_EQ(ancestor.violations[0].element, "Scenery/Crossings/Level crossing");
    // Points on one track more than 1 mm apart stay separate stretches.
    EXPECT_EQ(ancestor.stretches.size(), 2u);
}

TEST(OddSpecCheck, UnlistedElementsOutside) {
    const auto v = check_inline("odd_spec: t\nunlisted_elements: outside\nelements:\n"
                                "  - path: Scenery/Track geometry/Horizontal/Curve\n"
                                "    attributes:\n      radius: {min: 200}\n"
                                "  - path: Scenery/Track geometry/Vertical\n");
    // Curves fit, gradients are covered by their ancestor entry; the speed
    // limit, both crossings and the station are not listed.
    ASSERT_EQ(v.violations.size(), 4u) << verdict_text(v);
    EXPECT_EQ(v.elements_unlisted, 4u);
    EXPECT_EQ(v.violations[0].element, "Operational Conditions/Speed/Speed limit");
    EXPECT_EQ(v.violations[0].constraint, "not listed (unlisted_elements: outside)");
    EXPECT_EQ(v.violations[3].element, "Scenery/Stations and stops/Station");
    // The speed limit spans 0-1000 and swallows the crossing at 450.
    ASSERT_EQ(v.stretches.size(), 3u);
    EXPECT_EQ(v.stretches[0].chainage_end, 1000.0);
    EXPECT_EQ(v.stretches[0].violations, 2u);
}

TEST(OddSpecCheck, PermissiveSpecPasses) {
    const auto v = check_inline("odd_spec: t\nelements:\n  - path: Scenery/Track geometry/Horizontal/Curve\n"
                                "    attributes:\n      radius: {bins: [tight, medium]}\n"
                                "      direction: {values: [left, right]}\n"
                                "  - path: Scenery/Crossings/Level crossing\n"
                                "    attributes:\n      lights: {value: true}\n");
    EXPECT_TRUE(v.passed) << verdict_text(v);
    EXPECT_EQ(v.entries[1].unknown, 1u); // the open crossing has no lights tag
    EXPECT_NE(verdict_text(v).find("IN ODD"), std::string::npos);
}
