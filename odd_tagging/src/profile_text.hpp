#pragma once
// The profile files' pieces as text, shared by ProfileFiles (the three files,
// a batch at a time) and write_json (odd_profile.json of a whole profile):
// both give the same bytes.
#include "profile_elements.hpp"

#include "railodd/odd/profile.hpp"

#include <ostream>
#include <string>

namespace railodd::odd::profile_text {

// odd_profile.json up to and including `"elements": [` and its line break,
// with the kinds the rows index.
void write_json_head(const OddProfile& head, const profile_elements::KindList& kinds, std::ostream& out);
// From the elements' closing bracket to the end: unparsed and summary.
void write_json_tail(const OddProfile& tail, std::ostream& out);

// odd_profile.geojson: the head, the features separated by ",\n" (a "\n"
// after the last), the tail.
inline constexpr const char* geojson_head = "{\"type\": \"FeatureCollection\", \"name\": \"odd_profile\", \"features\": [\n";
inline constexpr const char* geojson_tail = "]}\n";
void append_feature(std::string& out, const TaggedElement& e);

// odd_profile.csv: the header row, then a row per element (field: a buffer
// the caller reuses).
void append_csv_header(std::string& out);
void append_csv_row(std::string& row, std::string& field, const TaggedElement& e);

} // namespace railodd::odd::profile_text
