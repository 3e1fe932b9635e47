// Coverage is counted per attribute class, not per value: a scenario at a
// 450 m curve covers the radius class the taxonomy puts 450 m in, which is the
// granularity an ODD is declared and profiled at.
#include "railodd/scenario/coverage.hpp"

#include "attribute_values.hpp"
#include "coverage_gaps.hpp"

#include <map>
#include <set>
#include <tuple>

namespace railodd::scenario {

namespace {

using Key = std::tuple<std::string, std::string, std::string>; // element, attribute, class

std::map<Key, std::size_t> route_items(const odd::OddProfile& profile, const odd::Taxonomy& tax) {
    std::map<Key, std::size_t> items;
    for (const auto& e : profile.elements) {
        ++items[{e.element, "", ""}];
        const odd::Element* el = tax.find(e.element);
        for (const auto& attr : e.attributes) {
            const odd::Attribute* a = el ? tax.attribute(*el, attr.name) : nullptr;
            if (a && countable(*a)) {
                ++items[{e.element, attr.name, value_class(*a, text_of(attr.value))}];
            }
        }
    }
    return items;
}

// Per item, the scenarios exercising it (each scenario counted once); with
// `beyond_map`, only what assets, perturbations and parameters contribute.
std::map<Key, std::size_t> scenario_items(const Generation& g, const odd::Taxonomy& tax, bool beyond_map = false) {
    std::map<Key, std::size_t> items;
    for (const auto& s : g.scenarios) {
        std::set<Key> seen;
        for (const auto& v : s.odd_elements) {
            const odd::Element* el = tax.find(v.element);
            const odd::Attribute* a = el && !v.attribute.empty() ? tax.attribute(*el, v.attribute) : nullptr;
            if (!v.attribute.empty() && (!a || !countable(*a))) {
                continue;
            }
            if (!beyond_map || v.source != "map") {
                seen.insert({v.element, v.attribute, v.value_class});
            }
        }
        for (const auto& k : seen) {
            ++items[k];
        }
    }
    return items;
}

} // namespace

// The classes a spec constraint allows: its listed values or bins, or the
// attribute's bins its range overlaps, or all of the attribute's classes.
std::vector<std::string> allowed_classes(const odd::AttributeConstraint& c, const odd::Attribute& a) {
    if (a.type == odd::AttributeType::boolean) {
        return c.value ? std::vector<std::string>{*c.value ? "true" : "false"} : std::vector<std::string>{"true", "false"};
    }
    if (a.type != odd::AttributeType::number) {
        return c.values.empty() ? a.values : c.values;
    }
    if (!c.bins.empty()) {
        return c.bins;
    }
    std::vector<std::string> out;
    for (const auto& b : a.bins) {
        if ((!c.min || b.upper > *c.min || (b.upper == *c.min && b.upper_closed)) &&
            (!c.max || b.lower < *c.max || (b.lower == *c.max && b.lower_closed))) {
            out.push_back(b.label);
        }
    }
    return out;
}

namespace {

bool under(const std::string& path, const std::string& element) {
    return path == element || path.rfind(element + "/", 0) == 0;
}

std::size_t scenarios_under(const std::map<Key, std::size_t>& covered, const Key& item) {
    std::size_t n = 0;
    for (const auto& [k, count] : covered) {
        if (under(std::get<0>(k), std::get<0>(item)) && std::get<1>(k) == std::get<1>(item) &&
            std::get<2>(k) == std::get<2>(item)) {
            n = std::max(n, count);
        }
    }
    return n;
}

std::vector<CoverageItem> spec_items(const odd::OddSpec& spec, const odd::Taxonomy& tax,
                                     const std::map<Key, std::size_t>& route, const std::map<Key, std::size_t>& covered) {
    std::vector<CoverageItem> out;
    auto add = [&](const std::string& element, const std::string& attribute, const std::string& klass) {
        const Key k{element, attribute, klass};
        const auto r = route.find(k);
        out.push_back({element, attribute, klass, r == route.end() ? 0 : r->second, scenarios_under(covered, k), {}});
    };
    for (const auto& e : spec.elements) {
        const odd::Element* el = tax.find(e.path);
        if (!e.allowed || !el) {
            continue;
        }
        add(e.path, "", "");
        for (const auto& c : e.attributes) {
            const odd::Attribute* a = tax.attribute(*el, c.attribute);
            if (a && countable(*a)) {
                for (const auto& klass : allowed_classes(c, *a)) {
                    add(e.path, c.attribute, klass);
                }
            }
        }
    }
    return out;
}

} // namespace

Coverage compute_coverage(const odd::OddProfile& profile, const odd::Taxonomy& taxonomy, const Generation& generation,
                          const odd::OddSpec* spec, const TemplateSet* templates) {
    Coverage c;
    c.scenarios = generation.scenarios.size();
    c.runs = generation.runs;
    const auto route = route_items(profile, taxonomy);
    const auto covered = scenario_items(generation, taxonomy);
    // Taxonomy order, so the table reads like the taxonomy file.
    for (const auto& el : taxonomy.elements) {
        for (auto it = route.lower_bound({el.path, "", ""}); it != route.end() && std::get<0>(it->first) == el.path; ++it) {
            const auto s = covered.find(it->first);
            c.route.push_back({el.path, std::get<1>(it->first), std::get<2>(it->first), it->second,
                               s == covered.end() ? 0 : s->second, {}});
        }
    }
    const auto beyond = scenario_items(generation, taxonomy, true);
    for (const auto& el : taxonomy.elements) {
        for (auto it = beyond.lower_bound({el.path, "", ""}); it != beyond.end() && std::get<0>(it->first) == el.path;
             ++it) {
            const auto r = route.find(it->first);
            c.exercised.push_back({el.path, std::get<1>(it->first), std::get<2>(it->first),
                                   r == route.end() ? 0 : r->second, it->second, {}});
        }
    }
    if (spec) {
        c.spec_name = spec->name;
        c.spec = spec_items(*spec, taxonomy, route, covered);
    }
    explain_gaps(c, profile, taxonomy, generation, templates, spec);
    return c;
}

} // namespace railodd::scenario
