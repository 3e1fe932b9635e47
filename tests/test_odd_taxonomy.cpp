// The shipped ODD taxonomy (data/odd/railway_odd.yaml): its shape, its classes,
// and every refusal of load_taxonomy() with file, line and element named.
#include "railodd/odd/taxonomy.hpp"
#include "railodd/odd/tag_values.hpp"
#include "railodd/util/errors.hpp"

#include "test_support.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <iostream>

using namespace railodd::odd;
using railodd::test::scratch_dir;
using railodd::test::write_file;

namespace {

std::filesystem::path shipped() { return std::filesystem::path{RAILODD_SOURCE_DIR} / "data/odd/railway_odd.yaml"; }

const Taxonomy& taxonomy() {
    static const Taxonomy t = load_taxonomy(shipped());
    return t;
}

const Attribute& attr(const std::string& path, const std::string& name) {
    const Element* e = taxonomy().find(path);
    EXPECT_NE(e, nullptr) << path;
    const Attribute* a = e ? taxonomy().attribute(*e, name) : nullptr;
    if (a == nullptr) {
        throw std::runtime_error("no attribute " + path + "@" + name);
    }
    return *a;
}

// A minimal valid file with `body` spliced in as the children of Scenery.
std::string with_children(const std::string& body) {
    return "taxonomy: t\nversion: \"1\"\nelements:\n  - name: Scenery\n    id: sc\n    children:\n" + body;
}

// Loads `yaml` from a scratch file and expects an InputError naming the file,
// `line` and every string of `needles`.
void expect_refused(const std::string& yaml, int line, std::initializer_list<std::string> needles) {
    const auto file = write_file(scratch_dir() / "taxonomy.yaml", yaml);
    try {
        load_taxonomy(file);
        ADD_FAILURE() << "accepted:\n" << yaml;
    } catch (const railodd::InputError& e) {
        const std::string msg = e.what();
        EXPECT_NE(msg.find(file.string() + ":" + std::to_string(line) + ":"), std::string::npos) << msg;
        for (const auto& n : needles) {
            EXPECT_NE(msg.find(n), std::string::npos) << "'" << n << "' missing in: " << msg;
        }
    }
}

} // namespace

TEST(OddTaxonomy, ShippedFileHasFiveTopCategories) {
    const auto top = taxonomy().top_level();
    ASSERT_EQ(top.size(), 5u);
    const std::vector<std::string> names{"Scenery", "Operational Conditions", "Environmental Conditions",
                                         "Dynamic Elements", "Connectivity"};
    for (std::size_t i = 0; i < names.size(); ++i) {
        EXPECT_EQ(top[i]->name, names[i]);
        EXPECT_EQ(top[i]->level, 1);
    }
    EXPECT_EQ(taxonomy().version, "1.0");
    std::cout << "elements: " << taxonomy().elements.size() << ", attributes: " << taxonomy().attribute_count()
              << '\n';
}

TEST(OddTaxonomy, ShippedFileIsAtMostFourLevelsWithConsistentPaths) {
    int deepest = 0;
    for (const auto& e : taxonomy().elements) {
        deepest = std::max(deepest, e.level);
        EXPECT_LE(e.level, max_levels) << e.path;
        const Element* p = taxonomy().parent(e);
        EXPECT_EQ(e.path, p ? p->path + "/" + e.name : e.name);
        EXPECT_EQ(taxonomy().find(e.path), &e);
        EXPECT_EQ(taxonomy().find_id(e.id), &e);
    }
    EXPECT_EQ(deepest, 4);
}

TEST(OddTaxonomy, FindsElementsByPath) {
    const Element* curve = taxonomy().find("Scenery/Track geometry/Horizontal/Curve");
    ASSERT_NE(curve, nullptr);
    EXPECT_EQ(curve->level, 4);
    EXPECT_EQ(curve->id, "sc.geo.hz.curve");
    EXPECT_EQ(curve->iso34503, "Curves");
    EXPECT_EQ(taxonomy().find("Scenery/Track geometry/Horizontal/Spiral"), nullptr);
    EXPECT_EQ(taxonomy().find("Scenery/Track geometry/Horizontal/"), nullptr);
    EXPECT_NE(taxonomy().find("Connectivity/Positioning/GNSS"), nullptr);
    EXPECT_NE(taxonomy().find("Scenery/Crossings/Level crossing"), nullptr);
}

