// A gap is only useful with its reason: an engineer acts differently on
// "the route has no such place", "the places are too short for a run",
// "no template tests it" and "the ODD excludes it".
#include "coverage_gaps.hpp"

#include "attribute_values.hpp"
#include "railodd/scenario/anchors.hpp"

#include <algorithm>
#include <set>

namespace railodd::scenario {

namespace {

bool under(const std::string& path, const std::string& element) {
    return path == element || path.rfind(element + "/", 0) == 0;
}

// Whether the profile element is the item: its element, and the class of the
// item's attribute.
bool is_item(const odd::TaggedElement& e, const CoverageItem& item, const odd::Taxonomy& tax) {
    if (e.element != item.element) {
        return false;
    }
    if (item.attribute.empty()) {
        return true;
    }
    const auto* v = e.find(item.attribute);
    const odd::Element* el = tax.find(e.element);
    const odd::Attribute* a = el ? tax.attribute(*el, item.attribute) : nullptr;
    return v && a && value_class(*a, text_of(*v)) == item.value_class;
}

// Whether the spec leaves the item outside the declared ODD.
bool excluded_by(const odd::OddSpec& spec, const CoverageItem& item, const odd::Taxonomy& tax) {
    const odd::ElementConstraint* e = nullptr;
    for (const auto& c : spec.elements) {
        if (under(item.element, c.path) && (!e || c.path.size() > e->path.size())) {
            e = &c;
        }
    }
    if (!e) {
        return !spec.unlisted_inside;
    }
    if (!e->allowed) {
        return true;
    }
    const odd::AttributeConstraint* c = item.attribute.empty() ? nullptr : e->find(item.attribute);
    const odd::Element* el = tax.find(item.element);
    const odd::Attribute* a = el && c ? tax.attribute(*el, item.attribute) : nullptr;
    if (!a) {
        return false;
    }
    const auto classes = allowed_classes(*c, *a);
    return std::find(classes.begin(), classes.end(), item.value_class) == classes.end();
}

// Whether some template varies a value of the item (a perturbation, a
// degraded mode's setting): none, only in values no valid row holds, or in
// some value a row can hold.
enum class Varied { none, only_infeasible, feasible };

Varied varied_by(const TemplateSet& templates, const Generation& g, const CoverageItem& item, const odd::Taxonomy& tax) {
    const odd::Element* el = tax.find(item.element);
    const odd::Attribute* a = el && !item.attribute.empty() ? tax.attribute(*el, item.attribute) : nullptr;
    auto holds = [&](const std::string& element, const std::string& attribute, const std::string& value) {
        return under(element, item.element) &&
               (item.attribute.empty() || (attribute == item.attribute && a && value_class(*a, value) == item.value_class));
    };
    Varied out = Varied::none;
    for (std::size_t t = 0; t < templates.templates.size() && t < g.runs.size(); ++t) {
        const auto& bad = g.runs[t].infeasible_values;
        for (const auto& p : templates.templates[t].parameters) {
            for (std::size_t v = 0; v < p.values.size(); ++v) {
                bool hit = p.kind == ParameterKind::perturbation && holds(p.element, p.attribute, p.values[v]);
                for (std::size_t k = 0; v < p.modes.size() && k < p.modes[v].sets.size(); ++k) {
                    const ModeSetting& s = p.modes[v].sets[k];
                    hit = hit || holds(s.element, s.attribute, s.value);
                }
                if (!hit) {
                    continue;
                }
                const bool feasible = std::find(bad.begin(), bad.end(), std::pair{p.name, p.values[v]}) == bad.end();
                out = feasible ? Varied::feasible : (out == Varied::none ? Varied::only_infeasible : out);
            }
        }
    }
    return out;
}

// An item no template anchors on (a line usage, a gauge) is exercised by the
// anchors lying on its stretches; where every such place was skipped, say so.
std::string places_on_it(const CoverageItem& item, const odd::OddProfile& profile, const odd::Taxonomy& tax,
                         const Generation& g, const TemplateSet& templates) {
    std::vector<const odd::TaggedElement*> stretches;
    for (const auto& e : profile.elements) {
        if (!e.point && is_item(e, item, tax)) {
            stretches.push_back(&e);
        }
    }
    std::size_t skipped = 0;
    std::string example;
    for (std::size_t t = 0; t < templates.templates.size() && t < g.runs.size(); ++t) {
        for (const auto& s : g.runs[t].skipped) {
            const auto& at = profile.elements[s.element];
            for (const auto* e : stretches) {
                if (at.track == e->track && at.chainage_start >= e->chainage_start && at.chainage_start <= e->chainage_end) {
                    ++skipped;
                    example = example.empty() ? templates.templates[t].id + ": " + s.reason : example;
                    break;
                }
            }
        }
    }
    if (skipped > 0) {
        return "no anchor on the route: no template anchors on this element, and the " + std::to_string(skipped) +
               " place(s) of other templates on it were skipped, e.g. " + example;
    }
    return "no template anchors on this element, and no scenario's anchor lies on it";
}

std::string route_gap(const CoverageItem& item, const odd::OddProfile& profile, const odd::Taxonomy& tax,
                      const Generation& g, const TemplateSet& templates) {
    std::vector<std::string> anchored, drawn_none, infeasible_in;
    std::string skip;
    std::size_t skipped = 0, infeasible = 0;
    for (std::size_t t = 0; t < templates.templates.size() && t < g.runs.size(); ++t) {
        const Template& tm = templates.templates[t];
        if (!under(item.element, tm.anchor.element)) {
            continue;
        }
        anchored.push_back(tm.id);
        // The item's places for this template, and which of them could not be used.
        std::set<std::size_t> places, unusable;
        for (std::size_t i = 0; i < profile.elements.size(); ++i) {
            if (is_item(profile.elements[i], item, tax) && matches(profile.elements[i], tm.anchor)) {
                places.insert(i);
            }
        }
        for (const auto& s : g.runs[t].skipped) {
            if (places.contains(s.element)) {
                ++skipped;
                skip = skip.empty() ? s.reason : skip;
                unusable.insert(s.element);
            }
        }
        for (const auto i : g.runs[t].infeasible) {
            if (places.contains(i)) {
                ++infeasible;
                infeasible_in.push_back(tm.id);
                unusable.insert(i);
            }
        }
        if (places.size() > unusable.size()) {
            drawn_none.push_back(tm.id);
        }
    }
    if (!drawn_none.empty()) {
        return "not drawn: the strategy chose no anchor of " + drawn_none.front() + " there (--count, --max-anchors)";
    }
    if (infeasible > 0) {
        return "constraint infeasible: at " + std::to_string(infeasible) + " place(s) " + infeasible_in.front() +
               "'s constraints admit no row (e.g. every ego speed above the speed limit there, or above what the "
               "trains can run)";
    }
    if (skipped > 0) {
        return "no anchor on the route: " + std::to_string(skipped) + " place(s) skipped, e.g. " + skip;
    }
    if (!anchored.empty()) {
        return "no template for this class: " + anchored.front() + " anchors here but its conditions exclude it";
    }
    return places_on_it(item, profile, tax, g, templates);
}

} // namespace

void explain_gaps(Coverage& c, const odd::OddProfile& profile, const odd::Taxonomy& taxonomy,
                  const Generation& generation, const TemplateSet* templates, const odd::OddSpec* spec) {
    for (auto& item : c.route) {
        if (item.scenarios > 0) {
            continue;
        }
        if (spec && excluded_by(*spec, item, taxonomy)) {
            item.reason = "excluded by the ODD spec";
        } else if (templates) {
            item.reason = route_gap(item, profile, taxonomy, generation, *templates);
        }
    }
    for (auto& item : c.spec) {
        if (item.scenarios > 0) {
            continue;
        }
        const bool infrastructure = item.element.rfind("Scenery/", 0) == 0 ||
                                    item.element.rfind("Operational Conditions/", 0) == 0;
        if (infrastructure && item.on_route == 0) {
            item.reason = not_on_route;
        } else if (item.on_route > 0 && templates) {
            item.reason = route_gap(item, profile, taxonomy, generation, *templates);
        } else if (templates) {
            switch (varied_by(*templates, generation, item, taxonomy)) {
            case Varied::feasible: item.reason = "not drawn: a template varies it, but no chosen row (--count) holds it"; break;
            case Varied::only_infeasible:
                item.reason = "constraint infeasible: the templates that vary it exclude every row holding it";
                break;
            case Varied::none: item.reason = "no template varies it"; break;
            }
        }
    }
}

} // namespace railodd::scenario
