// check_spec(): which tagged elements of a route lie outside a declared ODD
// (the matching rules are in spec_check.hpp).
#include "railodd/odd/spec_check.hpp"

#include "text.hpp"

#include <algorithm>
#include <cmath>
#include <map>
#include <set>

namespace railodd::odd {

namespace {

// An entry covers its element and every element below it.
bool covers(const std::string& entry_path, const std::string& element_path) {
    return element_path == entry_path ||
           (element_path.size() > entry_path.size() && element_path.compare(0, entry_path.size(), entry_path) == 0 &&
            element_path[entry_path.size()] == '/');
}

std::string list_text(const std::vector<std::string>& values) {
    std::string s = "[";
    for (std::size_t i = 0; i < values.size(); ++i) {
        s += (i > 0 ? ", " : "") + values[i];
    }
    return s + "]";
}

std::string with_unit(double value, const std::string& unit) {
    return unit.empty() ? text::format(value) : text::format(value) + " " + unit;
}

// The constraint as a reader would state it: "radius >= 300 m".
std::string constraint_text(const AttributeConstraint& c, const std::string& unit) {
    std::vector<std::string> parts;
    if (c.min && c.max && *c.min == *c.max) {
        parts.push_back("= " + with_unit(*c.min, unit));
    } else {
        if (c.min) {
            parts.push_back(">= " + with_unit(*c.min, unit));
        }
        if (c.max) {
            parts.push_back("<= " + with_unit(*c.max, unit));
        }
    }
    if (!c.bins.empty()) {
        parts.push_back("in classes " + list_text(c.bins));
    }
    if (!c.values.empty()) {
        parts.push_back("in " + list_text(c.values));
    }
    if (c.value) {
        parts.push_back(*c.value ? "= true" : "= false");
    }
    std::string s = c.attribute;
    for (std::size_t i = 0; i < parts.size(); ++i) {
        s += (i > 0 ? " and " : " ") + parts[i];
    }
    return parts.empty() ? c.attribute + " (any value)" : s;
}

std::string value_text(const AttributeValue& v) {
    if (const auto* d = std::get_if<double>(&v)) {
        return text::format(*d);
    }
    if (const auto* b = std::get_if<bool>(&v)) {
        return *b ? "true" : "false";
    }
    return std::get<std::string>(v);
}

enum class Judgement { inside, outside, unknown };

// One attribute value against one constraint; a value of the wrong type for
// the constraint cannot be judged (unknown).
Judgement judge(const AttributeConstraint& c, const Attribute& attribute, const AttributeValue& v) {
    switch (c.type) {
    case AttributeType::number:
        if (const auto* d = std::get_if<double>(&v)) {
            return admits_number(c, attribute, *d) ? Judgement::inside : Judgement::outside;
        }
        return Judgement::unknown;
    case AttributeType::boolean:
        if (const auto* b = std::get_if<bool>(&v)) {
            return admits_flag(c, *b) ? Judgement::inside : Judgement::outside;
        }
        return Judgement::unknown;
    case AttributeType::enumeration:
    case AttributeType::string:
        if (const auto* s = std::get_if<std::string>(&v)) {
            return admits_value(c, *s) ? Judgement::inside : Judgement::outside;
        }
        return Judgement::unknown;
    }
    return Judgement::unknown;
}

SpecViolation violation_at(const TaggedElement& e) {
    SpecViolation v;
    static_cast<MapPlace&>(v) = e;
    v.element = e.element;
    return v;
}

// Applies one covering entry to one element; returns whether it rejected it.
bool apply_entry(const ElementConstraint& entry, const TaggedElement& e, const Taxonomy& taxonomy,
                 SpecEntryCount& count, std::vector<SpecViolation>& out) {
    ++count.matched;
    if (!entry.allowed) {
        SpecViolation v = violation_at(e);
        v.spec_element = entry.path;
        v.constraint = "not allowed";
        v.note = entry.note;
        v.spec_line = entry.line;
        out.push_back(std::move(v));
        ++count.outside;
        return true;
    }
    static const Attribute no_attribute;
    const Element* spec_element = taxonomy.find(entry.path);
    bool rejected = false;
    bool unknown = false;
    for (const auto& c : entry.attributes) {
        const Attribute* declared = spec_element ? taxonomy.attribute(*spec_element, c.attribute) : nullptr;
        const Attribute& attribute = declared ? *declared : no_attribute;
        const AttributeValue* value = e.find(c.attribute);
        const Judgement j = value ? judge(c, attribute, *value) : Judgement::unknown;
        if (j == Judgement::unknown) {
            unknown = true;
            if (std::find(count.unknown_attributes.begin(), count.unknown_attributes.end(), c.attribute) ==
                count.unknown_attributes.end()) {
                count.unknown_attributes.push_back(c.attribute);
            }
        } else if (j == Judgement::outside) {
            SpecViolation v = violation_at(e);
            v.spec_element = entry.path;
            v.attribute = c.attribute;
            v.value = value_text(*value);
            v.unit = attribute.unit;
            v.constraint = constraint_text(c, attribute.unit);
            v.note = entry.note;
            v.spec_line = c.line > 0 ? c.line : entry.line;
            out.push_back(std::move(v));
            rejected = true;
        }
    }
    count.outside += rejected ? 1 : 0;
    count.unknown += unknown ? 1 : 0;
    return rejected;
}

struct Interval {
    std::size_t track;
    double start;
    double end;
    std::string road_id;
    std::string element;
    std::size_t violations;
};

// Outside elements merged into stretches per track where they touch or overlap
// (1 mm tolerance, the precision chainages are written with).
std::vector<OutsideStretch> merge_stretches(std::vector<Interval> intervals) {
    std::stable_sort(intervals.begin(), intervals.end(), [](const Interval& a, const Interval& b) {
        return a.track != b.track ? a.track < b.track : a.start < b.start;
    });
    std::vector<OutsideStretch> stretches;
    std::vector<std::set<std::string>> element_sets;
    for (const auto& iv : intervals) {
        if (stretches.empty() || stretches.back().track != iv.track || iv.start > stretches.back().chainage_end + 1e-3) {
            stretches.push_back({iv.track, iv.start, iv.end, {}, {}, 0});
            element_sets.emplace_back();
        }
        auto& s = stretches.back();
        s.chainage_end = std::max(s.chainage_end, iv.end);
        if (std::find(s.road_ids.begin(), s.road_ids.end(), iv.road_id) == s.road_ids.end()) {
            s.road_ids.push_back(iv.road_id);
        }
        element_sets.back().insert(iv.element);
        s.violations += iv.violations;
    }
    for (std::size_t i = 0; i < stretches.size(); ++i) {
        stretches[i].elements.assign(element_sets[i].begin(), element_sets[i].end());
    }
    return stretches;
}

} // namespace

SpecVerdict check_spec(const OddProfile& profile, const OddSpec& spec, const Taxonomy& taxonomy) {
    SpecVerdict verdict;
    verdict.spec_name = spec.name;
    verdict.spec_source = spec.source;
    for (const auto& entry : spec.elements) {
        verdict.entries.push_back({entry.path, entry.line, 0, 0, 0, {}});
    }
    std::vector<Interval> intervals;
    for (const auto& e : profile.elements) {
        ++verdict.elements_checked;
        const std::size_t before = verdict.violations.size();
        bool listed = false;
        for (std::size_t i = 0; i < spec.elements.size(); ++i) {
            if (covers(spec.elements[i].path, e.element)) {
                listed = true;
                apply_entry(spec.elements[i], e, taxonomy, verdict.entries[i], verdict.violations);
            }
        }
        if (!listed) {
            ++verdict.elements_unlisted;
            if (!spec.unlisted_inside) {
                SpecViolation v = violation_at(e);
                v.constraint = "not listed (unlisted_elements: outside)";
                verdict.violations.push_back(std::move(v));
            }
        }
        const std::size_t added = verdict.violations.size() - before;
        if (added > 0) {
            ++verdict.elements_outside;
            intervals.push_back({e.track, std::min(e.chainage_start, e.chainage_end),
                                 std::max(e.chainage_start, e.chainage_end), e.road_id, e.element, added});
        }
    }
    for (auto& c : verdict.entries) {
        std::sort(c.unknown_attributes.begin(), c.unknown_attributes.end());
    }
    verdict.stretches = merge_stretches(std::move(intervals));
    verdict.passed = verdict.violations.empty();
    return verdict;
}

} // namespace railodd::odd
