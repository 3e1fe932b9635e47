#pragma once
// Reading a hand-editable JSON file key by key: every lookup names the key
// and where it was expected, so that a file that lost a key is reported as
// "elements[3].s_start: missing" (std::invalid_argument; read_profile adds
// the file). Templates over nlohmann::json and ordered_json.
#include "railodd/odd/profile.hpp"

#include <stdexcept>
#include <string>
#include <type_traits>

namespace railodd::odd::json_read {

inline std::string at(const std::string& where, const std::string& key) {
    return where.empty() ? key : where + "." + key;
}

template <class Json>
const Json& required(const Json& j, const std::string& key, const std::string& where) {
    if (!j.is_object()) {
        throw std::invalid_argument((where.empty() ? "document" : where) + ": expected an object");
    }
    const auto it = j.find(key);
    if (it == j.end()) {
        throw std::invalid_argument(at(where, key) + ": missing");
    }
    return *it;
}

// The value itself, typed; std::size_t must be an exact unsigned integer
// (nlohmann would wrap -1 to 2^64-1 and cut 1.5 to 1).
template <class T, class Json>
T as(const Json& v, const std::string& where) {
    if constexpr (std::is_same_v<T, std::size_t>) {
        if (!v.is_number_unsigned()) {
            throw std::invalid_argument(where + ": expected a count, not " + v.dump());
        }
    }
    try {
        return v.template get<T>();
    } catch (const nlohmann::json::exception&) { // shared by both specialisations
        throw std::invalid_argument(where + ": wrong type (" + v.type_name() + ")");
    }
}

template <class T, class Json>
T get(const Json& j, const std::string& key, const std::string& where) {
    return as<T>(required(j, key, where), at(where, key));
}

template <class T, class Json>
T get_or(const Json& j, const std::string& key, const std::string& where, T fallback) {
    if (!j.is_object()) {
        throw std::invalid_argument((where.empty() ? "document" : where) + ": expected an object");
    }
    return j.contains(key) ? get<T>(j, key, where) : fallback;
}

template <class Json>
AttributeValue attribute_value(const Json& v, const std::string& where) {
    if (v.is_boolean()) {
        return v.template get<bool>();
    }
    if (v.is_number()) {
        return v.template get<double>();
    }
    if (v.is_string()) {
        return v.template get<std::string>();
    }
    throw std::invalid_argument(where + ": expected a number, string or bool (" + v.type_name() + ")");
}

template <class Json>
std::vector<TaggedAttribute> attributes(const Json& attrs, const std::string& where) {
    if (!attrs.is_object()) {
        throw std::invalid_argument(where + ": expected an object");
    }
    std::vector<TaggedAttribute> out;
    for (const auto& [name, value] : attrs.items()) {
        out.push_back({name, attribute_value(value, where + "." + name)});
    }
    return out;
}

} // namespace railodd::odd::json_read
