#pragma once
// The YAML mapping from a vector layer's attribute fields onto OSM tags.
#include <filesystem>
#include <map>
#include <optional>
#include <string>
#include <vector>

namespace railodd::ingest {

struct TagRule {
    std::string key;
    std::optional<std::string> constant;       // value: the tag is the same on every feature
    std::string field;                         // or copied from this field ...
    std::map<std::string, std::string> values; // ... translated through this table where it has the value
    std::optional<std::string> fallback;       // value when the field is null
    int line = 0;                              // in the mapping file, for messages
};

struct FieldMapping {
    std::string source;   // mapping file
    std::string layer;    // empty: the dataset's first layer
    std::string id_field; // empty: the OGR feature id
    std::string crs;      // empty: the layer's own CRS
    std::vector<TagRule> tags;
};

// Throws InputError naming the file and line for anything it does not understand.
FieldMapping load_field_mapping(const std::filesystem::path& file);

} // namespace railodd::ingest
