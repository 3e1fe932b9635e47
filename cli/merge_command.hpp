#pragma once
// railodd merge OUTROOT [-o MERGED.json]: one summary over the shards of a
// batch (every batch_summary*.json under OUTROOT), with the routes' scenario
// coverage and ODD profile summaries merged network-wide (docs/batch.md).
// Exit codes: 0 written, 1 usage, 2 unreadable or mismatched input, 3 output.
#include "command.hpp"

#include <string>

namespace railodd::cli {

struct MergeOptions {
    std::string outroot;
    std::string output; // empty: OUTROOT/batch_merged.json
};

class MergeCommand : public Command {
public:
    CLI::App* add(CLI::App& parent) override;
    void setup() override;
    int run() override;

private:
    MergeOptions opt_;
};

} // namespace railodd::cli
