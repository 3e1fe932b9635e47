#pragma once
// All outputs of one command are written into a hidden staging folder inside
// the output directory and moved into place only when the command succeeds,
// so a failed run leaves no half-written file behind.
//
// A run that fails before its commit leaves OUTDIR as it found it: a folder
// it had to create is removed again.
//
// A run holds a lock on OUTDIR (flock on the folder) from start to commit: a
// second run into the same folder is refused, and staging folders left by
// killed runs are removed. The commit writes a journal (OUTDIR/.railodd-journal: the staging
// folder, the names to move, the names to remove) before it moves anything; a
// run killed mid-commit is rolled forward by the next run into the folder, so
// the folder never stays a mix of two runs' files.
#include <filesystem>
#include <fstream>
#include <functional>
#include <iosfwd>
#include <mutex>
#include <string>
#include <string_view>
#include <vector>

namespace railodd {

class OutputStage {
public:
    // Throws OutputError when OUTDIR cannot be made or locked (another run).
    explicit OutputStage(std::filesystem::path outdir);
    OutputStage(const OutputStage&) = delete;
    OutputStage& operator=(const OutputStage&) = delete;
    ~OutputStage();

    // Path inside the staging folder where the output `name` is to be written.
    // This and the writers may be called from several threads, one per file.
    // Throws InputError for a name that is not a file inside the folder.
    std::filesystem::path staged_path(std::string_view name);
    // A working file of this run inside the staging folder: never moved into
    // place, gone with the staging folder.
    std::filesystem::path scratch_path(std::string_view name);
    void write_text(std::string_view name, std::string_view content);
    // Streams the output `name` straight into its staged file: large outputs
    // (a national network's profile runs to hundreds of MB) are never held
    // as one string.
    void write_with(std::string_view name, const std::function<void(std::ostream&)>& write);

    // An earlier run's output that this run replaces with nothing: removed by
    // the commit (in the same journal), unless this run writes it again.
    void remove_on_commit(std::string_view name);

    // Moves every staged file into the output directory and removes the
    // stale ones; the final paths.
    std::vector<std::filesystem::path> commit();

    const std::filesystem::path& outdir() const noexcept { return outdir_; }

private:
    // Before the journal: a move that cannot succeed (a file onto a folder) fails the run, not the folder.
    void require_replaceable(const std::vector<std::string>& moves) const;

    std::filesystem::path outdir_;
    std::filesystem::path staging_;
    std::vector<std::string> names_;
    std::vector<std::string> removals_;
    std::mutex names_mutex_;
    int lock_fd_ = -1;
    bool committed_ = false;
    bool created_ = false; // OUTDIR did not exist: removed again, empty, if nothing is committed
};

// One staged output written over several calls (an output fed a batch at a
// time): open from construction to close(), which throws OutputError naming
// the file when a write failed. Not closed, it is never moved into place
// unless the run commits, and then it holds what was written.
class StagedFile {
public:
    StagedFile(OutputStage& stage, std::string_view name);
    std::ostream& stream() { return out_; }
    void close();

private:
    std::filesystem::path path_;
    std::ofstream out_;
};

// For a command that reads `dir` (written by another command): a commit that a
// killed run left half done there is finished first, under the folder's lock,
// so the reader never sees a mix of two runs' files. Nothing to do, and no
// lock taken, where there is no journal. Throws OutputError when the journal
// cannot be carried out or a live run keeps the folder locked.
void finish_pending_commit(const std::filesystem::path& dir);

// The staging folders' prefix inside an output folder.
inline constexpr const char* staging_prefix = ".railodd-staging-";

} // namespace railodd
