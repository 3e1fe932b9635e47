// generate() on a hand-made profile of three lines whose speed limits are
// 100, 300 and 400 km/h: a template that names no train runs each line with a
// train that can (the shipped catalog's regional EMU, then its high-speed
// train), a line no train of the class can run is "constraint infeasible" in
// the run and in the coverage, and the cover strategy never chooses it.
#include "railodd/odd/taxonomy.hpp"
#include "railodd/scenario/catalog.hpp"
#include "railodd/scenario/coverage.hpp"
#include "railodd/scenario/generator.hpp"
#include "railodd/scenario/templates.hpp"

#include "odd_profile_support.hpp"
#include "test_support.hpp"

#include <gtest/gtest.h>

using namespace railodd;
using namespace railodd::scenario;
using railodd::test::tagged;

namespace {

const std::filesystem::path data_dir = std::filesystem::path{RAILODD_SOURCE_DIR} / "data";

const std::string templates_yaml = R"(name: line speed
taxonomy_version: "1.0"
templates:
  - id: curve_at_line_speed
    text: "Train at {speed} into a curve"
    anchor: {element: Scenery/Track geometry/Horizontal/Curve}
    ego: {run_up_m: 500, min_run_up_m: 100, overrun_m: 200}
    parameters:
      speed: {kind: ego_speed, limit_fractions: [1.0]}
)";

// Track k: a straight, a curve from 900 to 1100 m, a straight, on road k+1;
// its speed limit over the whole track.
odd::OddProfile lines(const std::vector<double>& limits) {
    odd::OddProfile p;
    p.taxonomy_version = "1.0";
    for (std::size_t k = 0; k < limits.size(); ++k) {
        const std::string road = std::to_string(k + 1), way = "way:" + road;
        std::vector<odd::TaggedElement> es = {
            tagged("Scenery/Track geometry/Horizontal/Straight", "sc.geo.hz.straight", {}, road, 0, 900, 0, 900, {way}),
            tagged("Scenery/Track geometry/Horizontal/Curve", "sc.geo.hz.curve",
                   {{"radius", 2500.0}, {"direction", std::string{"left"}}}, road, 900, 1100, 900, 1100, {way}),
            tagged("Scenery/Track geometry/Horizontal/Straight", "sc.geo.hz.straight", {}, road, 1100, 2000, 1100, 2000,
                   {way}),
            tagged("Operational Conditions/Speed/Speed limit", "op.speed.limit", {{"maxspeed", limits[k]}}, road, 0,
                   2000, 0, 2000, {way}),
        };
        for (auto& e : es) {
            e.track = k;
            p.elements.push_back(std::move(e));
        }
        p.length_m += 2000.0;
        ++p.tracks;
    }
    return p;
}

struct Inputs {
    odd::Taxonomy taxonomy = odd::load_taxonomy(data_dir / "odd" / "railway_odd.yaml");
    Catalog catalog = load_catalog(data_dir / "scenario" / "assets.yaml", taxonomy);
    TemplateSet templates;
    Inputs() {
        const auto dir = railodd::test::scratch_dir();
        templates = load_templates(railodd::test::write_file(dir / "t.yaml", templates_yaml), taxonomy, catalog);
    }
};

} // namespace

