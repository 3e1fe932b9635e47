#pragma once
// JSON files railodd reads back (odd_profile.json, batch summaries, coverage):
// a hand-edited or foreign file with a wrong type or an out-of-range number is
// bad input, not a bug. Include only from targets that link nlohmann_json;
// the project builds with JSON_DIAGNOSTICS, so each message has the JSON path.
#include "railodd/util/errors.hpp"
#include "railodd/util/input_file.hpp"
#include "railodd/util/json_depth.hpp"

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

// The one reader of JSON files railodd reads back: the file must exist, nest
// no deeper than max_json_depth and parse; anything else is InputError(file,
// ...) naming `what` the file should be. `keep` may drop parts while parsing.
template <class Json = nlohmann::ordered_json>
Json read_json_file(const std::filesystem::path& file, const std::string& what,
                    typename Json::parser_callback_t keep = nullptr) {
    const std::string text = read_input_file(file, what);
    require_json_depth(text, file);
    try {
        return Json::parse(text, std::move(keep));
    } catch (const nlohmann::json::exception& e) {
        throw InputError(file.string(), "not valid JSON (" + what + "): " + e.what());
    }
}

} // namespace railodd
