#include "railodd/util/output_stage.hpp"

#include "railodd/util/errors.hpp"

#include <algorithm>
#include <fstream>
#include <system_error>
#include <unistd.h>

namespace railodd {

namespace fs = std::filesystem;

OutputStage::OutputStage(fs::path outdir) : outdir_(std::move(outdir)) {
    std::error_code ec;
    fs::create_directories(outdir_, ec);
    if (ec) {
        throw OutputError(outdir_.string(), "cannot create output directory: " + ec.message());
    }
    staging_ = outdir_ / (".railodd-staging-" + std::to_string(::getpid()));
    fs::remove_all(staging_, ec);
    fs::create_directory(staging_, ec);
    if (ec) {
        throw OutputError(staging_.string(), "cannot create staging directory: " + ec.message());
    }
}

OutputStage::~OutputStage() {
    std::error_code ec;
    fs::remove_all(staging_, ec); // best effort: never throw from a destructor
}

fs::path OutputStage::staged_path(std::string_view name) {
    std::string n{name};
    // Names come from inputs (template ids, ...): whatever their loaders
    // checked, nothing is written outside the output folder.
    const fs::path rel = fs::path{n}.lexically_normal();
    if (n.empty() || rel.has_root_path() || rel.empty() || *rel.begin() == ".." || *rel.begin() == "." ||
        rel.filename().empty()) {
        throw InputError((outdir_ / n).string(), "output name '" + n + "' is not a file inside the output folder");
    }
    {
        const std::lock_guard<std::mutex> lock(names_mutex_);
        if (std::find(names_.begin(), names_.end(), n) == names_.end()) {
            names_.push_back(n);
        }
    }
    // Names may hold folders ("catalogs/VehicleCatalog.xosc").
    std::error_code ec;
    fs::create_directories((staging_ / n).parent_path(), ec);
    if (ec) {
        throw OutputError((staging_ / n).string(), "cannot create directory: " + ec.message());
    }
    return staging_ / n;
}

void OutputStage::write_text(std::string_view name, std::string_view content) {
    write_with(name, [&](std::ostream& out) { out.write(content.data(), static_cast<std::streamsize>(content.size())); });
}

void OutputStage::write_with(std::string_view name, const std::function<void(std::ostream&)>& write) {
    const fs::path path = staged_path(name);
    std::ofstream out(path, std::ios::binary);
    if (!out) {
        throw OutputError(path.string(), "cannot open for writing");
    }
    write(out);
    out.close();
    if (!out) {
        throw OutputError(path.string(), "write failed");
    }
}

std::vector<fs::path> OutputStage::commit() {
    std::vector<fs::path> written;
    // By name, not by when each writer started: outputs written on several
    // threads are listed in the same order on every run.
    std::vector<std::string> names = names_;
    std::sort(names.begin(), names.end());
    for (const auto& name : names) {
        const fs::path from = staging_ / name;
        if (!fs::exists(from)) {
            continue; // reserved but never written
        }
        const fs::path to = outdir_ / name;
        std::error_code ec;
        fs::create_directories(to.parent_path(), ec);
        fs::rename(from, to, ec);
        if (ec) {
            throw OutputError(to.string(), "cannot move output into place: " + ec.message());
        }
        written.push_back(to);
    }
    committed_ = true;
    return written;
}

} // namespace railodd