TEST(ScenarioGenerate, TheEgoIsATrainThatCanRunTheLineSpeed) {
    const Inputs in;
    for (const auto strategy : {Strategy::pairwise, Strategy::cover}) {
        SCOPED_TRACE(to_string(strategy));
        GenerateOptions o;
        o.strategy = strategy;
        const auto p = lines({100.0, 300.0, 400.0});
        const Generation g = generate(p, in.templates, in.catalog, in.taxonomy, o);
        ASSERT_EQ(g.runs.size(), 1u);
        EXPECT_EQ(g.runs[0].anchors, 3u);
        ASSERT_EQ(g.runs[0].infeasible.size(), 1u) << "no Ego train of the catalog runs 400 km/h";
        EXPECT_EQ(p.elements[g.runs[0].infeasible[0]].track, 2u);
        std::map<std::size_t, std::string> ego_on; // track -> ego asset
        for (const auto& s : g.scenarios) {
            ego_on[p.elements[s.anchor.element].track] = s.assets.front().second;
            EXPECT_EQ(s.assets.front().first, "Ego");
        }
        if (strategy == Strategy::pairwise) {
            EXPECT_EQ(ego_on, (std::map<std::size_t, std::string>{{0, "regional_emu"}, {1, "high_speed_train"}}));
        } else {
            EXPECT_FALSE(ego_on.contains(2)) << "cover chose the infeasible anchor";
        }
        const odd::Taxonomy& tax = in.taxonomy;
        const Coverage c = compute_coverage(p, tax, g, nullptr, &in.templates);
        for (const auto& item : c.route) {
            EXPECT_TRUE(item.scenarios > 0 || !item.reason.empty()) << item.element << " " << item.value_class;
        }
    }
}

TEST(ScenarioGenerate, AClassOnlyAnInfeasibleAnchorHoldsIsConstraintInfeasible) {
    const Inputs in;
    // Only the 400 km/h line has a curve of direction right.
    auto p = lines({100.0, 400.0});
    for (auto& e : p.elements) {
        if (e.track == 1 && e.element == "Scenery/Track geometry/Horizontal/Curve") {
            e.attributes[1].value = std::string{"right"};
        }
    }
    const Generation g = generate(p, in.templates, in.catalog, in.taxonomy, GenerateOptions{});
    const Coverage c = compute_coverage(p, in.taxonomy, g, nullptr, &in.templates);
    bool found = false;
    for (const auto& item : c.route) {
        if (item.element == "Scenery/Track geometry/Horizontal/Curve" && item.value_class == "right") {
            found = true;
            EXPECT_EQ(item.scenarios, 0u);
            EXPECT_EQ(item.reason.rfind("constraint infeasible", 0), 0u) << "[" << item.reason << "]";
        }
    }
    EXPECT_TRUE(found);
}

// A perturbation value every row of which an exclusion forbids is
// "constraint infeasible" for the declared ODD, not "not drawn".
TEST(ScenarioGenerate, ASpecValueOnlyAnExclusionForbidsIsConstraintInfeasible) {
    Inputs in;
    const auto dir = railodd::test::scratch_dir();
    in.templates = load_templates(railodd::test::write_file(dir / "t.yaml", templates_yaml + R"(    perturbations:
      rain: {element: Environmental Conditions/Weather/Rain, attribute: intensity, values: [0, 20]}
    constraints:
      exclude:
        - {rain: 20}
)"),
                                  in.taxonomy, in.catalog);
    const auto spec = odd::load_odd_spec(railodd::test::write_file(dir / "spec.yaml", R"(odd_spec: wet
elements:
  - path: Environmental Conditions/Weather/Rain
    attributes: {intensity: {bins: [none, light, heavy]}}
)"),
                                         in.taxonomy);
    const auto p = lines({100.0});
    const Generation g = generate(p, in.templates, in.catalog, in.taxonomy, GenerateOptions{});
    ASSERT_EQ(g.runs[0].infeasible_values.size(), 1u);
    EXPECT_EQ(g.runs[0].infeasible_values[0], (std::pair<std::string, std::string>{"rain", "20"}));
    const Coverage c = compute_coverage(p, in.taxonomy, g, &spec, &in.templates);
    std::size_t infeasible = 0, no_template = 0;
    for (const auto& item : c.spec) {
        if (item.scenarios > 0) {
            continue;
        }
        infeasible += item.reason.rfind("constraint infeasible", 0) == 0 ? 1 : 0;
        no_template += item.reason == "no template varies it" ? 1 : 0;
    }
    EXPECT_EQ(infeasible, 1u) << "heavy: 20 mm/h";
    EXPECT_EQ(no_template, 1u) << "light: no template lists it";
}
