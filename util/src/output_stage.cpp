#include "railodd/util/output_stage.hpp"

#include "railodd/util/errors.hpp"

#include <algorithm>
#include <cstdio>
#include <fstream>
#include <optional>
#include <sstream>
#include <system_error>

#include <fcntl.h>
#include <sys/file.h>
#include <unistd.h>

namespace railodd {

namespace fs = std::filesystem;

namespace {

constexpr const char* journal_name = ".railodd-journal";

// A name as a path relative to the folder, or throws: no input-derived name
// (a template id, ...) may place a file elsewhere.
fs::path inside(const fs::path& dir, const std::string& n) {
    const fs::path rel = fs::path{n}.lexically_normal();
    if (n.empty() || rel.has_root_path() || rel.empty() || *rel.begin() == ".." || *rel.begin() == "." ||
        rel.filename().empty()) {
        throw InputError((dir / n).string(), "output name '" + n + "' is not a file inside the output folder");
    }
    return rel;
}

void move_into_place(const fs::path& from, const fs::path& to) {
    std::error_code ec;
    fs::create_directories(to.parent_path(), ec);
    fs::rename(from, to, ec);
    if (ec) {
        throw OutputError(to.string(), "cannot move output into place: " + ec.message());
    }
}

// Journal: the staging folder's name, then "+ name" per move, "- name" per removal.
void write_journal(const fs::path& outdir, const std::string& staging, const std::vector<std::string>& moves,
                   const std::vector<std::string>& removals) {
    const fs::path tmp = outdir / (std::string{journal_name} + ".tmp");
    {
        std::ofstream out(tmp, std::ios::binary | std::ios::trunc);
        out << staging << '\n';
        for (const auto& m : moves) {
            out << "+ " << m << '\n';
        }
        for (const auto& r : removals) {
            out << "- " << r << '\n';
        }
        out.close();
        if (!out) {
            throw OutputError(tmp.string(), "cannot write the commit journal");
        }
    }
    // The journal must be on disk before the first rename it describes.
    if (const int fd = ::open(tmp.c_str(), O_RDONLY); fd >= 0) {
        ::fsync(fd);
        ::close(fd);
    }
    std::error_code ec;
    fs::rename(tmp, outdir / journal_name, ec);
    if (ec) {
        throw OutputError((outdir / journal_name).string(), "cannot write the commit journal: " + ec.message());
    }
}

// Carries out a journal's moves and removals (those not yet done), then drops it.
void roll_forward(const fs::path& outdir) {
    const fs::path journal = outdir / journal_name;
    std::ifstream in(journal, std::ios::binary);
    std::string staging;
    if (!std::getline(in, staging) || staging.rfind(staging_prefix, 0) != 0 ||
        staging.find('/') != std::string::npos) {
        throw OutputError(journal.string(), "not a railodd commit journal: remove it by hand after checking the folder");
    }
    for (std::string line; std::getline(in, line);) {
        if (line.size() < 3 || (line[0] != '+' && line[0] != '-') || line[1] != ' ') {
            continue;
        }
        const fs::path rel = inside(outdir, line.substr(2));
        std::error_code ec;
        if (line[0] == '+' && fs::exists(outdir / staging / rel, ec)) {
            move_into_place(outdir / staging / rel, outdir / rel);
        } else if (line[0] == '-') {
            fs::remove(outdir / rel, ec);
        }
    }
    in.close();
    std::error_code ec;
    fs::remove(journal, ec);
}

// Staging folders of runs that were killed: nobody else holds the lock, so
// none of them is live.
void remove_stale_staging(const fs::path& outdir) {
    std::error_code ec;
    std::vector<fs::path> stale;
    for (fs::directory_iterator it(outdir, ec), end; !ec && it != end; it.increment(ec)) {
        if (it->path().filename().string().rfind(staging_prefix, 0) == 0) {
            stale.push_back(it->path());
        }
    }
    for (const auto& p : stale) {
        fs::remove_all(p, ec);
    }
}

} // namespace

void finish_pending_commit(const fs::path& dir) {
    std::error_code ec;
    if (!fs::exists(dir / journal_name, ec)) {
        return;
    }
    const int fd = ::open(dir.c_str(), O_RDONLY | O_DIRECTORY | O_CLOEXEC);
    if (fd < 0) {
        throw OutputError(dir.string(), "cannot open the folder to finish its pending commit");
    }
    // A live run holding the lock with a journal there is in its commit,
    // which takes moments (renames): wait up to 10 s for it.
    int tries = 0;
    while (::flock(fd, LOCK_EX | LOCK_NB) != 0 && ++tries < 100) {
        ::usleep(100000);
    }
    if (tries == 100) {
        ::close(fd);
        throw OutputError(dir.string(), "another railodd run keeps this folder locked in its commit; try again");
    }
    try {
        if (fs::exists(dir / journal_name, ec)) {
            roll_forward(dir);
            remove_stale_staging(dir); // the lock is ours: no live run stages there
        }
    } catch (...) {
        ::close(fd);
        throw;
    }
    ::close(fd); // releases the flock
}

OutputStage::OutputStage(fs::path outdir) : outdir_(std::move(outdir)) {
    if (outdir_.empty()) {
        throw OutputError("''", "the output folder name is empty");
    }
    std::error_code ec;
    created_ = !fs::exists(outdir_, ec);
    fs::create_directories(outdir_, ec);
    if (ec || !fs::is_directory(outdir_)) {
        throw OutputError(outdir_.string(), "cannot create output directory" + (ec ? ": " + ec.message() : ""));
    }
    // The folder itself is locked (flock on its descriptor): no lock file to
    // leave behind, and the kernel drops the lock when a run dies.
    lock_fd_ = ::open(outdir_.c_str(), O_RDONLY | O_DIRECTORY | O_CLOEXEC);
    if (lock_fd_ < 0) {
        throw OutputError(outdir_.string(), "cannot open the output directory");
    }
    if (::flock(lock_fd_, LOCK_EX | LOCK_NB) != 0) {
        ::close(lock_fd_);
        lock_fd_ = -1;
        throw OutputError(outdir_.string(),
                          "another railodd run is writing into this folder; wait for it or choose another folder");
    }
    if (fs::exists(outdir_ / journal_name, ec)) {
        roll_forward(outdir_); // a run killed in its commit: finish it first
    }
    remove_stale_staging(outdir_);
    staging_ = outdir_ / (staging_prefix + std::to_string(::getpid()));
    fs::create_directory(staging_, ec);
    if (ec) {
        throw OutputError(staging_.string(), "cannot create staging directory: " + ec.message());
    }
}

OutputStage::~OutputStage() {
    std::error_code ec;
    if (!committed_ || !fs::exists(outdir_ / journal_name, ec)) {
        fs::remove_all(staging_, ec); // best effort: never throw from a destructor
    }
    if (lock_fd_ >= 0) {
        ::close(lock_fd_); // releases the flock
    }
    if (!committed_ && created_) {
        fs::remove(outdir_, ec); // the folder this run made, empty again: a failed run leaves nothing
    }
}

fs::path OutputStage::staged_path(std::string_view name) {
    std::string n{name};
    const fs::path rel = inside(outdir_, n);
    {
        const std::lock_guard<std::mutex> lock(names_mutex_);
        if (std::find(names_.begin(), names_.end(), n) == names_.end()) {
            names_.push_back(n);
        }
    }
    // Names may hold folders ("catalogs/VehicleCatalog.xosc").
    std::error_code ec;
    fs::create_directories((staging_ / rel).parent_path(), ec);
    if (ec) {
        throw OutputError((staging_ / rel).string(), "cannot create directory: " + ec.message());
    }
    return staging_ / rel;
}

void OutputStage::write_text(std::string_view name, std::string_view content) {
    write_with(name, [&](std::ostream& out) { out.write(content.data(), static_cast<std::streamsize>(content.size())); });
}

fs::path OutputStage::scratch_path(std::string_view name) {
    const fs::path dir = staging_ / ".scratch";
    std::error_code ec;
    fs::create_directories(dir, ec);
    if (ec) {
        throw OutputError(dir.string(), "cannot create directory: " + ec.message());
    }
    return dir / fs::path(std::string{name}).filename();
}

void OutputStage::write_with(std::string_view name, const std::function<void(std::ostream&)>& write) {
    StagedFile file(*this, name);
    write(file.stream());
    file.close();
}

StagedFile::StagedFile(OutputStage& stage, std::string_view name)
    : path_(stage.staged_path(name)), out_(path_, std::ios::binary) {
    if (!out_) {
        throw OutputError(path_.string(), "cannot open for writing");
    }
}

void StagedFile::close() {
    out_.close();
    if (!out_) {
        throw OutputError(path_.string(), "write failed");
    }
}

void OutputStage::remove_on_commit(std::string_view name) {
    const std::string n{name};
    inside(outdir_, n);
    const std::lock_guard<std::mutex> lock(names_mutex_);
    removals_.push_back(n);
}

std::vector<fs::path> OutputStage::commit() {
    // By name, not by when each writer started: outputs written on several
    // threads are listed in the same order on every run.
    std::vector<std::string> moves;
    for (const auto& name : names_) {
        std::error_code ec;
        if (fs::exists(staging_ / name, ec)) {
            moves.push_back(name); // else reserved but never written
        }
    }
    std::sort(moves.begin(), moves.end());
    std::vector<std::string> removals;
    for (const auto& r : removals_) {
        if (!std::binary_search(moves.begin(), moves.end(), r)) {
            removals.push_back(r);
        }
    }
    std::sort(removals.begin(), removals.end());
    removals.erase(std::unique(removals.begin(), removals.end()), removals.end());
    require_replaceable(moves);
    write_journal(outdir_, staging_.filename().string(), moves, removals);
    committed_ = true;
    std::vector<fs::path> written;
    std::optional<OutputError> failed; // the first move that failed: the rest are still made
    for (const auto& name : moves) {
        try {
            move_into_place(staging_ / name, outdir_ / name);
            written.push_back(outdir_ / name);
        } catch (const OutputError& e) {
            failed = failed ? failed : e;
        }
    }
    std::error_code ec;
    for (const auto& r : removals) {
        fs::remove(outdir_ / r, ec);
    }
    // Even after a failed move: a journal left behind would make every later
    // run into this folder retry the same move and fail the same way.
    fs::remove(outdir_ / journal_name, ec);
    fs::remove_all(staging_, ec);
    if (failed) {
        throw *failed;
    }
    return written;
}

void OutputStage::require_replaceable(const std::vector<std::string>& moves) const {
    for (const auto& name : moves) {
        std::error_code ec;
        if (fs::is_directory(outdir_ / name, ec) && !fs::is_directory(staging_ / name, ec)) {
            throw OutputError((outdir_ / name).string(), "is a folder: the file this run wrote cannot replace it");
        }
    }
}

} // namespace railodd
