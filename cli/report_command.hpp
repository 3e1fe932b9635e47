#pragma once
// railodd report MAPDIR [--scenarios SCENDIR] [--play PLAY] [--odd-spec SPEC]
//                [--tiles URL] [-o report.html]: one self-contained HTML page of
// a converted route (docs/report.md, "report.html").
// Exit codes: 0 written, 2 unreadable input, 3 output not writable, 1 usage.
#include "command.hpp"

#include <string>

namespace railodd::cli {

struct ReportCommandOptions {
    std::string map_dir;
    std::string scenario_dir;
    std::string play;
    std::string odd_spec;
    std::string taxonomy;
    std::string tiles;
    std::string title;
    std::string output; // default MAPDIR/report.html
};

class ReportCommand : public Command {
public:
    CLI::App* add(CLI::App& parent) override;
    void setup() override;
    int run() override;

private:
    ReportCommandOptions opt_;
};


} // namespace railodd::cli
