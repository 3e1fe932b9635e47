#pragma once
// CLI11 validators on the value checks of railodd/util/value_checks.hpp
// (which say what CLI11's own let through).
#include "railodd/util/value_checks.hpp"

#include <CLI/CLI.hpp>

#include <string>

namespace railodd::cli {

// A finite number in [lo, hi].
inline CLI::Validator finite_range(double lo, double hi) {
    return CLI::Validator([lo, hi](std::string& text) { return util::check_finite_in(text, lo, hi); },
                          "FINITE in [" + CLI::detail::to_string(lo) + " - " + CLI::detail::to_string(hi) + "]");
}

// Decimal digits only: no sign, so no wrap-around into an unsigned option.
inline const CLI::Validator unsigned_integer([](std::string& text) { return util::check_non_negative_integer(text); },
                                             "UINT");

// A path that is not empty.
inline const CLI::Validator non_empty_path([](std::string& text) { return util::check_non_empty_path(text); }, "PATH");

} // namespace railodd::cli
