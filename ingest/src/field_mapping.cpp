#include "field_mapping.hpp"

#include "railodd/util/errors.hpp"
#include "railodd/util/yaml_support.hpp"

#include <yaml-cpp/yaml.h>

namespace railodd::ingest {

namespace {

std::string where(const std::string& file, const YAML::Node& node) {
    return file + ":" + std::to_string(node.Mark().line + 1);
}

TagRule parse_rule(const std::string& file, const std::string& key, const YAML::Node& spec) {
    TagRule rule;
    rule.key = key;
    rule.line = spec.Mark().line + 1;
    if (spec.IsScalar()) {
        rule.constant = spec.as<std::string>();
        return rule;
    }
    if (!spec.IsMap()) {
        throw InputError(where(file, spec), "tag '" + key + "' must be a constant or {field: NAME, ...}");
    }
    for (const auto& kv : spec) {
        const auto name = kv.first.as<std::string>();
        if (name == "field") {
            rule.field = kv.second.as<std::string>();
        } else if (name == "default") {
            rule.fallback = kv.second.as<std::string>();
        } else if (name == "values") {
            if (!kv.second.IsMap()) {
                throw InputError(where(file, kv.second), "'values' of tag '" + key + "' must be a map");
            }
            for (const auto& v : kv.second) {
                rule.values[v.first.as<std::string>()] = v.second.as<std::string>();
            }
        } else {
            throw InputError(where(file, kv.first), "unknown key '" + name + "' in tag '" + key +
                                                        "' (expected field, values, default)");
        }
    }
    if (rule.field.empty()) {
        throw InputError(where(file, spec), "tag '" + key + "' has no 'field'");
    }
    return rule;
}

} // namespace

FieldMapping load_field_mapping(const std::filesystem::path& path) {
    FieldMapping m;
    m.source = path.string();
    const YAML::Node root = yaml::load_file(path, "field mapping");
    if (!root.IsMap()) {
        throw InputError(m.source, "field mapping must be a YAML map with a 'tags' entry");
    }
    try {
        for (const auto& kv : root) {
            const auto key = kv.first.as<std::string>();
            if (key == "layer") {
                m.layer = kv.second.as<std::string>();
            } else if (key == "id_field") {
                m.id_field = kv.second.as<std::string>();
            } else if (key == "crs") {
                m.crs = kv.second.as<std::string>();
            } else if (key == "tags") {
                if (!kv.second.IsMap()) {
                    throw InputError(where(m.source, kv.second), "'tags' must map OSM keys to rules");
                }
                for (const auto& t : kv.second) {
                    m.tags.push_back(parse_rule(m.source, t.first.as<std::string>(), t.second));
                }
            } else {
                throw InputError(where(m.source, kv.first),
                                 "unknown key '" + key + "' (expected layer, id_field, crs, tags)");
            }
        }
    } catch (const YAML::Exception& e) {
        throw InputError(m.source + ":" + std::to_string(e.mark.line + 1), "invalid field mapping: " + e.msg);
    }
    const bool has_railway = std::any_of(m.tags.begin(), m.tags.end(), [](const TagRule& r) { return r.key == "railway"; });
    if (!has_railway) {
        throw InputError(m.source, "no rule for tag 'railway': tracks need railway=rail|tram|... "
                                   "(a constant, or mapped from a field)");
    }
    return m;
}

} // namespace railodd::ingest
