#pragma once
// The routes file of `railodd batch` (docs/batch.md): every route's id, input,
// selection and convert options (YAML keys mapped 1:1 onto ConvertOptions),
// optional scenario options, with the top-level `defaults:` merged in and
// relative paths resolved against the file's folder.
#include <nlohmann/json.hpp>

#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

namespace railodd::cli {

struct BatchRoute {
    std::string id;          // folder name under OUTROOT
    std::string input;       // absolute
    int line = 0;            // of the route in the routes file
    // Convert options after defaults, in the order of the key table, as
    // command-line flag and values ("--dem" may carry several).
    std::vector<std::pair<std::string, std::vector<std::string>>> convert;
    bool scenarios = false;
    std::vector<std::pair<std::string, std::vector<std::string>>> scenario_options;
    // Every file the route reads (input, polygon, dem, taxonomy, ...): their
    // fingerprints decide whether outputs are up to date.
    std::vector<std::string> files;
    // The route as resolved: the stamp's `spec`, byte-stable for one file.
    nlohmann::ordered_json spec;
    std::optional<double> timeout_s; // `timeout:` (seconds, 0: none); else --route-timeout
};

struct BatchFile {
    std::filesystem::path path;
    std::vector<BatchRoute> routes; // file order
    std::string content_hash;       // of the routes file, so merge can tell shards of different files apart
};

// Reads and checks ROUTES.yaml; InputError "FILE:LINE: problem" on unknown
// keys, wrong types, duplicate or unusable ids.
BatchFile load_batch_file(const std::filesystem::path& path);

// argv (without the executable) of `railodd convert` / `railodd scenarios` for a route.
std::vector<std::string> convert_args(const BatchRoute& r, const std::filesystem::path& outdir, bool single_thread);
std::vector<std::string> scenarios_args(const BatchRoute& r, const std::filesystem::path& outdir);

// FNV-1a 64 as 16 hex digits: change detection, not security.
std::string fnv1a_hex(std::string_view data, std::uint64_t seed = 14695981039346656037ULL);

} // namespace railodd::cli
