// Reads data/odd/railway_odd.yaml (or any taxonomy file) and refuses anything
// the stages after it could misread: the file is the single source of the ODD's
// names and classes, so a silent mistake there would skew every profile.
#include "railodd/odd/taxonomy.hpp"

#include "bins.hpp"
#include "yaml_support.hpp"

#include <set>

namespace railodd::odd {

namespace {

class TaxonomyLoader {
public:
    explicit TaxonomyLoader(Taxonomy& taxonomy) : tax_(taxonomy), file_(taxonomy.source) {}

    void root(const YAML::Node& root) {
        yaml::require(file_, root, root.IsMap(), "a taxonomy must be a YAML map with an 'elements' list");
        yaml::check_keys(file_, root, {"taxonomy", "version", "description", "elements"}, "taxonomy");
        if (root["taxonomy"]) {
            tax_.name = yaml::scalar(file_, root["taxonomy"], "'taxonomy'");
        }
        if (root["version"]) {
            tax_.version = yaml::scalar(file_, root["version"], "'version'");
        }
        const auto list = root["elements"];
        yaml::require(file_, list ? list : root, list && list.IsSequence() && list.size() > 0,
                      "taxonomy needs a non-empty 'elements' list (the top categories)");
        for (const auto& node : list) {
            element(node, Element::no_parent, 1, "");
        }
    }

private:
    Taxonomy& tax_;
    const std::string file_;

    void element(const YAML::Node& node, std::size_t parent, int level, const std::string& parent_path) {
        const auto context = parent_path.empty() ? std::string("top-level element") : "element under '" + parent_path + "'";
        yaml::require(file_, node, node.IsMap(), context + " must be a map with name, id, ...");
        yaml::require(file_, node, static_cast<bool>(node["name"]), context + " has no 'name'");
        Element e;
        e.name = yaml::scalar(file_, node["name"], "'name'");
        yaml::require(file_, node["name"], !e.name.empty() && e.name.find('/') == std::string::npos,
                      context + ": name '" + e.name + "' must be non-empty and contain no '/'");
        e.path = parent_path.empty() ? e.name : parent_path + "/" + e.name;
        e.level = level;
        e.parent = parent;
        e.line = yaml::line_of(node);
        const auto what = "element '" + e.path + "'";
        yaml::check_keys(file_, node,
                         {"name", "id", "description", "osm", "iso34503", "pas1883", "dke99004", "attributes", "children"},
                         what);
        yaml::require(file_, node, level <= max_levels,
                      what + " is at level " + std::to_string(level) + "; the taxonomy allows " +
                          std::to_string(max_levels) + " levels (describe further detail with attributes)");
        yaml::require(file_, node, static_cast<bool>(node["id"]), what + " has no 'id'");
        e.id = yaml::scalar(file_, node["id"], what + ": 'id'");
        yaml::require(file_, node["id"], !e.id.empty(), what + ": empty 'id'");
        read_optional(node, "description", what, e.description);
        read_optional(node, "osm", what, e.osm);
        read_optional(node, "iso34503", what, e.iso34503);
        read_optional(node, "pas1883", what, e.pas1883);
        read_optional(node, "dke99004", what, e.dke99004);

        const std::size_t index = tax_.elements.size();
        if (const auto [it, fresh] = tax_.by_path.emplace(e.path, index); !fresh) {
            yaml::fail(file_, node["name"], "duplicate path '" + e.path + "' (first at line " +
                                                std::to_string(tax_.elements[it->second].line) + ")");
        }
        if (const auto [it, fresh] = tax_.by_id.emplace(e.id, index); !fresh) {
            yaml::fail(file_, node["id"], what + ": duplicate id '" + e.id + "' (already used by '" +
                                              tax_.elements[it->second].path + "')");
        }
        tax_.elements.push_back(std::move(e));
        if (parent != Element::no_parent) {
            tax_.elements[parent].children.push_back(index);
        }
        if (const auto attrs = node["attributes"]) {
            attributes(attrs, index, what);
        }
        if (const auto kids = node["children"]) {
            yaml::require(file_, kids, kids.IsSequence(), what + ": 'children' must be a list of elements");
            const auto path = tax_.elements[index].path;
            for (const auto& kid : kids) {
                element(kid, index, level + 1, path);
            }
        }
    }

    void read_optional(const YAML::Node& node, const char* key, const std::string& what, std::string& out) {
        if (const auto v = node[key]) {
            out = yaml::scalar(file_, v, what + ": '" + key + "'");
        }
    }

