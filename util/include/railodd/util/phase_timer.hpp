#pragma once
// Wall-clock time per named phase, in the order the phases ran, for report.json.
#include <chrono>
#include <string>
#include <utility>
#include <vector>

namespace railodd {

class PhaseTimer {
public:
    // Ends the running phase (if any) and starts `name`.
    void start(std::string name);
    // Ends the running phase.
    void stop();
    const std::vector<std::pair<std::string, double>>& seconds() const noexcept { return done_; }

private:
    using clock = std::chrono::steady_clock;
    std::string current_;
    clock::time_point started_{};
    std::vector<std::pair<std::string, double>> done_;
};

} // namespace railodd
