#pragma once
// All outputs of one command are written into a hidden staging folder inside
// the output directory and renamed into place only when the command succeeds,
// so a failed run leaves no half-written file behind.
#include <filesystem>
#include <functional>
#include <iosfwd>
#include <mutex>
#include <string>
#include <string_view>
#include <vector>

namespace railodd {

class OutputStage {
public:
    explicit OutputStage(std::filesystem::path outdir);
    OutputStage(const OutputStage&) = delete;
    OutputStage& operator=(const OutputStage&) = delete;
    ~OutputStage();

    // Path inside the staging folder where the output `name` is to be written.
    // This and the writers may be called from several threads, one per file.
    std::filesystem::path staged_path(std::string_view name);
    void write_text(std::string_view name, std::string_view content);
    // Streams the output `name` straight into its staged file: large outputs
    // (a national network's profile runs to hundreds of MB) are never held
    // as one string.
    void write_with(std::string_view name, const std::function<void(std::ostream&)>& write);

    // Renames every staged file into the output directory; the final paths.
    std::vector<std::filesystem::path> commit();

    const std::filesystem::path& outdir() const noexcept { return outdir_; }

private:
    std::filesystem::path outdir_;
    std::filesystem::path staging_;
    std::vector<std::string> names_;
    std::mutex names_mutex_;
    bool committed_ = false;
};

} // namespace railodd
