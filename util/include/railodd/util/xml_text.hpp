#pragma once
// Text that reaches XML and JSON outputs (OSM tags, GIS attributes, template
// texts) must be UTF-8 made of characters XML 1.0 allows: tab, LF, CR,
// U+0020..U+D7FF, U+E000..U+FFFD, U+10000..U+10FFFF. Anything else (invalid
// or overlong byte sequences, surrogates, C0 controls, U+FFFE/U+FFFF) makes
// a map that no XML reader opens.
#include <cstddef>
#include <string>
#include <string_view>

namespace railodd {

// Byte offset of the first byte that is not such text, or npos.
std::size_t first_non_xml_text(std::string_view s);

// Replaces every offending byte sequence or character by U+FFFD; whether
// anything was replaced.
bool make_xml_text(std::string& s);

} // namespace railodd
