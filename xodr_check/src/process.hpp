#pragma once
// Running the external validators (xmllint, python3 xmlschema, netconvert):
// a command line built from quoted arguments, stdout and stderr read together.
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

namespace railodd::xodr_check {

struct ProcessOutput {
    int exit_code = -1;
    std::vector<std::string> lines; // stdout and stderr, in the order written
};

// Runs argv (argv[0] looked up on PATH by the shell); never throws for a
// non-zero exit, which is the caller's to read.
ProcessOutput run_process(const std::vector<std::string>& argv);

// The program's path if it is an executable on PATH (or an absolute path).
std::optional<std::filesystem::path> find_program(const std::string& name);

} // namespace railodd::xodr_check
