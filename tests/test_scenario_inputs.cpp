// Scenario inputs: the shipped asset catalog and base-scenario templates load
// against the shipped taxonomy, and every refusal of load_catalog() and
// load_templates() is an InputError naming the file, the line and the name.
#include "railodd/scenario/catalog.hpp"
#include "railodd/scenario/templates.hpp"
#include "railodd/util/errors.hpp"

#include "test_support.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <set>
#include <sstream>

using namespace railodd::scenario;
using railodd::test::scratch_dir;
using railodd::test::write_file;

namespace {

const std::filesystem::path source_dir{RAILODD_SOURCE_DIR};

const railodd::odd::Taxonomy& taxonomy() {
    static const auto t = railodd::odd::load_taxonomy(source_dir / "data/odd/railway_odd.yaml");
    return t;
}

const Catalog& shipped_catalog() {
    static const Catalog c = load_catalog(source_dir / "data/scenario/assets.yaml", taxonomy());
    return c;
}

// `text` with the first `from` replaced by `to`; fails the test when `from` is absent.
std::string edit(std::string text, const std::string& from, const std::string& to) {
    const auto at = text.find(from);
    EXPECT_NE(at, std::string::npos) << "'" << from << "' not in the test input";
    return at == std::string::npos ? text : text.replace(at, from.size(), to);
}

// The 1-based line of the first line holding `needle` (the line the loader must name).
int line_with(const std::string& text, const std::string& needle) {
    std::istringstream in(text);
    std::string l;
    for (int n = 1; std::getline(in, l); ++n) {
        if (l.find(needle) != std::string::npos) {
            return n;
        }
    }
    ADD_FAILURE() << "'" << needle << "' not in the test input";
    return -1;
}

template <class Load>
void expect_refused(const std::string& file_name, const std::string& yaml, int line,
                    std::initializer_list<std::string> needles, Load load) {
    const auto file = write_file(scratch_dir() / file_name, yaml);
    try {
        load(file);
        ADD_FAILURE() << "accepted:\n" << yaml;
    } catch (const railodd::InputError& e) {
        const std::string msg = e.what();
        const std::string where = file.string() + ":" + std::to_string(line) + ":";
        EXPECT_NE(msg.find(where), std::string::npos) << "expected '" << where << "' in: " << msg;
        for (const auto& n : needles) {
            EXPECT_NE(msg.find(n), std::string::npos) << "'" << n << "' missing in: " << msg;
        }
    }
}

// ------------------------------------------------------------------ catalog

// Two valid assets: a car (lines 3-11) and a pedestrian with attributes (12-20).
const std::string catalog_yaml = R"(catalog: test
assets:
  - id: car
    name: small car
    element: Dynamic Elements/Road vehicle/Passenger car
    kind: vehicle
    osc_category: car
    carla_blueprint: vehicle.test.car
    dimensions: {length: 4.5, width: 1.8, height: 1.4}
    mass: 1500
    performance: {max_speed_kmh: 180, max_acceleration: 4, max_deceleration: 8}
  - id: walker
    element: Dynamic Elements/Human actor/Role/Pedestrian
    kind: pedestrian
    osc_category: pedestrian
    carla_blueprint: walker.test
    dimensions: {length: 0.5, width: 0.6, height: 1.7}
    mass: 70
    performance: {max_speed_kmh: 10, max_acceleration: 1, max_deceleration: 2}
    attributes: {pose: standing, height: 1.7, group_size: 1}
)";

Catalog load_catalog_text(const std::string& yaml) {
    return load_catalog(write_file(scratch_dir() / "assets.yaml", yaml), taxonomy());
}

void expect_catalog_refused(const std::string& yaml, int line, std::initializer_list<std::string> needles) {
    expect_refused("assets.yaml", yaml, line, needles,
                   [](const std::filesystem::path& f) { load_catalog(f, taxonomy()); });
}

// ---------------------------------------------------------------- templates

// One valid template using the shipped catalog; every section the refusals edit.
const std::string templates_yaml = R"(name: test
templates:
  - id: crossing_person
    text: "Train at {speed} meets a {person} at {time_of_day} after a curve of {radius}"
    anchor:
      element: Scenery/Crossings/Level crossing
      where: {barrier: [full, half]}
    context:
      - element: Scenery/Track geometry/Horizontal/Curve
        within_m: 500
        where: {radius: {min: 100, max: 3000}}
    actors:
      - name: Person
        asset_class: Dynamic Elements/Human actor
        place: crossing_approach
        move_to: on_track
        move_speed_kmh: 5
    parameters:
      speed: {kind: ego_speed, values: [40, 80]}
      person: {kind: asset, actor: Person, values: [adult_passenger, child]}
      radius: {kind: map, from: context 0, attribute: radius}
    perturbations:
      time_of_day: {element: Environmental Conditions/Illumination/Time of day, attribute: period, values: [day, night]}
    constraints:
      exclude:
        - {person: child, time_of_day: night}
)";

