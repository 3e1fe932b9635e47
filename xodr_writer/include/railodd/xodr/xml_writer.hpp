#pragma once
// Serializes the map as ASAM OpenDRIVE 1.6, 1.7 or 1.8 XML. Numbers are
// written with 15 significant digits through std::to_chars, so the output is
// byte-identical for identical maps and locale-independent.
#include "railodd/xodr/model.hpp"

#include <functional>
#include <iosfwd>
#include <string>
#include <vector>

namespace railodd::xodr {

// User data a road gets in the output beyond its own, after it.
using ExtraUserData = std::function<std::vector<UserData>(const Road&)>;

std::string write_xodr(const Map& map, Revision revision);
// The same, streamed: the document is never held as one string.
void write_xodr(const Map& map, Revision revision, std::ostream& out, const ExtraUserData& extra = {});

} // namespace railodd::xodr
