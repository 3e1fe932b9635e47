// Declared ODD specs: the shipped example against the shipped taxonomy, the
// admits_* checks, and every refusal of load_odd_spec() with file and line.
#include "railodd/odd/odd_spec.hpp"
#include "railodd/util/errors.hpp"

#include "test_support.hpp"

#include <gtest/gtest.h>

using namespace railodd::odd;
using railodd::test::scratch_dir;
using railodd::test::write_file;

namespace {

const std::filesystem::path data_dir = std::filesystem::path{RAILODD_SOURCE_DIR} / "data/odd";

const Taxonomy& taxonomy() {
    static const Taxonomy t = load_taxonomy(data_dir / "railway_odd.yaml");
    return t;
}

void expect_refused(const std::string& yaml, int line, std::initializer_list<std::string> needles) {
    const auto file = write_file(scratch_dir() / "spec.yaml", yaml);
    try {
        load_odd_spec(file, taxonomy());
        ADD_FAILURE() << "accepted:\n" << yaml;
    } catch (const railodd::InputError& e) {
        const std::string msg = e.what();
        EXPECT_NE(msg.find(file.string() + ":" + std::to_string(line) + ":"), std::string::npos) << msg;
        for (const auto& n : needles) {
            EXPECT_NE(msg.find(n), std::string::npos) << "'" << n << "' missing in: " << msg;
        }
    }
}

// One element entry (line 3) with `attrs` as its attribute block (from line 5).
std::string entry(const std::string& path, const std::string& attrs) {
    return "odd_spec: t\nelements:\n  - path: " + path + "\n    attributes:\n" + attrs;
}

} // namespace

TEST(OddSpec, LoadsTheShippedExample) {
    const OddSpec spec = load_odd_spec(data_dir / "example_odd_spec.yaml", taxonomy());
    EXPECT_EQ(spec.name, "Regional ATO over ETCS, 15 kV");
    EXPECT_TRUE(spec.unlisted_inside);
    EXPECT_EQ(spec.taxonomy_version, "1.0");

    const auto* curve = spec.find("Scenery/Track geometry/Horizontal/Curve");
    ASSERT_NE(curve, nullptr);
    EXPECT_EQ(curve->id, "sc.geo.hz.curve");
    const auto* radius = curve->find("radius");
    ASSERT_NE(radius, nullptr);
    EXPECT_EQ(radius->min, 300.0);
    EXPECT_FALSE(radius->max);

    const auto* diamond = spec.find("Scenery/Track layout/Diamond crossing");
    ASSERT_NE(diamond, nullptr);
    EXPECT_FALSE(diamond->allowed);
    EXPECT_EQ(spec.find("Scenery/Structures/Tunnel"), nullptr); // unlisted: inside
}

TEST(OddSpec, AdmitsValuesInsideTheDeclaredRanges) {
    const OddSpec spec = load_odd_spec(data_dir / "example_odd_spec.yaml", taxonomy());
    const auto& radius_attr = *taxonomy().attribute(*taxonomy().find("Scenery/Track geometry/Horizontal/Curve"), "radius");
    const auto& radius = *spec.find("Scenery/Track geometry/Horizontal/Curve")->find("radius");
    EXPECT_FALSE(admits_number(radius, radius_attr, 250.0));
    EXPECT_TRUE(admits_number(radius, radius_attr, 300.0));
    EXPECT_TRUE(admits_number(radius, radius_attr, 6000.0));

    const auto* rain_el = taxonomy().find("Environmental Conditions/Weather/Rain");
    const auto& rain = *spec.find(rain_el->path)->find("intensity");
    EXPECT_TRUE(admits_number(rain, *taxonomy().attribute(*rain_el, "intensity"), 7.5));  // moderate
    EXPECT_FALSE(admits_number(rain, *taxonomy().attribute(*rain_el, "intensity"), 7.6)); // heavy

    const auto& barrier = *spec.find("Scenery/Crossings/Level crossing")->find("barrier");
    EXPECT_TRUE(admits_value(barrier, "full"));
    EXPECT_FALSE(admits_value(barrier, "no"));
    const auto& lights = *spec.find("Scenery/Crossings/Level crossing")->find("lights");
    EXPECT_TRUE(admits_flag(lights, true));
    EXPECT_FALSE(admits_flag(lights, false));
}

TEST(OddSpec, AcceptsInheritedAttributes) {
    const auto file = write_file(scratch_dir() / "spec.yaml",
                                 entry("Dynamic Elements/Human actor/Role/Rail personnel",
                                       "      head_wear: {values: [hard_hat, helmet]}\n"
                                       "      height: {min: 1.5}\n"));
    const OddSpec spec = load_odd_spec(file, taxonomy());
    ASSERT_EQ(spec.elements.size(), 1u);
    EXPECT_EQ(spec.elements[0].attributes.size(), 2u);
}

TEST(OddSpec, RefusesUnknownElement) {
    expect_refused(entry("Scenery/Track geometry/Horizontal/Spiral", "      radius: {min: 300}\n"), 3,
                   {"element 'Scenery/Track geometry/Horizontal/Spiral' is not in the taxonomy"});
}

TEST(OddSpec, RefusesUnknownAttribute) {
    expect_refused(entry("Scenery/Track geometry/Horizontal/Curve", "      radius: {min: 300}\n      cant: {max: 100}\n"),
                   6, {"'Scenery/Track geometry/Horizontal/Curve' has no attribute 'cant'"});
}

TEST(OddSpec, RefusesValuesTheTaxonomyDoesNotDefine) {
    expect_refused(entry("Scenery/Crossings/Level crossing", "      barrier: {values: [full, gates]}\n"), 5,
                   {"attribute 'barrier'", "value 'gates' is not defined"});
    expect_refused(entry("Environmental Conditions/Weather/Rain", "      intensity: {bins: [drizzle]}\n"), 5,
                   {"attribute 'intensity'", "bin 'drizzle' is not defined"});
}

TEST(OddSpec, RefusesConstraintsOfTheWrongType) {
    expect_refused(entry("Scenery/Crossings/Level crossing", "      barrier: {min: 1}\n"), 5,
                   {"attribute 'barrier'", "'min' applies to numbers", "enum"});
    expect_refused(entry("Scenery/Crossings/Level crossing", "      lights: {values: [yes]}\n"), 5,
                   {"attribute 'lights'", "'values' applies to enums"});
    expect_refused(entry("Scenery/Track geometry/Horizontal/Curve", "      radius: {value: true}\n"), 5,
                   {"attribute 'radius'", "'value' applies to bools"});
    expect_refused(entry("Scenery/Track geometry/Horizontal/Curve", "      radius: {min: 900, max: 300}\n"), 5,
                   {"attribute 'radius'", "min is above max"});
}

TEST(OddSpec, RefusesUnknownKeysDuplicatesAndVersionMismatch) {
    expect_refused("odd_spec: t\nelements:\n  - path: Scenery\n    allow: false\n", 4,
                   {"spec entry 'Scenery'", "unknown key 'allow'"});
    expect_refused("odd_spec: t\nelements:\n  - path: Scenery\n  - path: Scenery\n", 4, {"listed twice"});
    expect_refused("odd_spec: t\ntaxonomy_version: \"0.9\"\nelements: []\n", 2, {"version '0.9'", "version '1.0'"});
    expect_refused("odd_spec: t\nunlisted_elements: maybe\nelements: []\n", 2, {"inside or outside"});
    expect_refused(entry("Scenery/Track geometry/Horizontal/Curve", "      radius: {minimum: 300}\n"), 5,
                   {"attribute 'radius'", "unknown key 'minimum'"});
}