void expect_templates_refused(const std::string& yaml, int line, std::initializer_list<std::string> needles) {
    expect_refused("templates.yaml", yaml, line, needles, [](const std::filesystem::path& f) {
        load_templates(f, taxonomy(), shipped_catalog());
    });
}

} // namespace

// ================================================================ shipped data

TEST(ScenarioInputs, ShippedCatalogLoads) {
    const Catalog& c = shipped_catalog();
    EXPECT_EQ(c.name, "railodd default assets");
    EXPECT_GE(c.assets.size(), 12u);
    std::set<std::string> ids;
    for (const auto& a : c.assets) {
        EXPECT_TRUE(ids.insert(a.id).second) << "duplicate " << a.id;
        EXPECT_EQ(a.element.rfind("Dynamic Elements/", 0), 0u) << a.id << ": " << a.element;
        EXPECT_GT(a.dimensions.length, 0.0) << a.id;
        EXPECT_GT(a.mass_kg, 0.0) << a.id;
        EXPECT_GT(a.max_speed_mps, 0.0) << a.id;
        EXPECT_GT(a.line, 0) << a.id;
    }
    // Every actor class the templates use has assets: trains, road vehicles, people, animals.
    for (const char* klass : {"Dynamic Elements/Rail vehicle/Ego train", "Dynamic Elements/Road vehicle",
                              "Dynamic Elements/Human actor/Role/Passenger", "Dynamic Elements/Animal"}) {
        EXPECT_FALSE(c.under(klass).empty()) << klass;
    }
    const Asset* cow = c.find("cow");
    ASSERT_NE(cow, nullptr);
    EXPECT_EQ(cow->kind, Actor::Kind::pedestrian);
    EXPECT_EQ(cow->osc_category, "animal");
    ASSERT_NE(cow->attribute("species"), nullptr);
    EXPECT_EQ(*cow->attribute("species"), "cattle");
    const Asset* emu = c.find("regional_emu");
    ASSERT_NE(emu, nullptr);
    EXPECT_NEAR(emu->max_speed_mps, 160.0 / 3.6, 1e-9);
    EXPECT_EQ(c.find("no_such_asset"), nullptr);
}

TEST(ScenarioInputs, ShippedTemplatesLoadAndCoverTheInfrastructure) {
    const TemplateSet set = load_templates(source_dir / "data/scenario/templates.yaml", taxonomy(), shipped_catalog());
    ASSERT_GE(set.templates.size(), 4u);
    std::set<std::string> anchors;
    for (const auto& t : set.templates) {
        anchors.insert(t.anchor.element);
        for (const auto& name : t.placeholders) {
            EXPECT_NE(t.parameter(name), nullptr) << t.id << ": {" << name << "} has no parameter";
            EXPECT_NE(t.text.find("{" + name + "}"), std::string::npos) << t.id << ": " << name;
        }
        for (const auto& p : t.parameters) {
            EXPECT_TRUE(p.kind == ParameterKind::map_value || !p.values.empty()) << t.id << ": " << p.name;
        }
    }
    for (const char* needed : {"Scenery/Crossings/Level crossing", "Scenery/Track geometry/Horizontal/Curve",
                               "Scenery/Stations and stops/Platform", "Scenery/Structures/Tunnel"}) {
        EXPECT_TRUE(anchors.contains(needed)) << "no template anchored on " << needed;
    }
    // The base scenario of the paper, with its curve context feeding {radius}.
    const auto paper = std::find_if(set.templates.begin(), set.templates.end(), [](const Template& t) {
        return t.text.find("Train driving at {speed}. The train is approaching a curved track") != std::string::npos;
    });
    ASSERT_NE(paper, set.templates.end()) << "the paper's template text is missing";
    EXPECT_EQ(paper->placeholders, (std::vector<std::string>{"speed", "radius", "street_vehicle"}));
    ASSERT_EQ(paper->context.size(), 1u);
    EXPECT_EQ(paper->context[0].element, "Scenery/Track geometry/Horizontal/Curve");
    const ParameterDomain* radius = paper->parameter("radius");
    ASSERT_NE(radius, nullptr);
    EXPECT_EQ(radius->kind, ParameterKind::map_value);
    EXPECT_EQ(radius->context, 0);
    EXPECT_EQ(radius->unit, "m");
    const ParameterDomain* vehicle = paper->parameter("street_vehicle");
    ASSERT_NE(vehicle, nullptr);
    EXPECT_EQ(vehicle->values, (std::vector<std::string>{"passenger_car", "delivery_van", "truck", "tractor"}));
}

