#include "railodd/util/phase_timer.hpp"

namespace railodd {

void PhaseTimer::start(std::string name) {
    stop();
    current_ = std::move(name);
    started_ = clock::now();
}

void PhaseTimer::stop() {
    if (current_.empty()) {
        return;
    }
    const std::chrono::duration<double> d = clock::now() - started_;
    done_.emplace_back(std::move(current_), d.count());
    current_.clear();
}

} // namespace railodd
