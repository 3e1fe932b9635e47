// popen with every argument single-quoted: file names with spaces or quotes
// reach the validators intact, and nothing is interpreted by the shell.
#include "process.hpp"

#include <sys/wait.h>
#include <unistd.h>

#include <array>
#include <cstdio>
#include <cstdlib>
#include <sstream>

namespace railodd::xodr_check {

namespace {

std::string shell_quote(const std::string& s) {
    std::string q = "'";
    for (const char c : s) {
        if (c == '\'') {
            q += "'\\''";
        } else {
            q += c;
        }
    }
    return q + "'";
}

} // namespace

ProcessOutput run_process(const std::vector<std::string>& argv) {
    ProcessOutput out;
    std::string command;
    for (const auto& a : argv) {
        command += shell_quote(a) + " ";
    }
    command += "2>&1 </dev/null";
    FILE* pipe = ::popen(command.c_str(), "r");
    if (!pipe) {
        return out;
    }
    std::array<char, 4096> buf{};
    std::string line;
    while (std::fgets(buf.data(), static_cast<int>(buf.size()), pipe)) {
        line += buf.data();
        if (!line.empty() && line.back() == '\n') {
            line.pop_back();
            out.lines.push_back(std::move(line));
            line.clear();
        }
    }
    if (!line.empty()) {
        out.lines.push_back(std::move(line));
    }
    const int status = ::pclose(pipe);
    out.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
    return out;
}

std::optional<std::filesystem::path> find_program(const std::string& name) {
    if (name.find('/') != std::string::npos) {
        return ::access(name.c_str(), X_OK) == 0 ? std::optional{std::filesystem::path{name}} : std::nullopt;
    }
    const char* path = std::getenv("PATH");
    std::istringstream dirs(path ? path : "/usr/bin:/bin");
    std::string dir;
    while (std::getline(dirs, dir, ':')) {
        const std::filesystem::path candidate = std::filesystem::path{dir.empty() ? "." : dir} / name;
        if (::access(candidate.c_str(), X_OK) == 0) {
            return candidate;
        }
    }
    return std::nullopt;
}

} // namespace railodd::xodr_check
