#pragma once
// yaml-cpp helpers shared by the YAML loaders (taxonomy, ODD spec, catalogs,
// templates); include only from targets that link yaml-cpp. Every refusal is
// an InputError "FILE:LINE: problem", the line taken from the node's Mark.
#include "railodd/util/errors.hpp"
#include "railodd/util/file_names.hpp"
#include "railodd/util/input_file.hpp"
#include "railodd/util/xml_text.hpp"

#include <yaml-cpp/yaml.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <initializer_list>
#include <string>
#include <string_view>
#include <vector>

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

// Nodes a loaded file may hold, aliases counted at each use: a few lines of
// nested aliases ("billion laughs") would otherwise expand past any memory.
inline constexpr std::size_t max_nodes = 1000000;

// yaml-cpp keeps both entries of a duplicated key and node["key"] finds the
// first: the later value would be silently ignored. Refused instead.
inline void check_keys_unique(const std::string& file, const YAML::Node& node, std::size_t& count) {
    if (++count > max_nodes) {
        fail(file, node, "more than " + std::to_string(max_nodes) + " YAML nodes (aliases expanded)");
    }
    if (node.IsMap()) {
        std::vector<std::string> seen;
        for (const auto& kv : node) {
            if (kv.first.IsScalar()) {
                if (first_non_xml_text(kv.first.Scalar()) != std::string::npos) {
                    fail(file, kv.first, "a key holds a byte that is not UTF-8 XML text (a control character or "
                                         "invalid UTF-8)");
                }
                if (std::find(seen.begin(), seen.end(), kv.first.Scalar()) != seen.end()) {
                    fail(file, kv.first, "duplicate key '" + kv.first.Scalar() + "'");
                }
                seen.push_back(kv.first.Scalar());
            }
            check_keys_unique(file, kv.second, count);
        }
    } else if (node.IsSequence()) {
        for (const auto& item : node) {
            check_keys_unique(file, item, count);
        }
    }
}

inline YAML::Node load_file(const std::filesystem::path& path, const std::string& what) {
    const std::string file = path.string();
    const std::string text = read_input_file(path, what);
    YAML::Node root;
    try {
        root = YAML::Load(text);
    } catch (const YAML::Exception& e) {
        throw InputError(file + ":" + std::to_string(e.mark.line + 1), "invalid YAML in " + what + ": " + e.msg);
    }
    std::size_t count = 0;
    check_keys_unique(file, root, count);
    return root;
}

// Refuses keys of `map` outside `allowed`, naming `context` (e.g. "element 'Scenery'").
inline void check_keys(const std::string& file, const YAML::Node& map, const std::vector<std::string_view>& allowed,
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

inline void check_keys(const std::string& file, const YAML::Node& map, std::initializer_list<std::string_view> allowed,
                       const std::string& context) {
    check_keys(file, map, std::vector<std::string_view>(allowed), context);
}

// A single value; text that XML cannot carry (control characters from "\x01"
// escapes, invalid UTF-8) is refused here, before it reaches a map or a scenario.
inline std::string scalar(const std::string& file, const YAML::Node& node, const std::string& what) {
    if (!node.IsScalar()) {
        fail(file, node, what + " must be a single value");
    }
    if (const auto at = first_non_xml_text(node.Scalar()); at != std::string::npos) {
        fail(file, node, what + " holds a byte that is not UTF-8 XML text at offset " + std::to_string(at) +
                             " (a control character or invalid UTF-8)");
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
        if (used == text.size() && std::isfinite(v)) {
            return v;
        }
    } catch (const std::exception&) {
    }
    fail(file, node, what + " must be a number, not '" + text + "' (NaN and infinities are refused)");
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