TEST(ScenarioInputs, TemplateDefaultsAndDerivedValues) {
    const auto file = write_file(scratch_dir() / "templates.yaml", templates_yaml);
    const TemplateSet set = load_templates(file, taxonomy(), shipped_catalog());
    ASSERT_EQ(set.templates.size(), 1u);
    const Template& t = set.templates[0];
    EXPECT_EQ(t.line, 3);
    EXPECT_EQ(t.placeholders, (std::vector<std::string>{"speed", "person", "time_of_day", "radius"}));
    EXPECT_EQ(t.ego.asset_class, "Dynamic Elements/Rail vehicle/Ego train");
    ASSERT_EQ(t.anchor.where.size(), 1u);
    EXPECT_EQ(t.anchor.where[0].values, (std::vector<std::string>{"full", "half"}));
    ASSERT_EQ(t.context.size(), 1u);
    EXPECT_EQ(t.context[0].where[0].min, 100.0);
    EXPECT_EQ(t.context[0].where[0].max, 3000.0);
    ASSERT_EQ(t.actors.size(), 1u);
    EXPECT_EQ(t.actors[0].place, Lateral::crossing_approach);
    EXPECT_EQ(t.actors[0].move_to, Lateral::on_track);
    ASSERT_EQ(t.exclusions.size(), 1u);
    EXPECT_EQ(t.exclusions[0].line, 26);
    EXPECT_EQ(t.parameter("time_of_day")->kind, ParameterKind::perturbation);
    // An asset parameter without values takes every asset under the actor's class.
    const TemplateSet all = load_templates(
        write_file(scratch_dir() / "all.yaml", edit(templates_yaml, ", values: [adult_passenger, child]", "")),
        taxonomy(), shipped_catalog());
    EXPECT_EQ(all.templates[0].parameter("person")->values.size(),
              shipped_catalog().under("Dynamic Elements/Human actor").size());
}

// ====================================================== catalog refusals

TEST(ScenarioCatalog, TestInputLoadsAndResolvesTaxonomyIds) {
    const Catalog c = load_catalog_text(edit(catalog_yaml, "Dynamic Elements/Road vehicle/Passenger car", "dy.road.car"));
    ASSERT_EQ(c.assets.size(), 2u);
    EXPECT_EQ(c.assets[0].element, "Dynamic Elements/Road vehicle/Passenger car");
    EXPECT_EQ(c.assets[0].line, 3);
    EXPECT_EQ(c.assets[1].name, "walker"); // defaults to the id
    EXPECT_EQ(c.assets[1].osc_entry, "walker");
    EXPECT_EQ(c.assets[1].attributes.size(), 3u);
}

TEST(ScenarioCatalog, RefusesUnknownKeyAndDuplicateId) {
    expect_catalog_refused(edit(catalog_yaml, "    mass: 1500\n", "    mass: 1500\n    colour: red\n"),
                           line_with(catalog_yaml, "mass: 1500") + 1, {"asset 'car'", "unknown key 'colour'"});
    const std::string dup = edit(catalog_yaml, "id: walker", "id: car");
    expect_catalog_refused(dup, 12, {"asset 'car' is listed twice"});
}

TEST(ScenarioCatalog, RefusesElementsOutsideTheTaxonomyOrDynamicElements) {
    const int line = line_with(catalog_yaml, "Road vehicle/Passenger car");
    expect_catalog_refused(edit(catalog_yaml, "Road vehicle/Passenger car", "Road vehicle/Hovercraft"), line,
                           {"asset 'car'", "'Dynamic Elements/Road vehicle/Hovercraft' is not in the taxonomy"});
    expect_catalog_refused(edit(catalog_yaml, "Dynamic Elements/Road vehicle/Passenger car",
                                "Scenery/Crossings/Level crossing"),
                           line, {"asset 'car'", "'Scenery/Crossings/Level crossing' is not a Dynamic Element"});
}

