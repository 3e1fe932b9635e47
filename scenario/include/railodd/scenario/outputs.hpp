#pragma once
// The files of a scenario set (docs/scenarios.md "Outputs"): ID.xosc and
// ID.behavior.yaml per scenario, catalogs/, distributions/ (not under
// OpenSCENARIO 1.0, which has no ParameterValueDistribution), manifest.json,
// coverage.json and coverage.txt.
#include "railodd/odd/profile.hpp"
#include "railodd/scenario/coverage.hpp"
#include "railodd/scenario/generator.hpp"
#include "railodd/scenario/xosc_writer.hpp"
#include "railodd/util/output_stage.hpp"

#include <cstdint>
#include <map>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

namespace railodd::scenario {

struct OutputInfo {
    std::string map_dir;
    std::string map_file;       // as the .xosc files reference it (relative)
    std::string taxonomy_file;
    std::string catalog_file;
    std::string templates_file;
    std::string spec_file;      // empty: none
    Strategy strategy = Strategy::pairwise;
    std::size_t count = 0;
    std::uint64_t seed = 1;
    int osc_minor = 2;
    std::string date;           // FileHeader date of every document
    Target target = Target::esmini;
};

// Per scenario id, what its document could not express for the target
// (XoscDocument::degraded_for_target).
using Degradations = std::map<std::string, std::vector<Degradation>>;

// manifest.json: every scenario with its template, parameters, anchor, assets,
// perturbations and the ODD elements it covers with their sources; under the
// carla target also its `degraded_for_target` (from `degraded`, empty lists
// for scenarios it does not name).
nlohmann::ordered_json manifest_json(const Generation& g, const odd::OddProfile& profile, const OutputInfo& info,
                                     const Degradations& degraded = {});

// ID.behavior.yaml (format railodd-behavior 1): the motions OpenSCENARIO
// players handle poorly, for a custom controller.
std::string behavior_yaml(const ScenarioRecord& rec, const odd::OddProfile& profile);

// Whether the set has distributions/TEMPLATE.xosc: OpenSCENARIO 1.1 and later.
bool has_distributions(const OutputInfo& info);

// Writes the whole set into the stage (committed by the caller).
void write_scenario_set(OutputStage& stage, const Generation& g, const Coverage& coverage,
                        const odd::OddProfile& profile, const OutputInfo& info);

} // namespace railodd::scenario
