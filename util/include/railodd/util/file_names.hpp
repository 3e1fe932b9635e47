#pragma once
// Names from user input that become part of a file or folder name (batch
// route ids, template ids, asset ids): one rule everywhere, so no input can
// place an output outside its folder, hide it or overflow a name.
#include <cstddef>
#include <string_view>

namespace railodd {

inline constexpr std::size_t max_name_length = 100;

// 1 to max_name_length letters, digits, '.', '_' or '-', the first a letter or
// digit: never '.', '..', a path, a hidden file or an option.
bool is_safe_name(std::string_view name);

// The rule in words, for error messages.
inline constexpr const char* safe_name_rule =
    "letters, digits, '.', '_', '-', at most 100 characters, starting with a letter or digit";

} // namespace railodd
