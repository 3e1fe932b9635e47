#include "json_text.hpp"

#include <nlohmann/json.hpp>

#include <array>
#include <charconv>
#include <cmath>

namespace railodd::odd::json_text {

void number(std::string& out, double value) {
    if (!std::isfinite(value)) {
        out += "null";
        return;
    }
    std::array<char, 64> buf{};
    char* end = nlohmann::detail::to_chars(buf.data(), buf.data() + buf.size(), value);
    out.append(buf.data(), static_cast<std::size_t>(end - buf.data()));
}

void number(std::string& out, unsigned long long value) {
    std::array<char, 24> buf{};
    const auto r = std::to_chars(buf.data(), buf.data() + buf.size(), value);
    out.append(buf.data(), static_cast<std::size_t>(r.ptr - buf.data()));
}

void string(std::string& out, std::string_view value) {
    for (const char c : value) {
        const auto u = static_cast<unsigned char>(c);
        if (u < 0x20 || u >= 0x7f || c == '"' || c == '\\') {
            out += nlohmann::json(std::string(value)).dump();
            return;
        }
    }
    out += '"';
    out += value;
    out += '"';
}

void value(std::string& out, const AttributeValue& v) {
    if (const auto* d = std::get_if<double>(&v)) {
        number(out, *d);
    } else if (const auto* b = std::get_if<bool>(&v)) {
        out += *b ? "true" : "false";
    } else {
        string(out, std::get<std::string>(v));
    }
}

void attributes(std::string& out, const std::vector<TaggedAttribute>& attributes) {
    out += '{';
    bool first = true;
    for (std::size_t i = 0; i < attributes.size(); ++i) {
        const auto& name = attributes[i].name;
        bool seen = false;
        for (std::size_t j = 0; j < i && !seen; ++j) {
            seen = attributes[j].name == name;
        }
        if (seen) {
            continue;
        }
        const AttributeValue* last = &attributes[i].value;
        for (std::size_t j = i + 1; j < attributes.size(); ++j) {
            if (attributes[j].name == name) {
                last = &attributes[j].value;
            }
        }
        out += first ? "" : ",";
        first = false;
        string(out, name);
        out += ':';
        value(out, *last);
    }
    out += '}';
}

} // namespace railodd::odd::json_text
