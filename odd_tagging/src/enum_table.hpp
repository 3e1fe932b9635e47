#pragma once
// Table-driven parsing of enumerated OSM tag values: each parser lists the OSM
// spellings it accepts next to the C++ value, and the taxonomy name comes from
// the parser's to_string (tests check those names exist in the taxonomy).
#include "railodd/odd/tag_values.hpp"

#include "text.hpp"

#include <array>
#include <string>
#include <string_view>
#include <utility>

namespace railodd::odd::enums {

template <class E>
struct Spelling {
    std::string_view osm;
    E value;
};

// Exact, case-sensitive match as OSM values are lower case by convention; a
// differently cased value is accepted with a note rather than silently.
template <class E, std::size_t N>
TagValue<E> lookup(std::string_view raw, const std::array<Spelling<E>, N>& table, std::string_view what) {
    TagValue<E> r;
    const auto s = text::trim(raw);
    const auto low = text::lower(s);
    std::string known;
    for (const auto& entry : table) {
        if (entry.osm == low) {
            r.value = entry.value;
            if (low != s) {
                r.note = "read " + text::quoted(s) + " as " + text::quoted(entry.osm);
            }
            return r;
        }
        known.append(known.empty() ? "" : ", ").append(entry.osm);
    }
    r.problem = text::quoted(s) + " is not a known " + std::string(what) + " value (" + known + ")";
    return r;
}

} // namespace railodd::odd::enums
