// SUMO's netconvert as a second consumer: a file that our checks accept but a
// widely used importer rejects, or imports without its tracks, is still broken.
#include "process.hpp"

#include "railodd/util/errors.hpp"
#include "railodd/xodr_check/check.hpp"

#include <pugixml.hpp>
#include <unistd.h>

#include <atomic>
#include <cstdlib>
#include <string>

namespace railodd::xodr_check {

namespace fs = std::filesystem;

namespace {

constexpr std::size_t kept_lines = 20;

// A private scratch folder removed on every way out.
class ScratchDir {
public:
    ScratchDir() {
        static std::atomic<int> counter{0};
        path_ = fs::temp_directory_path() /
                ("railodd-validate-" + std::to_string(::getpid()) + "-" + std::to_string(counter++));
        fs::remove_all(path_);
        fs::create_directories(path_);
    }
    ~ScratchDir() {
        std::error_code ec;
        fs::remove_all(path_, ec);
    }
    ScratchDir(const ScratchDir&) = delete;
    ScratchDir& operator=(const ScratchDir&) = delete;
    const fs::path& path() const { return path_; }

private:
    fs::path path_;
};

bool allows_rail(const pugi::xml_node& edge) {
    for (const auto lane : edge.children("lane")) {
        const std::string allow = lane.attribute("allow").value();
        if (allow.find("rail") != std::string::npos || allow.find("tram") != std::string::npos) {
            return true;
        }
    }
    return false;
}

void count_edges(NetconvertResult& r, const fs::path& net) {
    pugi::xml_document doc;
    if (!doc.load_file(net.c_str())) {
        r.errors.push_back("Error: netconvert wrote no readable net (" + net.string() + ")");
        return;
    }
    for (const auto edge : doc.child("net").children("edge")) {
        if (std::string{edge.attribute("function").value()} == "internal") {
            continue;
        }
        ++r.edges;
        if (allows_rail(edge)) {
            ++r.rail_edges;
        }
    }
}

} // namespace

NetconvertResult run_netconvert(const fs::path& file) {
    if (!find_program("netconvert")) {
        throw UsageError("--netconvert", "netconvert is not on PATH (apt-get install sumo)");
    }
    if (!std::getenv("SUMO_HOME")) {
        ::setenv("SUMO_HOME", "/usr/share/sumo", 0); // netconvert looks up its type maps there
    }
    NetconvertResult r;
    const ScratchDir scratch;
    const fs::path net = scratch.path() / "validate.net.xml";
    const ProcessOutput out = run_process({"netconvert", "--opendrive-files", file.string(), "-o", net.string()});
    r.ran = true;
    r.exit_code = out.exit_code;
    for (const auto& line : out.lines) {
        if (line.rfind("Error", 0) == 0 && r.errors.size() < kept_lines) {
            r.errors.push_back(line);
        }
    }
    if (out.exit_code != 0 && r.errors.empty()) {
        r.errors.push_back("Error: netconvert exited with code " + std::to_string(out.exit_code) +
                           (out.lines.empty() ? std::string{} : ": " + out.lines.back()));
    }
    if (out.exit_code == 0) {
        count_edges(r, net);
    }
    return r;
}

} // namespace railodd::xodr_check
