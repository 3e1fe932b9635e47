#pragma once
// yaml-cpp helpers shared by the YAML loaders (taxonomy, ODD spec, catalogs,
// templates); include only from targets that link yaml-cpp. Every refusal is
// an InputError "FILE:LINE: problem", the line taken from the node's Mark.
#include "railodd/util/errors.hpp"
#include "railodd/util/file_names.hpp"
#include "railodd/util/input_file.hpp"

#include <yaml-cpp/yaml.h>

#include <algorithm>
#include <filesystem>
#include <initializer_list>
#include <string>
#include <string_view>

namespace railodd::yaml {

inline int line_of(const YAML::Node& node) {
    return node.Mark().is_null() ? 0 : node.Mark().line + 1;
}

inline std::string where(const std::string& file, const YAML::Node& node) {
    const int line = line_of(node);
    return line > 0 ? file + ":" + std::to_string(line) : file;
}

[[noreturn]] inline void fail(const std::string& file, const YAML::Node& at, const std::string& problem) {
    throw InputError(where(file, at), problem);
}

inline YAML::Node load_file(const std::filesystem::path& path, const std::string& what) {
    const std::string file = path.string();
    const std::string text = read_input_file(path, what);
    try {
        return YAML::Load(text);
    } catch (const YAML::Exception& e) {
        throw InputError(file + ":" + std::to_string(e.mark.line + 1), "invalid YAML in " + what + ": " + e.msg);
    }
}

// Refuses keys of `map` outside `allowed`, naming `context` (e.g. "element 'Scenery'").
inline void check_keys(const std::string& file, const YAML::Node& map, std::initializer_list<std::string_view> allowed,
                       const std::string& context) {
    for (const auto& kv : map) {
        const auto key = kv.first.Scalar();
        if (std::find(allowed.begin(), allowed.end(), key) == allowed.end()) {
            std::string list;
            for (const auto a : allowed) {
                list += (list.empty() ? "" : ", ") + std::string(a);
            }
            fail(file, kv.first, context + ": unknown key '" + key + "' (expected " + list + ")");
        }
    }
}

inline std::string scalar(const std::string& file, const YAML::Node& node, const std::string& what) {
    if (!node.IsScalar()) {
        fail(file, node, what + " must be a single value");
    }
    return node.Scalar();
}

// A scalar that becomes part of a file name (an id): refused unless it is a
// safe name, so that no input can write outside the output folder.
inline std::string name(const std::string& file, const YAML::Node& node, const std::string& what) {
    auto text = scalar(file, node, what);
    if (!is_safe_name(text)) {
        fail(file, node, what + " '" + text + "' cannot be used in a file name: " + safe_name_rule);
    }
    return text;
}

inline double number(const std::string& file, const YAML::Node& node, const std::string& what) {
    const auto text = scalar(file, node, what);
    try {
        std::size_t used = 0;
        const double v = std::stod(text, &used);
        if (used == text.size()) {
            return v;
        }
    } catch (const std::exception&) {
    }
    fail(file, node, what + " must be a number, not '" + text + "'");
}

inline bool boolean(const std::string& file, const YAML::Node& node, const std::string& what) {
    const auto text = scalar(file, node, what);
    if (text == "true" || text == "yes") {
        return true;
    }
    if (text == "false" || text == "no") {
        return false;
    }
    fail(file, node, what + " must be true or false, not '" + text + "'");
}

inline void require(const std::string& file, const YAML::Node& node, bool ok, const std::string& problem) {
    if (!ok) {
        fail(file, node, problem);
    }
}

} // namespace railodd::yaml
