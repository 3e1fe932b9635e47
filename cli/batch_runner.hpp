#pragma once
// Runs the routes of `railodd batch` as child processes of the same
// executable, N at a time: each route's memory and failure stay its own, and
// wait4() gives its peak RSS. A route is a sequence of steps (convert, then
// scenarios) whose output goes to a log file in the route's folder.
#include <chrono>
#include <cstdint>
#include <cstddef>
#include <filesystem>
#include <functional>
#include <string>
#include <vector>

namespace railodd::cli {

struct BatchStep {
    std::string name;               // shown as the route's phase
    std::vector<std::string> args;  // argv after the executable
    std::filesystem::path log;      // stdout and stderr of the step (absolute)
    std::filesystem::path cwd;      // the step runs there (absolute)
    std::string program;            // executable (absolute); empty: railodd itself
    std::uintmax_t log_cap = 0;     // bytes of the log kept, head and tail (0: all)
};

struct BatchTask {
    std::string id;
    std::vector<BatchStep> steps;   // the next starts only when the previous exited 0
    double timeout_s = 0.0;         // killed when still running after this (0: no limit)
    std::string timeout_option = "--route-timeout or the route's timeout"; // named where it times out
};

struct TaskOutcome {
    bool ok = false;
    int exit_code = 0;              // of the failed step; 128+signal when killed
    double seconds = 0.0;
    long peak_rss_kb = 0;           // largest over the steps
    std::string failed_step;
    std::string error;              // the step's last "railodd: ..." line
};

// The status display: finished routes as log lines ("[3/10] ok lauf 2.8 s");
// on a terminal also one line, redrawn in place, with the running routes,
// their phase and an ETA.
class BatchProgress {
public:
    BatchProgress(std::size_t total, unsigned jobs, bool terminal, std::string noun = "routes");
    void finished(const std::string& id, const std::string& status, double seconds, const std::string& detail);
    void running(const std::vector<std::pair<std::string, std::string>>& id_phase);
    void close();

private:
    void clear_line();
    std::size_t total_;
    std::size_t done_ = 0;
    std::size_t ran_ = 0;   // finished routes that ran (not skipped): the ETA's sample
    double ran_seconds_ = 0.0;
    std::chrono::steady_clock::time_point last_finish_ = std::chrono::steady_clock::now();
    unsigned jobs_;
    bool terminal_;
    std::string noun_;
    bool line_shown_ = false;
};

// Runs every task, at most `jobs` at once; on_done is called in the order the
// tasks finish (index into `tasks`). Each step runs in a process group of its
// own: a task still running its timeout_s after it started is killed with
// everything it started (SIGKILL to the group) and fails with "timed out";
// the others go on. SIGINT or SIGTERM to railodd meanwhile kills every
// running group and throws Interrupted, so that the caller's temporary and
// staging folders are removed as the stack unwinds.
void run_tasks(const std::vector<BatchTask>& tasks, unsigned jobs, BatchProgress& progress,
               const std::function<void(std::size_t, const TaskOutcome&)>& on_done);

} // namespace railodd::cli