TEST(ScenarioCatalog, RefusesAttributesAndValuesTheTaxonomyLacks) {
    const int car_attrs = 12; // inserted after the car's performance line
    expect_catalog_refused(edit(catalog_yaml, "  - id: walker", "    attributes: {pose: standing}\n  - id: walker"),
                           car_attrs, {"asset 'car'", "has no attribute 'pose'"});
    const int line = line_with(catalog_yaml, "attributes: {pose");
    expect_catalog_refused(edit(catalog_yaml, "pose: standing", "pose: flying"), line,
                           {"asset 'walker'", "attribute 'pose'", "'flying' is not one of"});
    // Height bins are [0, 1.2) .. [1.9, inf): 5 m is a "tall adult", -0.3 m lies outside every class.
    EXPECT_NO_THROW(load_catalog_text(edit(catalog_yaml, "height: 1.7,", "height: 5,")));
    expect_catalog_refused(edit(catalog_yaml, "height: 1.7,", "height: -0.3,"), line,
                           {"asset 'walker'", "attribute 'height'", "-0.3 lies outside every class"});
    // group_size bins start at 1.
    expect_catalog_refused(edit(catalog_yaml, "group_size: 1", "group_size: 0"), line,
                           {"asset 'walker'", "attribute 'group_size'", "outside every class"});
    expect_catalog_refused(edit(catalog_yaml, "height: 1.7,", "height: tall,"), line,
                           {"attribute 'height'", "'tall' is not a number"});
}

TEST(ScenarioCatalog, RefusesUnknownKindAndWrongCategory) {
    expect_catalog_refused(edit(catalog_yaml, "kind: vehicle", "kind: robot"), line_with(catalog_yaml, "kind: vehicle"),
                           {"asset 'car'", "kind must be vehicle, pedestrian or misc_object, not 'robot'"});
    expect_catalog_refused(edit(catalog_yaml, "osc_category: pedestrian", "osc_category: car"),
                           line_with(catalog_yaml, "osc_category: pedestrian"),
                           {"asset 'walker'", "'car' is not an OpenSCENARIO pedestrianCategory"});
    expect_catalog_refused(edit(catalog_yaml, "osc_category: car", "osc_category: spaceship"),
                           line_with(catalog_yaml, "osc_category: car"),
                           {"asset 'car'", "'spaceship' is not an OpenSCENARIO vehicleCategory"});
}

TEST(ScenarioCatalog, RefusesMissingDimensionsAndNonPositiveMass) {
    expect_catalog_refused(edit(catalog_yaml, "    dimensions: {length: 4.5, width: 1.8, height: 1.4}\n", ""), 3,
                           {"asset 'car'", "'dimensions' {length, width, height} is missing"});
    const int dims = line_with(catalog_yaml, "dimensions: {length: 4.5");
    expect_catalog_refused(edit(catalog_yaml, "width: 1.8, height: 1.4}", "width: 1.8}"), dims,
                           {"asset 'car'", "dimensions 'height' is missing"});
    expect_catalog_refused(edit(catalog_yaml, "length: 4.5,", "length: 0,"), dims,
                           {"asset 'car'", "dimensions 'length' must be positive", "not 0"});
    const int mass = line_with(catalog_yaml, "mass: 1500");
    expect_catalog_refused(edit(catalog_yaml, "mass: 1500", "mass: 0"), mass, {"asset 'car'", "'mass' must be positive"});
    expect_catalog_refused(edit(catalog_yaml, "mass: 1500", "mass: -20"), mass, {"asset 'car'", "not -20"});
    expect_catalog_refused(edit(catalog_yaml, "mass: 1500", "mass: heavy"), mass, {"asset 'car'", "must be a number"});
    // std::stod reads "inf" and "nan": every YAML number refuses them.
    expect_catalog_refused(edit(catalog_yaml, "mass: 1500", "mass: inf"), mass,
                           {"asset 'car'", "'mass' must be a number, not 'inf' (NaN and infinities are refused)"});
    expect_catalog_refused(edit(catalog_yaml, "mass: 1500", "mass: nan"), mass, {"asset 'car'", "not 'nan'"});
    expect_catalog_refused(edit(catalog_yaml, "max_speed_kmh: 180", "max_speed_kmh: inf"),
                           line_with(catalog_yaml, "max_speed_kmh: 180"), {"asset 'car'", "'max_speed_kmh'"});
}

