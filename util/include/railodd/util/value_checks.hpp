#pragma once
// Checks of an option's value as text, for the command line's validators
// (cli/option_checks.hpp) and the convert options' table (convert::check_value):
// each says why the text is no value, or nothing where it is one. They refuse
// what CLI11's own checks let through: NaN and infinities pass a plain range
// (every comparison with NaN is false), "-1" parses into an unsigned option
// as 2^64-1, and "" is a valid path string.
#include <cmath>
#include <sstream>
#include <string>

namespace railodd::util {

// A finite number in [lo, hi].
inline std::string check_finite_in(const std::string& text, double lo, double hi) {
    double v = 0.0;
    std::size_t used = 0;
    try {
        v = std::stod(text, &used);
    } catch (const std::exception&) {
        return "'" + text + "' is not a number";
    }
    if (used != text.size() || !std::isfinite(v)) {
        return "'" + text + "' is not a finite number";
    }
    if (v < lo || v > hi) {
        std::ostringstream range;
        range << "[" << lo << ", " << hi << "]";
        return "'" + text + "' is outside " + range.str();
    }
    return {};
}

// Decimal digits only: no sign, so no wrap-around into an unsigned option.
inline std::string check_non_negative_integer(const std::string& text) {
    return text.empty() || text.find_first_not_of("0123456789") != std::string::npos
               ? "'" + text + "' is not a non-negative integer"
               : std::string{};
}

// A path that is not empty ("" would write into or read from the working
// directory without saying so).
inline std::string check_non_empty_path(const std::string& text) {
    return text.empty() ? "the path is empty" : std::string{};
}

} // namespace railodd::util
