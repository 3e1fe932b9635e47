#pragma once
// The railway ODD taxonomy (data/odd/railway_odd.yaml, docs/odd.md): a tree of
// elements, at most four levels deep, whose attributes carry value classes
// (bins). Every stage that speaks about the ODD (tagger, profile, scenario
// generator, coverage) reads the same file through load_taxonomy(), so the
// classes live in data and never in code.
#include <cstddef>
#include <filesystem>
#include <limits>
#include <map>
#include <string>
#include <vector>

namespace railodd::odd {

inline constexpr int max_levels = 4;

// One class of a numeric attribute: an interval with open or closed ends.
struct Bin {
    std::string label;
    double lower = -std::numeric_limits<double>::infinity();
    double upper = std::numeric_limits<double>::infinity();
    bool lower_closed = true;
    bool upper_closed = false;
    int line = 0; // 1-based line in the taxonomy file

    bool contains(double value) const;
    std::string interval() const; // "[0, 300)", "(40, inf)"
};

enum class AttributeType { number, enumeration, boolean, string };
const char* to_string(AttributeType type); // "number", "enum", "bool", "string"

// A descriptor beyond the last level of an element (pose, radius, ...). It
// describes the element it is declared on and every element below it.
struct Attribute {
    std::string name;
    AttributeType type = AttributeType::string;
    std::string unit;
    std::string description;
    std::string source; // where the bins come from
    std::vector<Bin> bins; // number only; ascending, tiling their range
    std::vector<std::string> values; // enum only
    int line = 0;

    bool has_value(const std::string& value) const; // enum membership
};

struct Element {
    static constexpr std::size_t no_parent = static_cast<std::size_t>(-1);

    std::string name;
    std::string id;
    std::string path; // "Scenery/Track geometry/Horizontal/Curve"
    int level = 1;    // 1 for the five top categories
    std::string description;
    std::string osm; // OSM tags the tagger reads (documentation)
    std::string iso34503;
    std::string pas1883;
    std::string dke99004;
    std::vector<Attribute> attributes; // declared here, not inherited ones
    std::vector<std::size_t> children; // indices into Taxonomy::elements
    std::size_t parent = no_parent;
    int line = 0;
};

struct Taxonomy {
    std::string source; // the file it was loaded from
    std::string name;
    std::string version;
    std::vector<Element> elements; // depth first, in file order
    std::map<std::string, std::size_t> by_path;
    std::map<std::string, std::size_t> by_id;

    const Element* find(const std::string& path) const;
    const Element* find_id(const std::string& id) const;
    std::vector<const Element*> top_level() const;
    std::vector<const Element*> children(const Element& element) const;
    const Element* parent(const Element& element) const;
    // The attribute `name` of the element or of its nearest ancestor declaring it.
    const Attribute* attribute(const Element& element, const std::string& name) const;
    // Own and inherited attributes, nearest ancestor's last.
    std::vector<const Attribute*> attributes(const Element& element) const;
    std::size_t attribute_count() const; // declared attributes over all elements
};

// Reads and validates a taxonomy file. Throws railodd::InputError naming the
// file, the line and the problem for: YAML errors, unknown keys, missing names
// or ids, more than max_levels levels, duplicate paths or ids, attributes
// without a type, enums without values, bins that overlap, descend or leave
// gaps, and attributes repeating an ancestor's attribute.
Taxonomy load_taxonomy(const std::filesystem::path& path);

// The label of the bin holding `value`, or "" when the attribute has no bins or
// the value lies outside all of them.
std::string classify(const Attribute& attribute, double value);

} // namespace railodd::odd
