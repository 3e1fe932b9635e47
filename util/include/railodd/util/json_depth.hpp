#pragma once
// JSON that nests deeper than any file railodd writes (its deepest, the
// manifest, nests about ten levels) is refused before it is parsed:
// nlohmann::json parses a million '[' without trouble, but copying, comparing
// or dumping that tree recurses once per level and overflows the stack.
#include <filesystem>
#include <string_view>

namespace railodd {

inline constexpr int max_json_depth = 128;

// The deepest nesting of arrays and objects in `text` (strings skipped),
// counting no further than `limit + 1`.
int json_depth(std::string_view text, int limit = max_json_depth);

// Throws InputError(file, "nested deeper than ...") where json_depth exceeds max_json_depth.
void require_json_depth(std::string_view text, const std::filesystem::path& file);

} // namespace railodd