TEST(ScenarioCatalog, RefusesYamlSyntaxErrorsAndVersionMismatch) {
    // An unclosed flow map: yaml-cpp reports it where the document goes on.
    const std::string broken = edit(catalog_yaml, "height: 1.4}", "height: 1.4");
    const auto file = write_file(scratch_dir() / "assets.yaml", broken);
    try {
        load_catalog(file, taxonomy());
        ADD_FAILURE() << "accepted a YAML syntax error";
    } catch (const railodd::InputError& e) {
        const std::string msg = e.what();
        EXPECT_NE(msg.find(file.string() + ":"), std::string::npos) << msg;
        EXPECT_NE(msg.find("invalid YAML in asset catalog"), std::string::npos) << msg;
    }
    // A key indented wrongly inside the first asset: the line is exact.
    expect_catalog_refused(edit(catalog_yaml, "    name: small car", "   name: small car"), 4, {"invalid YAML"});
    expect_catalog_refused("catalog: t\ntaxonomy_version: \"0.9\"\nassets: []\n", 2, {"version '0.9'", "'1.0'"});
    expect_catalog_refused("catalog: t\nassets: []\n", 2, {"non-empty 'assets' list"});
}

// ==================================================== template refusals

TEST(ScenarioTemplates, RefusesUnknownNamesInTextAnchorAndWhere) {
    const int text = line_with(templates_yaml, "text:");
    expect_templates_refused(edit(templates_yaml, "{radius}\"", "{radius} in {weather}\""), text,
                             {"template 'crossing_person'", "placeholder {weather}"});
    const int anchor = line_with(templates_yaml, "element: Scenery/Crossings/Level crossing");
    expect_templates_refused(edit(templates_yaml, "Crossings/Level crossing", "Crossings/Ford"), anchor,
                             {"template 'crossing_person'", "'Scenery/Crossings/Ford' is not in the taxonomy"});
    const int where = line_with(templates_yaml, "where: {barrier");
    expect_templates_refused(edit(templates_yaml, "{barrier: [full, half]}", "{colour: red}"), where,
                             {"template 'crossing_person'", "has no attribute 'colour'"});
    expect_templates_refused(edit(templates_yaml, "[full, half]", "[full, electric]"), where,
                             {"where 'barrier'", "'electric' is not one of"});
    expect_templates_refused(edit(templates_yaml, "{min: 100, max: 3000}", "{min: 3000, max: 100}"),
                             line_with(templates_yaml, "where: {radius"), {"where 'radius'", "min is above max"});
}

TEST(ScenarioTemplates, RefusesActorsAndAssetsTheCatalogDoesNotHave) {
    const int klass = line_with(templates_yaml, "asset_class: Dynamic Elements/Human actor");
    expect_templates_refused(edit(templates_yaml, "Dynamic Elements/Human actor", "Dynamic Elements/Rail vehicle/Other train"),
                             klass, {"actor 'Person'", "has no asset under 'Dynamic Elements/Rail vehicle/Other train'"});
    const int person = line_with(templates_yaml, "person: {kind: asset");
    expect_templates_refused(edit(templates_yaml, "actor: Person", "actor: Ghost"), person,
                             {"parameter 'person'", "the template has no actor 'Ghost'"});
    expect_templates_refused(edit(templates_yaml, "[adult_passenger, child]", "[adult_passenger, unicorn]"), person,
                             {"parameter 'person'", "asset 'unicorn' is not in the catalog"});
    expect_templates_refused(edit(templates_yaml, "[adult_passenger, child]", "[adult_passenger, cow]"), person,
                             {"parameter 'person'", "asset 'cow'", "not under the actor's class 'Dynamic Elements/Human actor'"});
    const int place = line_with(templates_yaml, "place: crossing_approach");
    expect_templates_refused(edit(templates_yaml, "place: crossing_approach", "place: on_roof"), place,
                             {"actor 'Person'", "'place' must be on_track", "not 'on_roof'"});
    // The switch's other track exists only at a switch anchor.
    expect_templates_refused(edit(templates_yaml, "place: crossing_approach", "place: branch_track"), place,
                             {"actor 'Person'", "place branch_track needs a switch anchor"});
}