TEST(OddTaxonomy, AttributesAreInheritedFromAncestors) {
    // VRAIL's example: Dynamic elements / Human actor / Role / Rail personnel,
    // with pose, height and head-wear described on the human actor.
    const Element* staff = taxonomy().find("Dynamic Elements/Human actor/Role/Rail personnel");
    ASSERT_NE(staff, nullptr);
    EXPECT_EQ(staff->level, 4);
    EXPECT_TRUE(staff->attributes.empty());
    for (const auto* name : {"pose", "height", "head_wear", "clothing"}) {
        EXPECT_NE(taxonomy().attribute(*staff, name), nullptr) << name;
    }
    const Attribute* head = taxonomy().attribute(*staff, "head_wear");
    EXPECT_EQ(head->type, AttributeType::enumeration);
    EXPECT_TRUE(head->has_value("hard_hat"));
    EXPECT_EQ(taxonomy().attribute(*staff, "radius"), nullptr);
}

TEST(OddTaxonomy, ClassifiesRadiusIntoEn13803Classes) {
    const Attribute& radius = attr("Scenery/Track geometry/Horizontal/Curve", "radius");
    EXPECT_EQ(radius.unit, "m");
    EXPECT_EQ(classify(radius, 250.0), "tight");
    EXPECT_EQ(classify(radius, 1200.0), "large"); // [1200, 3000): lower end closed
    EXPECT_EQ(classify(radius, 1199.9), "medium");
    EXPECT_EQ(classify(radius, 6000.0), "wide");
    EXPECT_EQ(classify(radius, 100.0), "very tight");
    EXPECT_EQ(classify(radius, -5.0), ""); // below every bin
}

TEST(OddTaxonomy, ClassifiesGradientWithClosedUpperEnds) {
    const Attribute& g = attr("Scenery/Track geometry/Vertical/Gradient", "gradient");
    EXPECT_EQ(g.unit, "permille");
    EXPECT_EQ(classify(g, 0.0), "level");
    EXPECT_EQ(classify(g, 1.0), "level");
    EXPECT_EQ(classify(g, 1.01), "light");
    EXPECT_EQ(classify(g, 12.5), "moderate");
    EXPECT_EQ(classify(g, 25.0), "steep");
    EXPECT_EQ(classify(g, 40.0), "very steep");
    EXPECT_EQ(classify(g, 70.0), "extreme");
}

TEST(OddTaxonomy, ClassifiesWeatherSpeedAndElectrification) {
    EXPECT_EQ(classify(attr("Environmental Conditions/Weather/Rain", "intensity"), 5.0), "moderate");
    EXPECT_EQ(classify(attr("Environmental Conditions/Particulates/Fog", "visibility"), 150.0), "thick");
    // Aliased bins (YAML anchor) classify the same way.
    EXPECT_EQ(classify(attr("Environmental Conditions/Particulates/Smoke", "visibility"), 150.0), "thick");
    EXPECT_EQ(classify(attr("Environmental Conditions/Weather/Wind", "speed"), 20.0), "gale");
    EXPECT_EQ(classify(attr("Operational Conditions/Speed/Speed limit", "maxspeed"), 160.0), "main line");
    EXPECT_EQ(classify(attr("Operational Conditions/Speed/Speed limit", "maxspeed"), 300.0), "high speed");
    EXPECT_EQ(classify(attr("Scenery/Trackside equipment/Electrification", "voltage"), 15000.0), "15 kV AC");
    EXPECT_EQ(classify(attr("Scenery/Trackside equipment/Electrification", "frequency"), 16.7), "16.7 Hz");
    EXPECT_EQ(classify(attr("Scenery/Track layout/Track count", "tracks"), 2.0), "double");
    EXPECT_EQ(classify(attr("Scenery/Track geometry/Gauge", "gauge"), 1435.0), "standard");
}

TEST(OddTaxonomy, EveryBinIntervalPrintsAndEveryEnumHasValues) {
    for (const auto& e : taxonomy().elements) {
        for (const auto& a : e.attributes) {
            if (a.type == AttributeType::enumeration) {
                EXPECT_FALSE(a.values.empty()) << e.path << "@" << a.name;
            }
            for (const auto& b : a.bins) {
                EXPECT_EQ(classify(a, std::isinf(b.lower) ? b.upper - 1.0 : b.lower + (b.lower_closed ? 0.0 : 1e-9)),
                          b.label)
                    << e.path << "@" << a.name << " " << b.interval();
            }
        }
    }
}

