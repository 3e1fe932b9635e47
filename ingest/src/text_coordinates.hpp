#pragma once
// A check of an OSM XML or OPL file's coordinates before libosmium reads them.
// libosmium 2.18 (Debian 12) applies a coordinate's exponent by multiplying a
// signed 64-bit integer by ten once per unit of it: "1e20" overflows, which is
// undefined behaviour and in practice a wrapped value that can pass its range
// check, a place other than the one written. Found by fuzz_convert
// (docs/reliability.md).
#include <filesystem>

namespace railodd::ingest {

// Throws InputError(file, "line 3: coordinate lat=\"1e20\" ...") when an XML
// attribute named *lat or *lon, or an OPL x / y coordinate (object fields and
// way node lists), is written with an exponent and its value is beyond
// +-1000 degrees: within that the product cannot overflow, and beyond it no
// coordinate is valid anyway. Other formats are not read.
void check_text_coordinates(const std::filesystem::path& file);

} // namespace railodd::ingest