TEST(ScenarioTemplates, RefusesPerturbationsWithoutMappingOrOutsideTheTaxonomy) {
    const std::string tod = "{element: Environmental Conditions/Illumination/Time of day, attribute: period, values: [day, night]}";
    const int line = line_with(templates_yaml, "time_of_day: {element");
    expect_templates_refused(edit(templates_yaml, tod, "{element: Scenery/Crossings/Level crossing, attribute: barrier, values: [full]}"),
                             line, {"perturbation 'time_of_day'", "'Scenery/Crossings/Level crossing' is not an Environmental Condition"});
    expect_templates_refused(edit(templates_yaml, tod, "{element: Environmental Conditions/Weather/Snow, attribute: depth_on_track, values: [10]}"),
                             line, {"perturbation 'time_of_day'", "no OpenSCENARIO mapping", "depth_on_track"});
    expect_templates_refused(edit(templates_yaml, tod, "{element: Environmental Conditions/Weather/Rain, attribute: intensity, values: [0, -1]}"),
                             line, {"perturbation 'time_of_day'", "-1 lies outside every class"});
    expect_templates_refused(edit(templates_yaml, tod, "{element: Environmental Conditions/Weather/Rain, attribute: colour, values: [red]}"),
                             line, {"perturbation 'time_of_day'", "has no attribute 'colour'"});
    // all_classes picks one value per rain class.
    std::string all = edit(templates_yaml, tod,
                           "{element: Environmental Conditions/Weather/Rain, attribute: intensity, all_classes: true}");
    all.resize(all.find("    constraints:")); // the exclusion names time_of_day: night
    const TemplateSet set = load_templates(write_file(scratch_dir() / "all.yaml", all), taxonomy(), shipped_catalog());
    EXPECT_EQ(set.templates[0].parameter("time_of_day")->values.size(), 5u); // none .. violent
}

TEST(ScenarioTemplates, RefusesMapParametersOfMissingContexts) {
    const int line = line_with(templates_yaml, "radius: {kind: map");
    expect_templates_refused(edit(templates_yaml, "from: context 0", "from: context 3"), line,
                             {"parameter 'radius'", "context N with N < 1"});
    expect_templates_refused(edit(templates_yaml, "from: context 0", "from: neighbour"), line,
                             {"parameter 'radius'", "not 'neighbour'"});
    for (const char* bad : {"context 0.5", "contexts0", "context_0", "context"}) {
        expect_templates_refused(edit(templates_yaml, "from: context 0", std::string("from: ") + bad), line,
                                 {"parameter 'radius'", "'from' must be anchor or context N"});
    }
    expect_templates_refused(edit(templates_yaml, "from: context 0, attribute: radius", "from: anchor, attribute: radius"),
                             line, {"parameter 'radius'", "'Scenery/Crossings/Level crossing' has no attribute 'radius'"});
}

TEST(ScenarioTemplates, RefusesNegativeDistances) {
    expect_templates_refused(edit(templates_yaml, "within_m: 500", "within_m: -500"),
                             line_with(templates_yaml, "within_m: 500"), {"context 'within_m' must be positive"});
    const std::string ego = edit(templates_yaml, "    actors:", "    ego: {run_up_m: 800, overrun_m: -5}\n    actors:");
    expect_templates_refused(ego, line_with(templates_yaml, "    actors:"), {"ego 'overrun_m' must not be negative"});
}

TEST(ScenarioTemplates, RefusesBadExclusionsDuplicateIdsAndUnknownKeys) {
    const int x = line_with(templates_yaml, "- {person: child");
    expect_templates_refused(edit(templates_yaml, "{person: child, time_of_day: night}", "{person: child, weather: snow}"),
                             x, {"exclusion names 'weather', which is not a varied parameter"});
    expect_templates_refused(edit(templates_yaml, "{person: child, time_of_day: night}", "{radius: 300}"), x,
                             {"exclusion names 'radius'"}); // a map value is not varied
    expect_templates_refused(edit(templates_yaml, "{person: child, time_of_day: night}", "{person: cow}"), x,
                             {"'cow' is not a value of parameter 'person'"});
    // The template appended twice: the second id is refused on its own line.
    // The template appended again: its id is refused on its own line, just after the
    // last line (26) of the first copy.
    const std::string body = templates_yaml.substr(templates_yaml.find("  - id:"));
    expect_templates_refused(templates_yaml + body, 27, {"template 'crossing_person' is listed twice"});
    expect_templates_refused(edit(templates_yaml, "    actors:", "    colour: red\n    actors:"),
                             line_with(templates_yaml, "    actors:"), {"template 'crossing_person'", "unknown key 'colour'"});
    expect_templates_refused(edit(templates_yaml, "name: test\n", "name: test\ntaxonomy_version: \"2.0\"\n"), 2,
                             {"version '2.0'"});
}