TEST(OddTaxonomy, TagParserNamesAreTaxonomyValues) {
    // The tagger stores to_string() of parsed tags as attribute values, so every
    // name must exist in the taxonomy's enum.
    const auto has = [](const std::string& path, const std::string& name, const std::string& value) {
        return attr(path, name).has_value(value);
    };
    for (auto e : {Electrification::contact_line, Electrification::rail, Electrification::fourth_rail,
                   Electrification::ground_level, Electrification::unspecified, Electrification::none}) {
        EXPECT_TRUE(has("Scenery/Trackside equipment/Electrification", "system", to_string(e))) << to_string(e);
    }
    for (auto u : {Usage::main, Usage::branch, Usage::industrial, Usage::military, Usage::tourism, Usage::scientific,
                   Usage::test}) {
        EXPECT_TRUE(has("Operational Conditions/Usage/Line usage", "usage", to_string(u))) << to_string(u);
    }
    for (auto s : {Service::siding, Service::yard, Service::spur, Service::crossover}) {
        EXPECT_TRUE(has("Operational Conditions/Usage/Track service", "service", to_string(s))) << to_string(s);
    }
    for (auto d : {PreferredDirection::forward, PreferredDirection::backward, PreferredDirection::both}) {
        EXPECT_TRUE(has("Operational Conditions/Direction/Preferred direction", "direction", to_string(d)));
    }
    for (auto b : {Barrier::no, Barrier::yes, Barrier::half, Barrier::double_half, Barrier::full, Barrier::gate,
                   Barrier::chain}) {
        EXPECT_TRUE(has("Scenery/Crossings/Level crossing", "barrier", to_string(b))) << to_string(b);
    }
    for (auto k : {SpeedLimitKind::posted, SpeedLimitKind::signals, SpeedLimitKind::none, SpeedLimitKind::unknown}) {
        EXPECT_TRUE(has("Operational Conditions/Speed/Speed limit", "kind", to_string(k))) << to_string(k);
    }
    for (auto f : {SignalForm::light, SignalForm::semaphore, SignalForm::sign}) {
        EXPECT_TRUE(has("Scenery/Trackside equipment/Signal", "form", to_string(f)));
    }
    for (auto r : {TrainRadio::gsm_r, TrainRadio::frmcs, TrainRadio::analogue, TrainRadio::none}) {
        EXPECT_TRUE(has("Connectivity/Communication/Train radio", "system", to_string(r))) << to_string(r);
    }
    // The OSM reader's land-use kinds (docs/odd.md "Land use").
    for (const char* kind : {"urban", "suburban", "rural", "industrial", "forest", "agricultural", "water"}) {
        EXPECT_TRUE(has("Scenery/Surroundings/Land use", "kind", kind)) << kind;
    }
    for (int c = 0; c <= static_cast<int>(SignalCategory::other); ++c) {
        const auto* name = to_string(static_cast<SignalCategory>(c));
        EXPECT_TRUE(has("Scenery/Trackside equipment/Signal", "category", name)) << name;
    }
}

// --- refusals: each names the file, the line and the element ---------------

TEST(OddTaxonomy, RefusesUnknownElementKey) {
    expect_refused(with_children("      - name: Track geometry\n"
                                 "        id: sc.geo\n"
                                 "        colour: red\n"),
                   9, {"element 'Scenery/Track geometry'", "unknown key 'colour'"});
}

TEST(OddTaxonomy, RefusesUnknownAttributeKey) {
    expect_refused(with_children("      - name: Curve\n"
                                 "        id: c\n"
                                 "        attributes:\n"
                                 "          - name: radius\n"
                                 "            typ: number\n"),
                   11, {"element 'Scenery/Curve'", "attribute 'radius'", "unknown key 'typ'"});
}

TEST(OddTaxonomy, RefusesAFifthLevel) {
    expect_refused(with_children("      - name: A\n"
                                 "        id: a\n"
                                 "        children:\n"
                                 "          - name: B\n"
                                 "            id: b\n"
                                 "            children:\n"
                                 "              - name: C\n"
                                 "                id: c\n"
                                 "                children:\n"
                                 "                  - name: D\n"
                                 "                    id: d\n"),
                   16, {"element 'Scenery/A/B/C/D'", "level 5", "allows 4 levels"});
}

TEST(OddTaxonomy, RefusesDuplicatePaths) {
    expect_refused(with_children("      - name: Tunnel\n"
                                 "        id: t1\n"
                                 "      - name: Tunnel\n"
                                 "        id: t2\n"),
                   9, {"duplicate path 'Scenery/Tunnel'", "first at line 7"});
}

