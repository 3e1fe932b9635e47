// Reads a declared ODD (data/odd/example_odd_spec.yaml) against the taxonomy:
// a spec naming an element, attribute, enum value or bin the taxonomy does not
// know would silently admit or exclude nothing, so each is refused with its line.
#include "railodd/odd/odd_spec.hpp"

#include "yaml_support.hpp"

#include <set>

namespace railodd::odd {

namespace {

class SpecLoader {
public:
    SpecLoader(OddSpec& spec, const Taxonomy& taxonomy) : spec_(spec), tax_(taxonomy), file_(spec.source) {}

    void root(const YAML::Node& root) {
        yaml::require(file_, root, root.IsMap(), "an ODD spec must be a YAML map with an 'elements' list");
        yaml::check_keys(file_, root, {"odd_spec", "description", "taxonomy_version", "unlisted_elements", "elements"},
                         "ODD spec");
        if (root["odd_spec"]) {
            spec_.name = yaml::scalar(file_, root["odd_spec"], "'odd_spec'");
        }
        if (root["description"]) {
            spec_.description = yaml::scalar(file_, root["description"], "'description'");
        }
        if (const auto v = root["taxonomy_version"]) {
            spec_.taxonomy_version = yaml::scalar(file_, v, "'taxonomy_version'");
            yaml::require(file_, v, spec_.taxonomy_version == tax_.version,
                          "spec is written for taxonomy version '" + spec_.taxonomy_version + "' but " + tax_.source +
                              " is version '" + tax_.version + "'");
        }
        if (const auto v = root["unlisted_elements"]) {
            const auto s = yaml::scalar(file_, v, "'unlisted_elements'");
            yaml::require(file_, v, s == "inside" || s == "outside",
                          "'unlisted_elements' must be inside or outside, not '" + s + "'");
            spec_.unlisted_inside = s == "inside";
        }
        const auto list = root["elements"];
        yaml::require(file_, list ? list : root, list && list.IsSequence(), "ODD spec needs an 'elements' list");
        for (const auto& node : list) {
            spec_.elements.push_back(element(node));
        }
    }

private:
    OddSpec& spec_;
    const Taxonomy& tax_;
    const std::string file_;
    std::set<std::string> seen_;

    ElementConstraint element(const YAML::Node& node) {
        yaml::require(file_, node, node.IsMap() && node["path"], "each spec entry needs a 'path'");
        ElementConstraint c;
        c.path = yaml::scalar(file_, node["path"], "'path'");
        c.line = yaml::line_of(node);
        const auto what = "spec entry '" + c.path + "'";
        yaml::check_keys(file_, node, {"path", "allowed", "note", "attributes"}, what);
        const Element* e = tax_.find(c.path);
        yaml::require(file_, node["path"], e != nullptr,
                      "element '" + c.path + "' is not in the taxonomy " + tax_.source);
        yaml::require(file_, node["path"], seen_.insert(c.path).second, what + " is listed twice");
        c.id = e->id;
        if (const auto v = node["allowed"]) {
            c.allowed = yaml::boolean(file_, v, what + ": 'allowed'");
        }
        if (const auto v = node["note"]) {
            c.note = yaml::scalar(file_, v, what + ": 'note'");
        }
        if (const auto attrs = node["attributes"]) {
            yaml::require(file_, attrs, attrs.IsMap(), what + ": 'attributes' must map attribute names to constraints");
            yaml::require(file_, attrs, c.allowed, what + ": an element outside the ODD (allowed: false) takes no attributes");
            for (const auto& kv : attrs) {
                c.attributes.push_back(constraint(*e, kv.first, kv.second, what));
            }
        }
        return c;
    }

    AttributeConstraint constraint(const Element& e, const YAML::Node& key, const YAML::Node& node,
                                   const std::string& entry) {
        AttributeConstraint c;
        c.attribute = yaml::scalar(file_, key, entry + ": attribute name");
        c.line = yaml::line_of(key);
        const auto what = entry + ", attribute '" + c.attribute + "'";
        const Attribute* a = tax_.attribute(e, c.attribute);
        yaml::require(file_, key, a != nullptr, "element '" + e.path + "' has no attribute '" + c.attribute +
                                                    "' in the taxonomy " + tax_.source);
        c.type = a->type;
        yaml::require(file_, node, node.IsMap(), what + ": the constraint must be a map (min, max, bins, values, value)");
        yaml::check_keys(file_, node, {"min", "max", "bins", "values", "value"}, what);
        const bool number = a->type == AttributeType::number;
        for (const char* k : {"min", "max", "bins"}) {
            yaml::require(file_, node[k] ? node[k] : node, !node[k] || number,
                          what + ": '" + k + "' applies to numbers; this attribute is " + to_string(a->type));
        }
        if (node["min"]) {
            c.min = yaml::number(file_, node["min"], what + ": 'min'");
        }
        if (node["max"]) {
            c.max = yaml::number(file_, node["max"], what + ": 'max'");
        }
        yaml::require(file_, node, !(c.min && c.max && *c.min > *c.max), what + ": min is above max");
        if (const auto b = node["bins"]) {
            c.bins = labels(b, what + ": bin", [&](const std::string& s) { return has_bin(*a, s); });
        }
        if (const auto v = node["values"]) {
            const bool listable = a->type == AttributeType::enumeration || a->type == AttributeType::string;
            yaml::require(file_, v, listable, what + ": 'values' applies to enums and strings; this attribute is " +
                                                  to_string(a->type));
            c.values = labels(v, what + ": value", [&](const std::string& s) {
                return a->type == AttributeType::string || a->has_value(s);
            });
        }
        if (const auto v = node["value"]) {
            yaml::require(file_, v, a->type == AttributeType::boolean,
                          what + ": 'value' applies to bools; this attribute is " + to_string(a->type));
            c.value = yaml::boolean(file_, v, what + ": 'value'");
        }
        return c;
    }

    static bool has_bin(const Attribute& a, const std::string& label) {
        for (const auto& b : a.bins) {
            if (b.label == label) {
                return true;
            }
        }
        return false;
    }

    template <class Known>
    std::vector<std::string> labels(const YAML::Node& list, const std::string& what, Known known) {
        yaml::require(file_, list, list.IsSequence() && list.size() > 0, what + "s must be a non-empty list");
        std::vector<std::string> out;
        for (const auto& v : list) {
            const auto s = yaml::scalar(file_, v, what);
            yaml::require(file_, v, known(s), what + " '" + s + "' is not defined in the taxonomy " + tax_.source);
            out.push_back(s);
        }
        return out;
    }
};

} // namespace

OddSpec load_odd_spec(const std::filesystem::path& path, const Taxonomy& taxonomy) {
    OddSpec spec;
    spec.source = path.string();
    const auto root = yaml::load_file(path, "ODD spec");
    SpecLoader loader(spec, taxonomy);
    try {
        loader.root(root);
    } catch (const YAML::Exception& e) {
        throw InputError(spec.source + ":" + std::to_string(e.mark.line + 1), "invalid ODD spec: " + e.msg);
    }
    return spec;
}

} // namespace railodd::odd
