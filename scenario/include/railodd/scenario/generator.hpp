#pragma once
// `railodd scenarios`: templates x anchors on the route x parameter rows ->
// concrete scenarios with their traceability records (docs/scenarios.md).
#include "railodd/odd/odd_spec.hpp"
#include "railodd/odd/profile.hpp"
#include "railodd/odd/taxonomy.hpp"
#include "railodd/scenario/anchors.hpp"
#include "railodd/scenario/catalog.hpp"
#include "railodd/scenario/concrete.hpp"
#include "railodd/scenario/strategies.hpp"
#include "railodd/scenario/target.hpp"
#include "railodd/scenario/templates.hpp"

#include <cstddef>
#include <cstdint>
#include <string>
#include <utility>
#include <vector>

namespace railodd::scenario {

// A junction's connecting road (a switch's leg in the map): what it links.
struct ConnectingRoad {
    std::string id;
    std::string junction;
    std::string from, to; // its predecessor and successor roads
    double length = 0.0;
};

struct GenerateOptions {
    Strategy strategy = Strategy::cover;
    std::size_t count = 0;     // random: rows per template (required); full / pairwise: 0 = all
    std::uint64_t seed = 1;
    std::size_t max_anchors = 0; // per template, spread evenly along the route; 0 = all
    std::string map_file;        // LogicFile path as the .xosc files will reference it
    std::string catalog_dir = "catalogs";
    std::string date = "2026-01-01T00:00:00"; // FileHeader date (the map's)
    // The player: names the catalog entries (target.hpp entry_name) and
    // samples the ego's run where the target cannot route it
    // (ConcreteScenario::ego_track).
    Target target = Target::esmini;
    // The map's connecting roads. The profile runs a track on through its
    // switch's main-track connecting road; a route that leaves the switch on
    // the other leg takes the connecting road to it instead (the player
    // routes by road: Munich's ego left its route there).
    std::vector<ConnectingRoad> connecting_roads;
};

// One ODD element and attribute value a scenario exercises.
struct CoveredValue {
    std::string element;   // taxonomy path
    std::string attribute; // empty: the element itself
    std::string value;     // as text
    std::string value_class; // bin label, enum value
    std::string source;    // "map", "asset", "perturbation", "parameter"
};

struct ScenarioRecord {
    ConcreteScenario scenario;
    std::string template_id;
    std::vector<std::pair<std::string, std::string>> values; // placeholder -> value text (as in the text)
    std::vector<std::pair<std::string, std::string>> raw;    // placeholder -> raw value (number, asset id)
    Anchor anchor;
    std::vector<std::pair<std::string, std::string>> assets; // actor -> asset id
    std::vector<CoveredValue> odd_elements;
    std::string speed_basis; // "parameter", "speed limit", "default line speed", "default"
};

struct TemplateRun {
    std::string template_id;
    std::size_t anchors = 0;
    std::vector<SkippedAnchor> skipped;
    // Anchors (their profile elements) where the constraints admit no row,
    // e.g. a speed limit below every ego speed of the template.
    std::vector<std::size_t> infeasible;
    // Parameter values no valid row holds (an exclusion, a speed above every
    // limit): (parameter, value).
    std::vector<std::pair<std::string, std::string>> infeasible_values;
    std::vector<std::string> dimensions;  // "anchor", then the varied parameters
    std::vector<std::size_t> sizes;
    std::size_t rows = 0;
    bool every_valid_row = false; // random: fewer valid rows than --count, all of them taken
    PairStats pairs;          // cover: pairs of the parameters alone
    // cover: what the same template needs under the other strategies.
    double full_factorial = 0.0;
    std::size_t pairwise_rows = 0;
};

struct Generation {
    std::vector<ScenarioRecord> scenarios; // by template, then row
    std::vector<TemplateRun> runs;
    std::vector<Actor> catalog_entries;    // every asset used, for the OpenSCENARIO catalogs
};

// Throws railodd::InputError when the profile has no track geometry, and
// std::invalid_argument for a random strategy without a count.
Generation generate(const odd::OddProfile& profile, const TemplateSet& templates, const Catalog& catalog,
                    const odd::Taxonomy& taxonomy, const GenerateOptions& options);

} // namespace railodd::scenario