TEST(OddTaxonomy, RefusesDuplicateIds) {
    expect_refused(with_children("      - name: Tunnel\n"
                                 "        id: t\n"
                                 "      - name: Bridge\n"
                                 "        id: t\n"),
                   10, {"element 'Scenery/Bridge'", "duplicate id 't'", "'Scenery/Tunnel'"});
}

namespace {

std::string radius_bins(const std::string& first, const std::string& second) {
    return with_children("      - name: Curve\n"
                         "        id: c\n"
                         "        attributes:\n"
                         "          - name: radius\n"
                         "            type: number\n"
                         "            bins:\n"
                         "              - {label: tight, range: \"" + first + "\"}\n"
                         "              - {label: wide, range: \"" + second + "\"}\n");
}

} // namespace

TEST(OddTaxonomy, RefusesOverlappingBins) {
    expect_refused(radius_bins("[0, 300)", "[250, inf)"), 14,
                   {"element 'Scenery/Curve'", "attribute 'radius'", "overlap"});
    // Touching ends overlap when both are closed.
    expect_refused(radius_bins("[0, 300]", "[300, inf)"), 14, {"attribute 'radius'", "overlap"});
}

TEST(OddTaxonomy, RefusesDescendingBins) {
    expect_refused(radius_bins("[300, inf)", "[0, 300)"), 14,
                   {"element 'Scenery/Curve'", "attribute 'radius'", "not in ascending order"});
}

TEST(OddTaxonomy, RefusesBinsWithAGap) {
    expect_refused(radius_bins("[0, 300)", "(300, inf)"), 14, {"attribute 'radius'", "gap"});
}

TEST(OddTaxonomy, RefusesMalformedAndEmptyRanges) {
    expect_refused(radius_bins("[0; 300)", "[300, inf)"), 13, {"attribute 'radius'", "bin 'tight'", "not an interval"});
    expect_refused(radius_bins("[300, 0)", "[300, inf)"), 13, {"bin 'tight'", "empty"});
}

TEST(OddTaxonomy, RefusesAttributeWithoutType) {
    expect_refused(with_children("      - name: Curve\n"
                                 "        id: c\n"
                                 "        attributes:\n"
                                 "          - name: radius\n"
                                 "            unit: m\n"),
                   10, {"element 'Scenery/Curve'", "attribute 'radius'", "has no 'type'"});
}

TEST(OddTaxonomy, RefusesUnknownType) {
    expect_refused(with_children("      - name: Curve\n"
                                 "        id: c\n"
                                 "        attributes:\n"
                                 "          - {name: radius, type: float}\n"),
                   10, {"attribute 'radius'", "unknown type 'float'"});
}

TEST(OddTaxonomy, RefusesEnumWithoutValues) {
    expect_refused(with_children("      - name: Platform\n"
                                 "        id: p\n"
                                 "        attributes:\n"
                                 "          - name: side\n"
                                 "            type: enum\n"),
                   10, {"element 'Scenery/Platform'", "attribute 'side'", "non-empty 'values'"});
}

TEST(OddTaxonomy, RefusesBinsOnAnEnum) {
    expect_refused(with_children("      - name: Platform\n"
                                 "        id: p\n"
                                 "        attributes:\n"
                                 "          - name: side\n"
                                 "            type: enum\n"
                                 "            values: [left, right]\n"
                                 "            bins: [{label: a, range: \"[0, 1)\"}]\n"),
                   13, {"attribute 'side'", "'bins' only apply to numbers"});
}

TEST(OddTaxonomy, RefusesAttributeRepeatingAnInheritedOne) {
    expect_refused(with_children("      - name: Human\n"
                                 "        id: h\n"
                                 "        attributes:\n"
                                 "          - {name: height, type: number}\n"
                                 "        children:\n"
                                 "          - name: Child\n"
                                 "            id: hc\n"
                                 "            attributes:\n"
                                 "              - {name: height, type: number}\n"),
                   15, {"element 'Scenery/Human/Child'", "attribute 'height'", "inherited", "line 10"});
}

TEST(OddTaxonomy, RefusesInvalidYamlAndMissingFiles) {
    const auto file = write_file(scratch_dir() / "broken.yaml", "elements:\n  - name: [Scenery\n");
    try {
        load_taxonomy(file);
        ADD_FAILURE() << "accepted broken YAML";
    } catch (const railodd::InputError& e) {
        EXPECT_NE(std::string(e.what()).find(file.string() + ":"), std::string::npos) << e.what();
        EXPECT_NE(std::string(e.what()).find("invalid YAML"), std::string::npos) << e.what();
    }
    EXPECT_THROW(load_taxonomy(scratch_dir() / "absent.yaml"), railodd::InputError);
}
