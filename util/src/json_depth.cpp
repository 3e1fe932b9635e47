#include "railodd/util/json_depth.hpp"

#include "railodd/util/errors.hpp"

#include <string>

namespace railodd {

int json_depth(std::string_view text, int limit) {
    int depth = 0, deepest = 0;
    bool in_string = false, escaped = false;
    for (const char c : text) {
        if (in_string) {
            if (escaped) {
                escaped = false;
            } else if (c == '\\') {
                escaped = true;
            } else if (c == '"') {
                in_string = false;
            }
            continue;
        }
        if (c == '"') {
            in_string = true;
        } else if (c == '[' || c == '{') {
            if (++depth > deepest && (deepest = depth) > limit) {
                return deepest; // no need to read the rest of a hostile file
            }
        } else if ((c == ']' || c == '}') && depth > 0) {
            --depth;
        }
    }
    return deepest;
}

void require_json_depth(std::string_view text, const std::filesystem::path& file) {
    if (json_depth(text) > max_json_depth) {
        throw InputError(file.string(), "JSON nested deeper than " + std::to_string(max_json_depth) +
                                            " levels: not a file railodd writes (refused before parsing)");
    }
}

} // namespace railodd
