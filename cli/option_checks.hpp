#pragma once
// CLI11 validators that also refuse what CLI11's own let through: NaN and
// infinities pass CLI::Range (every comparison with NaN is false), "-1"
// parses into an unsigned option as 2^64-1, and "" is a valid path string.
#include <CLI/CLI.hpp>

#include <cmath>
#include <string>

namespace railodd::cli {

// A finite number in [lo, hi].
inline CLI::Validator finite_range(double lo, double hi) {
    return CLI::Validator(
        [lo, hi](std::string& text) -> std::string {
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
                return "'" + text + "' is outside [" + CLI::detail::to_string(lo) + ", " + CLI::detail::to_string(hi) +
                       "]";
            }
            return {};
        },
        "FINITE in [" + CLI::detail::to_string(lo) + " - " + CLI::detail::to_string(hi) + "]");
}

// Decimal digits only: no sign, so no wrap-around into an unsigned option.
inline const CLI::Validator unsigned_integer(
    [](std::string& text) -> std::string {
        if (text.empty() || text.find_first_not_of("0123456789") != std::string::npos) {
            return "'" + text + "' is not a non-negative integer";
        }
        return {};
    },
    "UINT");

// A path that is not empty ("" would write into or read from the working
// directory without saying so).
inline const CLI::Validator non_empty_path(
    [](std::string& text) -> std::string { return text.empty() ? "the path is empty" : std::string{}; }, "PATH");

} // namespace railodd::cli
