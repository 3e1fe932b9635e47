#include "attribute_values.hpp"

#include <charconv>
#include <cmath>
#include <variant>

namespace railodd::scenario {

std::optional<double> parse_number(const std::string& text) {
    double v = 0.0;
    const char* end = text.data() + text.size();
    const auto r = std::from_chars(text.data(), end, v);
    if (r.ec != std::errc{} || r.ptr != end || !std::isfinite(v)) {
        return std::nullopt;
    }
    return v;
}

std::string check_value(const odd::Attribute& attribute, const std::string& value) {
    switch (attribute.type) {
    case odd::AttributeType::number: {
        const auto v = parse_number(value);
        if (!v) {
            return "'" + value + "' is not a number";
        }
        if (!attribute.bins.empty() && odd::classify(attribute, *v).empty()) {
            return value + " lies outside every class of the taxonomy (" + attribute.bins.front().interval() + " .. " +
                   attribute.bins.back().interval() + ")";
        }
        return {};
    }
    case odd::AttributeType::enumeration:
        if (attribute.has_value(value)) {
            return {};
        } else {
            std::string list;
            for (const auto& v : attribute.values) {
                list += (list.empty() ? "" : ", ") + v;
            }
            return "'" + value + "' is not one of " + list;
        }
    case odd::AttributeType::boolean:
        return value == "true" || value == "false" ? std::string{} : "'" + value + "' is not true or false";
    case odd::AttributeType::string:
        return {};
    }
    return {};
}

std::string value_class(const odd::Attribute& attribute, const std::string& value) {
    if (attribute.type == odd::AttributeType::number && !attribute.bins.empty()) {
        if (const auto v = parse_number(value)) {
            const auto label = odd::classify(attribute, *v);
            return label.empty() ? value : label;
        }
    }
    return value;
}

std::string format_number(double value) {
    char buf[32];
    const double r = std::round(value);
    if (std::abs(value - r) < 1e-9 && std::abs(r) < 1e15) {
        std::snprintf(buf, sizeof buf, "%.0f", r);
    } else {
        std::snprintf(buf, sizeof buf, "%.6g", value);
    }
    return buf;
}

bool countable(const odd::Attribute& a) {
    return a.type != odd::AttributeType::string && (a.type != odd::AttributeType::number || !a.bins.empty());
}

std::string text_of(const odd::AttributeValue& v) {
    if (const double* x = std::get_if<double>(&v)) {
        return format_number(*x);
    }
    if (const bool* b = std::get_if<bool>(&v)) {
        return *b ? "true" : "false";
    }
    return std::get<std::string>(v);
}

} // namespace railodd::scenario
