#pragma once
// Small text helpers for the tag value parsers: OSM values are free text, so
// numbers are read strictly (the whole string, '.' as decimal point) and every
// looser reading is done explicitly by the caller, which then adds a note.
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace railodd::odd::text {

std::string_view trim(std::string_view s);
std::string lower(std::string_view s);
// Splits on `sep`, trimming each part; empty parts are kept (callers refuse them).
std::vector<std::string_view> split(std::string_view s, char sep);
// A plain decimal number: optional sign, digits, optional '.' and digits.
// No exponent, no spaces, no thousands separators, no "inf"/"nan".
std::optional<double> strict_number(std::string_view s);
// Splits "80 km/h" / "80km/h" into number text and unit text (trimmed).
std::pair<std::string_view, std::string_view> number_and_unit(std::string_view s);
// 'value' in single quotes, for messages (built by appending: GCC 12 warns
// falsely (-Wrestrict) on "'" + std::string).
std::string quoted(std::string_view s);
// "1.5" for 1.5, "80" for 80: shortest round-trip text for notes and messages.
std::string format(double value);

} // namespace railodd::odd::text
