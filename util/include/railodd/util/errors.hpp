#pragma once
// Exception types of railodd. Each carries the file (or object) it is about and
// the problem; main() catches them once and maps each kind to an exit code.
#include <stdexcept>
#include <string>

namespace railodd {

class Error : public std::runtime_error {
public:
    Error(const std::string& where, const std::string& problem)
        : std::runtime_error(where.empty() ? problem : where + ": " + problem),
          where_(where), problem_(problem) {}
    const std::string& where() const noexcept { return where_; }
    const std::string& problem() const noexcept { return problem_; }

private:
    std::string where_;
    std::string problem_;
};

// The input (a file, or an option's value) is unreadable or malformed.
class InputError : public Error {
    using Error::Error;
};

// An output could not be written.
class OutputError : public Error {
    using Error::Error;
};

// Options that contradict each other or name nothing usable.
class UsageError : public Error {
    using Error::Error;
};

// SIGINT or SIGTERM arrived while railodd waited for its child processes:
// they are killed, and main() exits 128 + signal after the unwinding has
// removed what the run had staged.
class Interrupted : public Error {
public:
    explicit Interrupted(int signal)
        : Error("", "interrupted by signal " + std::to_string(signal)), signal_(signal) {}
    int signal() const noexcept { return signal_; }

private:
    int signal_;
};

enum ExitCode : int {
    exit_ok = 0,
    exit_usage = 1,
    exit_input = 2,
    exit_output = 3,
    exit_internal = 4,
    exit_invalid = 5, // `railodd validate`: the checked file fails a check
};

} // namespace railodd
