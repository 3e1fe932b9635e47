#pragma once
// Shared by the libFuzzer harnesses: loaders that take a path get the input
// as a file. railodd's own errors (InputError, UsageError, std::invalid_argument
// naming the problem) are the expected outcome for bad input; anything else
// escaping, a crash or a sanitizer report is a finding.
#include "railodd/util/errors.hpp"

#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <stdexcept>
#include <string>
#include <string_view>

#include <unistd.h>

namespace railodd::fuzz {

// One scratch file per process, rewritten for every input.
inline std::filesystem::path scratch(const std::string& name) {
    static const std::filesystem::path dir = [] {
        auto d = std::filesystem::temp_directory_path() / ("railodd-fuzz-" + std::to_string(::getpid()));
        std::filesystem::create_directories(d);
        return d;
    }();
    return dir / name;
}

inline std::filesystem::path as_file(const std::string& name, const std::uint8_t* data, std::size_t size) {
    const auto p = scratch(name);
    std::ofstream(p, std::ios::binary | std::ios::trunc).write(reinterpret_cast<const char*>(data),
                                                                static_cast<std::streamsize>(size));
    return p;
}

// Runs a whole command: only the errors main() maps to a documented exit
// code (usage, input) are fine; std::invalid_argument escaping a command is an
// internal error there, so it is a finding here.
template <class F>
void expect_exit_code(F&& f) {
    try {
        f();
    } catch (const railodd::InputError&) {
    } catch (const railodd::UsageError&) {
    }
}

// Runs a loader: besides those, std::invalid_argument naming the problem is
// its documented error.
template <class F>
void expect_clean(F&& f) {
    expect_exit_code([&] {
        try {
            f();
        } catch (const std::invalid_argument&) {
        }
    });
}

} // namespace railodd::fuzz
