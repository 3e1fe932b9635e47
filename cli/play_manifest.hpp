#pragma once
// The scenario set as `railodd play` reads it back: manifest.json (and
// coverage.json, which play extends), checked whole before anything is
// played: JSON that is too deep, fields of the wrong type, scenario ids that
// are not file names or repeat, and scenario files outside the set are bad
// input (exit 2) naming the file, not failures met after minutes of playing.
#include <nlohmann/json.hpp>

#include <filesystem>
#include <optional>

namespace railodd::cli {

struct PlaySet {
    nlohmann::ordered_json manifest;
    std::optional<nlohmann::ordered_json> coverage; // absent where the set has none
};

// Throws InputError naming manifest.json or coverage.json and the problem.
PlaySet read_play_set(const std::filesystem::path& dir);

// The scenario's OpenSCENARIO file, inside `dir` (read_play_set checked it).
std::filesystem::path scenario_file(const std::filesystem::path& dir, const nlohmann::ordered_json& entry);

} // namespace railodd::cli
