#pragma once
// railodd play SCENDIR: plays every scenario of a set in a real OpenSCENARIO
// player (esmini), headless, and checks what it recorded against the set's
// manifest (railodd::scenario::play); play.json, play.txt and the recordings
// (play/ID.csv, play/ID.log) go into SCENDIR. Exit 5 where a scenario fails.
#include "command.hpp"

#include <string>

namespace railodd::cli {

struct PlayOptions {
    std::string scendir;
    std::string player;        // esmini; empty: found (RAILODD_ESMINI, PATH, ../shared/tools/esmini/bin)
    unsigned jobs = 0;         // 0: one per hardware thread
    double timestep_s = 0.05;
    double reaction_time_s = 1.0;
    bool plot = false;         // play/ID.svg per scenario
    bool quiet = false;
};

class PlayCommand : public Command {
public:
    CLI::App* add(CLI::App& parent) override;
    void setup() override;
    int run() override;

private:
    PlayOptions opt_;
    std::string dat2csv_;
};

} // namespace railodd::cli
