#pragma once
// A declared ODD (`railodd profile --odd-spec FILE`, docs/odd.md "ODD spec"):
// which taxonomy elements a system is designed for and the ranges or values of
// their attributes. Loaded against a Taxonomy so that every path, attribute,
// enum value and bin label it names is known.
#include "railodd/odd/taxonomy.hpp"

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

namespace railodd::odd {

struct AttributeConstraint {
    std::string attribute;
    AttributeType type = AttributeType::string;
    std::optional<double> min; // inclusive, number only
    std::optional<double> max; // inclusive, number only
    std::vector<std::string> bins;   // allowed bin labels, number only
    std::vector<std::string> values; // allowed values, enum or string
    std::optional<bool> value;       // required value, bool only
    int line = 0;
};

struct ElementConstraint {
    std::string path;
    std::string id;
    bool allowed = true; // false: the element lies outside the ODD
    std::string note;
    std::vector<AttributeConstraint> attributes;
    int line = 0;

    const AttributeConstraint* find(const std::string& attribute) const;
};

struct OddSpec {
    std::string source;
    std::string name;
    std::string description;
    std::string taxonomy_version; // empty: not pinned
    bool unlisted_inside = true;  // elements the spec does not name are inside the ODD
    std::vector<ElementConstraint> elements;

    const ElementConstraint* find(const std::string& path) const;
};

// Reads a spec and checks it against the taxonomy; throws railodd::InputError
// naming the file, the line and the problem for unknown keys, paths or
// attributes not in the taxonomy, constraints that do not fit the attribute's
// type, enum values or bin labels the taxonomy does not define, min > max, and
// a taxonomy_version other than the taxonomy's.
OddSpec load_odd_spec(const std::filesystem::path& path, const Taxonomy& taxonomy);

// Whether a measured number lies inside the constraint (min, max and, when
// given, one of the allowed bins of `attribute`).
bool admits_number(const AttributeConstraint& constraint, const Attribute& attribute, double value);
// Whether an enum or string value is allowed (any value when `values` is empty).
bool admits_value(const AttributeConstraint& constraint, const std::string& value);
// Whether a bool value is allowed (any value when no `value` is required).
bool admits_flag(const AttributeConstraint& constraint, bool value);

} // namespace railodd::odd
