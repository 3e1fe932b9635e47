#pragma once
// Reading and checking the bins of a numeric attribute (interval notation).
#include "railodd/odd/taxonomy.hpp"

#include <string>
#include <string_view>
#include <vector>

namespace railodd::odd::bins {

// Fills the bounds of `bin` from "[a, b)", "(a, b]", "[a, inf)", "(-inf, b]".
// Returns the problem, or "" when the text is a valid interval.
std::string parse_range(std::string_view text, Bin& bin);

// Checks that the bins ascend, do not overlap and leave no gap (so that every
// value in their overall range has exactly one class), and that labels are
// unique. Returns the problem naming the offending bins, or "".
std::string check_sequence(const std::vector<Bin>& bins);

} // namespace railodd::odd::bins
