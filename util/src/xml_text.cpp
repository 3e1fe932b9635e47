#include "railodd/util/xml_text.hpp"

#include <cstdint>

namespace railodd {

namespace {

// Length of the well-formed UTF-8 sequence at s[i] encoding an XML character,
// or 0 (RFC 3629's table: no overlong forms, no surrogates, at most U+10FFFF).
std::size_t xml_char_at(std::string_view s, std::size_t i) {
    const auto b = [&](std::size_t k) { return static_cast<unsigned char>(s[i + k]); };
    const std::size_t left = s.size() - i;
    const unsigned char c = b(0);
    if (c < 0x80) {
        return c >= 0x20 || c == 0x09 || c == 0x0A || c == 0x0D ? 1 : 0;
    }
    auto cont = [&](std::size_t k) { return k < left && (b(k) & 0xC0) == 0x80; };
    if (c >= 0xC2 && c <= 0xDF) {
        return cont(1) ? 2 : 0;
    }
    if (c >= 0xE0 && c <= 0xEF) {
        if (!cont(1) || !cont(2)) {
            return 0;
        }
        const std::uint32_t cp = ((c & 0x0Fu) << 12) | ((b(1) & 0x3Fu) << 6) | (b(2) & 0x3Fu);
        const bool ok = cp >= 0x800 && !(cp >= 0xD800 && cp <= 0xDFFF) && cp != 0xFFFE && cp != 0xFFFF;
        return ok ? 3 : 0;
    }
    if (c >= 0xF0 && c <= 0xF4) {
        if (!cont(1) || !cont(2) || !cont(3)) {
            return 0;
        }
        const std::uint32_t cp =
            ((c & 0x07u) << 18) | ((b(1) & 0x3Fu) << 12) | ((b(2) & 0x3Fu) << 6) | (b(3) & 0x3Fu);
        return cp >= 0x10000 && cp <= 0x10FFFF ? 4 : 0;
    }
    return 0;
}

} // namespace

std::size_t first_non_xml_text(std::string_view s) {
    for (std::size_t i = 0; i < s.size();) {
        const std::size_t n = xml_char_at(s, i);
        if (n == 0) {
            return i;
        }
        i += n;
    }
    return std::string_view::npos;
}

bool make_xml_text(std::string& s) {
    std::size_t i = first_non_xml_text(s);
    if (i == std::string_view::npos) {
        return false;
    }
    std::string out = s.substr(0, i);
    while (i < s.size()) {
        const std::size_t n = xml_char_at(s, i);
        if (n > 0) {
            out.append(s, i, n);
            i += n;
        } else {
            out += "\xEF\xBF\xBD"; // U+FFFD for the offending byte
            ++i;
        }
    }
    s = std::move(out);
    return true;
}

} // namespace railodd
