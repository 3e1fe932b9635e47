#pragma once
// What `railodd play` makes of each run: the scenario's record in play.json
// (ran or not, the checks on its recording, the criticality), play.txt, and
// the play outcome added to the set's manifest and coverage.
#include "batch_runner.hpp"
#include "play_targets.hpp"

#include "railodd/scenario/play.hpp"
#include "railodd/util/output_stage.hpp"

#include <nlohmann/json.hpp>

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

namespace railodd::cli {

struct Played {
    nlohmann::ordered_json entry;
    bool passed = false;
    bool can_stop = false;
    std::string svg; // with --plot
};

// One scenario's record. A recording that cannot be read (empty, missing,
// malformed) fails this scenario only: the others' results stand.
// `csv_name`: the recording as named in the set (play/ID.csv).
Played analyse_one(const nlohmann::ordered_json& sc, const TaskOutcome& outcome, const std::filesystem::path& csv,
                   const std::string& csv_name, const std::filesystem::path& log,
                   const scenario::play::Options& o, const std::vector<scenario::play::LaneLine>* lanes,
                   const TargetPlaces& places);

std::string text_report(const nlohmann::ordered_json& report);

// The manifest gains each scenario's play outcome and criticality, and
// coverage.json (where the set has one) the criticality classes.
void record_criticality(OutputStage& stage, nlohmann::ordered_json manifest,
                        std::optional<nlohmann::ordered_json> coverage, const nlohmann::ordered_json& report);

} // namespace railodd::cli
