#pragma once
// Checks and formats attribute values against the taxonomy, shared by the
// catalog and template loaders and the coverage table.
#include "railodd/odd/profile.hpp"
#include "railodd/odd/taxonomy.hpp"

#include <optional>
#include <string>

namespace railodd::scenario {

// The number the text holds, or none.
std::optional<double> parse_number(const std::string& text);

// Empty when `value` is a valid value of the attribute: a number inside one
// of its bins (any number when it has none), one of its enum values, true or
// false; else what is wrong.
std::string check_value(const odd::Attribute& attribute, const std::string& value);

// The value class coverage counts: the bin label of a number (the number
// itself when the attribute has no bins), the value itself otherwise.
std::string value_class(const odd::Attribute& attribute, const std::string& value);

// Whether coverage counts the attribute's classes: numbers without classes
// (lengths, angles) and free strings have no finite set to cover.
bool countable(const odd::Attribute& attribute);

// Shortest text of a number as parameters and texts show it ("80", "0.5").
std::string format_number(double value);

// A profile value as text: a number formatted so, true / false, the string.
std::string text_of(const odd::AttributeValue& value);

} // namespace railodd::scenario
