#pragma once
// railodd play SCENDIR: plays every scenario of a set in a real OpenSCENARIO
// player (esmini), headless, and checks what it recorded against the set's
// manifest (railodd::scenario::play); play.json, play.txt and the recordings
// (play/ID.csv, play/ID.log) go into SCENDIR. Exit 5 where a scenario fails.
#include "batch_runner.hpp"
#include "command.hpp"

#include "railodd/util/output_stage.hpp"

#include <nlohmann/json.hpp>

#include <filesystem>
#include <string>
#include <vector>

namespace railodd::cli {

struct PlayOptions {
    std::string scendir;
    std::string player;        // esmini; empty: found (RAILODD_ESMINI, PATH, ../shared/tools/esmini/bin)
    unsigned jobs = 0;         // 0: one per hardware thread
    double timestep_s = 0.05;
    double reaction_time_s = 1.0;
    double player_timeout_s = 0.0; // 0: from each scenario's length
    bool plot = false;         // play/ID.svg per scenario
    bool quiet = false;
};

class PlayCommand : public Command {
public:
    CLI::App* add(CLI::App& parent) override;
    void setup() override;
    int run() override;

private:
    // Kept of each run's console output: its head (the player's version,
    // its start) and its tail (how it ended); a player printing without end
    // does not fill the disk.
    static constexpr std::uintmax_t player_log_cap = 1 << 20;

    double timeout_of(const nlohmann::ordered_json& sc) const;
    std::vector<BatchTask> tasks_of(const nlohmann::ordered_json& manifest, const std::filesystem::path& dir,
                                    OutputStage& stage, const std::filesystem::path& scratch) const;
    std::vector<TaskOutcome> play_all(const std::vector<BatchTask>& tasks) const;

    PlayOptions opt_;
    std::string dat2csv_;
};

} // namespace railodd::cli
