#pragma once
// ODD coverage of a scenario set (coverage.json and its table, docs/scenarios.md
// "Coverage"): which elements and attribute classes present on the route, or
// declared in an ODD spec, some scenario exercises, the pairwise coverage of
// each template's parameter values, and the gaps.
#include "railodd/odd/odd_spec.hpp"
#include "railodd/odd/profile.hpp"
#include "railodd/odd/taxonomy.hpp"
#include "railodd/scenario/generator.hpp"
#include "railodd/scenario/templates.hpp"

#include <cstddef>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

namespace railodd::scenario {

// One element, or one class of one of its attributes (bin label, enum value, bool).
struct CoverageItem {
    std::string element;
    std::string attribute; // empty: the element itself
    std::string value_class;
    std::size_t on_route = 0;  // profile elements with it
    std::size_t scenarios = 0; // scenarios exercising it
    std::string reason;        // why no scenario does (gaps only; coverage_gaps.cpp)
};

struct Coverage {
    std::vector<CoverageItem> route; // everything the route's profile has, taxonomy order
    std::vector<CoverageItem> spec;  // everything an ODD spec allows, when one was given
    // What the scenarios add beyond the map (assets, perturbations, the ego's
    // speed): Dynamic Elements and Environmental Conditions, taxonomy order.
    std::vector<CoverageItem> exercised;
    std::string spec_name;
    std::vector<TemplateRun> runs;   // pairwise coverage per template
    std::size_t scenarios = 0;
};

// With the templates, every gap says why: no anchor on the route (and the
// skip reason), excluded by the spec, no template, not drawn, constraints.
Coverage compute_coverage(const odd::OddProfile& profile, const odd::Taxonomy& taxonomy, const Generation& generation,
                          const odd::OddSpec* spec, const TemplateSet* templates = nullptr);

nlohmann::ordered_json coverage_json(const Coverage& c);
std::string coverage_table(const Coverage& c);

} // namespace railodd::scenario
