#pragma once
// Appending JSON text directly: for large GeoJSON dumps, building a DOM first
// costs more than everything else a conversion does.
#include <cstdint>
#include <string>
#include <string_view>

namespace railodd {

// A quoted JSON string with the escapes RFC 8259 requires.
void append_json_string(std::string& out, std::string_view text);

// Shortest text that reads back as the same double (std::to_chars); non-finite
// values become null, which JSON has instead of NaN.
void append_json_number(std::string& out, double value);

void append_json_number(std::string& out, std::int64_t value);

} // namespace railodd