    void attributes(const YAML::Node& list, std::size_t index, const std::string& what) {
        yaml::require(file_, list, list.IsSequence(), what + ": 'attributes' must be a list");
        for (const auto& node : list) {
            Attribute a = attribute(node, what);
            for (const auto& other : tax_.elements[index].attributes) {
                yaml::require(file_, node, other.name != a.name,
                              what + ": attribute '" + a.name + "' declared twice (first at line " +
                                  std::to_string(other.line) + ")");
            }
            const auto& parent = tax_.elements[index].parent;
            if (parent != Element::no_parent) {
                if (const auto* inherited = tax_.attribute(tax_.elements[parent], a.name)) {
                    yaml::fail(file_, node, what + ": attribute '" + a.name + "' repeats an inherited attribute (line " +
                                                std::to_string(inherited->line) + ")");
                }
            }
            tax_.elements[index].attributes.push_back(std::move(a));
        }
    }

    Attribute attribute(const YAML::Node& node, const std::string& element) {
        yaml::require(file_, node, node.IsMap() && node["name"], element + ": an attribute needs a map with 'name'");
        Attribute a;
        a.name = yaml::scalar(file_, node["name"], element + ": attribute 'name'");
        a.line = yaml::line_of(node);
        const auto what = element + ", attribute '" + a.name + "'";
        yaml::check_keys(file_, node, {"name", "type", "unit", "description", "source", "bins", "values"}, what);
        yaml::require(file_, node, static_cast<bool>(node["type"]),
                      what + " has no 'type' (number, enum, bool or string)");
        a.type = type(node["type"], what);
        read_optional(node, "unit", what, a.unit);
        read_optional(node, "description", what, a.description);
        read_optional(node, "source", what, a.source);
        if (const auto b = node["bins"]) {
            yaml::require(file_, b, a.type == AttributeType::number, what + ": 'bins' only apply to numbers");
            a.bins = bins(b, what);
        }
        if (const auto v = node["values"]) {
            yaml::require(file_, v, a.type == AttributeType::enumeration, what + ": 'values' only apply to enums");
            a.values = values(v, what);
        }
        yaml::require(file_, node, a.type != AttributeType::enumeration || !a.values.empty(),
                      what + ": an enum needs a non-empty 'values' list");
        return a;
    }

    AttributeType type(const YAML::Node& node, const std::string& what) {
        const auto t = yaml::scalar(file_, node, what + ": 'type'");
        for (const auto candidate : {AttributeType::number, AttributeType::enumeration, AttributeType::boolean,
                                     AttributeType::string}) {
            if (t == to_string(candidate)) {
                return candidate;
            }
        }
        yaml::fail(file_, node, what + ": unknown type '" + t + "' (expected number, enum, bool or string)");
    }

    std::vector<std::string> values(const YAML::Node& list, const std::string& what) {
        yaml::require(file_, list, list.IsSequence() && list.size() > 0, what + ": 'values' must be a non-empty list");
        std::vector<std::string> out;
        std::set<std::string> seen;
        for (const auto& v : list) {
            const auto s = yaml::scalar(file_, v, what + ": enum value");
            yaml::require(file_, v, seen.insert(s).second, what + ": enum value '" + s + "' listed twice");
            out.push_back(s);
        }
        return out;
    }

    std::vector<Bin> bins(const YAML::Node& list, const std::string& what) {
        yaml::require(file_, list, list.IsSequence() && list.size() > 0, what + ": 'bins' must be a non-empty list");
        std::vector<Bin> out;
        for (const auto& node : list) {
            yaml::require(file_, node, node.IsMap() && node["label"] && node["range"],
                          what + ": a bin needs 'label' and 'range'");
            yaml::check_keys(file_, node, {"label", "range"}, what + ", bin");
            Bin b;
            b.label = yaml::scalar(file_, node["label"], what + ": bin 'label'");
            b.line = yaml::line_of(node);
            const auto problem = bins::parse_range(yaml::scalar(file_, node["range"], what + ": bin 'range'"), b);
            yaml::require(file_, node["range"], problem.empty(), what + ", bin '" + b.label + "': " + problem);
            out.push_back(std::move(b));
            const auto sequence = bins::check_sequence(out);
            yaml::require(file_, node, sequence.empty(), what + ": " + sequence);
        }
        return out;
    }
};

} // namespace

Taxonomy load_taxonomy(const std::filesystem::path& path) {
    Taxonomy tax;
    tax.source = path.string();
    const auto root = yaml::load_file(path, "ODD taxonomy");
    TaxonomyLoader loader(tax);
    try {
        loader.root(root);
    } catch (const YAML::Exception& e) {
        throw InputError(tax.source + ":" + std::to_string(e.mark.line + 1), "invalid ODD taxonomy: " + e.msg);
    }
    return tax;
}

} // namespace railodd::odd
