#include "railodd/odd/taxonomy.hpp"

#include <algorithm>

namespace railodd::odd {

const char* to_string(AttributeType type) {
    switch (type) {
    case AttributeType::number: return "number";
    case AttributeType::enumeration: return "enum";
    case AttributeType::boolean: return "bool";
    case AttributeType::string: return "string";
    }
    return "string";
}

bool Attribute::has_value(const std::string& value) const {
    return std::find(values.begin(), values.end(), value) != values.end();
}

const Element* Taxonomy::find(const std::string& path) const {
    const auto it = by_path.find(path);
    return it == by_path.end() ? nullptr : &elements[it->second];
}

const Element* Taxonomy::find_id(const std::string& id) const {
    const auto it = by_id.find(id);
    return it == by_id.end() ? nullptr : &elements[it->second];
}

std::vector<const Element*> Taxonomy::top_level() const {
    std::vector<const Element*> out;
    for (const auto& e : elements) {
        if (e.parent == Element::no_parent) {
            out.push_back(&e);
        }
    }
    return out;
}

std::vector<const Element*> Taxonomy::children(const Element& element) const {
    std::vector<const Element*> out;
    out.reserve(element.children.size());
    for (const auto i : element.children) {
        out.push_back(&elements[i]);
    }
    return out;
}

const Element* Taxonomy::parent(const Element& element) const {
    return element.parent == Element::no_parent ? nullptr : &elements[element.parent];
}

const Attribute* Taxonomy::attribute(const Element& element, const std::string& name) const {
    for (const Element* e = &element; e != nullptr; e = parent(*e)) {
        for (const auto& a : e->attributes) {
            if (a.name == name) {
                return &a;
            }
        }
    }
    return nullptr;
}

std::vector<const Attribute*> Taxonomy::attributes(const Element& element) const {
    std::vector<const Attribute*> out;
    for (const Element* e = &element; e != nullptr; e = parent(*e)) {
        for (const auto& a : e->attributes) {
            out.push_back(&a);
        }
    }
    return out;
}

std::size_t Taxonomy::attribute_count() const {
    std::size_t n = 0;
    for (const auto& e : elements) {
        n += e.attributes.size();
    }
    return n;
}

} // namespace railodd::odd
