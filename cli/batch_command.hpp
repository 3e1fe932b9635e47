#pragma once
// railodd batch ROUTES.yaml -o OUTROOT: convert (and optionally generate
// scenarios for) many routes in parallel child processes, skip the ones that
// are up to date, and write a per-route summary (docs/batch.md).
// Exit codes: 0 every route ok or skipped; else the largest exit code of the
// failed routes (2 input, 3 output, 4 internal or killed); 1 usage, 2 invalid
// routes file, 3 OUTROOT not writable.
#include "command.hpp"

#include <string>

namespace railodd::cli {

// The largest N of --shard I/N. A shard is one job of a scheduler's array,
// and schedulers cap arrays near this (Slurm's MaxArraySize defaults to
// 1001, sites raise it to some 10,000s); 10,000 shards already give each a
// handful of routes of a national network. Above it, N is a typo, and
// merge's list of missing shards would only grow.
inline constexpr unsigned max_shards = 10000;

struct BatchOptions {
    std::string routes_file;
    std::string outroot;
    unsigned jobs = 0;          // 0: hardware threads
    std::string shard = "0/1";  // I/N, 0-based: matches SLURM_ARRAY_TASK_ID and JOB_COMPLETION_INDEX
    bool force = false;
    double route_timeout_s = 6 * 3600.0; // a route still running after this is killed and fails (0: no limit)
};

class BatchCommand : public Command {
public:
    CLI::App* add(CLI::App& parent) override;
    void setup() override;
    int run() override;

private:
    BatchOptions opt_;
    unsigned shard_index_ = 0;
    unsigned shard_count_ = 1;
};

} // namespace railodd::cli
