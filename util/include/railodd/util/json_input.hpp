#pragma once
// JSON files railodd reads back (odd_profile.json, batch summaries, coverage):
// a hand-edited or foreign file with a wrong type or an out-of-range number is
// bad input, not a bug. Include only from targets that link nlohmann_json;
// the project builds with JSON_DIAGNOSTICS, so each message has the JSON path.
#include "railodd/util/errors.hpp"

#include <nlohmann/json.hpp>

#include <filesystem>
#include <string>
#include <utility>

namespace railodd {

// Runs `read` (which takes JSON parsed from `file` apart) and turns
// nlohmann's type, range and parse errors into InputError(file, ...).
template <class Read>
decltype(auto) reading_json(const std::filesystem::path& file, Read&& read) {
    try {
        return std::forward<Read>(read)();
    } catch (const nlohmann::json::exception& e) {
        throw InputError(file.string(), std::string{"unexpected JSON content: "} + e.what());
    }
}

} // namespace railodd
