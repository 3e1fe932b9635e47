#pragma once
// Helpers shared by the tests: scratch folders, the shared real data, and
// running the railodd executable.
#include <gtest/gtest.h>

#include <array>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include <unistd.h> // getpid

namespace railodd::test {

namespace fs = std::filesystem;

// A fresh folder per test, named after it and the process: two builds'
// test runs at once (a release and a sanitizer build) must not share one.
inline fs::path scratch_dir() {
    const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
    fs::path dir = fs::temp_directory_path() / "railodd-tests" /
                   (std::string{info->test_suite_name()} + "." + info->name() + "-" + std::to_string(::getpid()));
    fs::remove_all(dir);
    fs::create_directories(dir);
    return dir;
}

inline fs::path write_file(const fs::path& path, const std::string& content) {
    std::ofstream out(path, std::ios::binary);
    out << content;
    return path;
}

inline std::string read_file(const fs::path& path) {
    std::ifstream in(path, std::ios::binary);
    std::ostringstream s;
    s << in.rdbuf();
    return s.str();
}

// ../shared/data beside the repository (or $RAILODD_SHARED_DATA), empty if absent.
inline fs::path shared_data() {
    if (const char* env = std::getenv("RAILODD_SHARED_DATA")) {
        return fs::is_directory(env) ? fs::path{env} : fs::path{};
    }
    const fs::path p{RAILODD_SHARED_DATA};
    return fs::is_directory(p) ? p : fs::path{};
}

#define RAILODD_REQUIRE_SHARED_DATA()                                                                  \
    if (::railodd::test::shared_data().empty()) {                                                     \
        GTEST_SKIP() << "../shared/data is absent (set RAILODD_SHARED_DATA): skipping real-data test"; \
    }

struct CommandResult {
    int exit_code = -1;
    std::string output; // stdout and stderr
};

inline CommandResult run_command(const std::string& command) {
    CommandResult r;
    FILE* pipe = ::popen((command + " 2>&1").c_str(), "r");
    if (!pipe) {
        return r;
    }
    std::array<char, 4096> buf{};
    while (std::fgets(buf.data(), buf.size(), pipe)) {
        r.output += buf.data();
    }
    const int status = ::pclose(pipe);
    r.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
    return r;
}

inline std::string quoted(const fs::path& p) {
    std::string q;
    q.reserve(p.native().size() + 2);
    q += '\'';
    q += p.native();
    q += '\'';
    return q;
}

} // namespace railodd::test
