#pragma once
// The types of the fields railodd reads from its own JSON files (manifest,
// play results, coverage, convert report), checked before the file is used:
// a hand-edited `"s": "12"` is refused as bad input naming the file, the JSON
// path and the value, not met later as nlohmann's type_error (exit 4) after
// minutes of work.
#include <nlohmann/json.hpp>

#include <filesystem>
#include <string>
#include <vector>

namespace railodd {

enum class JsonKind { string, number, integer, boolean, array, object };

// `path`: keys joined by '/', "*" for every element of an array
// ("scenarios/*/anchor/s"). A field is checked only where its parent is
// there; `required` says whether it may be missing from a present parent.
struct JsonField {
    std::string path;
    JsonKind kind;
    bool required = true;
};

// Throws InputError(file, "/scenarios/3/anchor/s: expected a number, found
// string \"12\"") for the first field of `root` that is missing or of
// another kind.
void require_shape(const nlohmann::ordered_json& root, const std::vector<JsonField>& fields,
                   const std::filesystem::path& file);

} // namespace railodd
