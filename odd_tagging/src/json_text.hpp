#pragma once
// JSON text appended straight to a buffer, byte for byte as nlohmann::json's
// compact dump() prints it: the profile's GeoJSON and JSON (one feature or
// element per line, 90 and 57 MB for the Cologne network) took longer to
// build as json objects than to print.
#include "railodd/odd/profile.hpp"

#include <string>
#include <string_view>
#include <vector>

namespace railodd::odd::json_text {

// Shortest round-trip digits (nlohmann's Grisu2: "20.0", "0.0", "1e-05");
// null for NaN and infinities.
void number(std::string& out, double value);
void number(std::string& out, unsigned long long value);
// Quoted and escaped; text that is not plain ASCII goes through nlohmann,
// which checks the UTF-8 and throws on bad bytes as dump() does.
void string(std::string& out, std::string_view value);
void value(std::string& out, const AttributeValue& value);
// As an ordered JSON object: a repeated name keeps its first place and its
// last value.
void attributes(std::string& out, const std::vector<TaggedAttribute>& attributes);

} // namespace railodd::odd::json_text
