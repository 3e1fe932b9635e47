#pragma once
// Why a coverage item has no scenario. Internal to the scenario library.
#include "railodd/scenario/coverage.hpp"

#include <string>
#include <vector>

namespace railodd::scenario {

// The reason of a spec item the route cannot host (infrastructure it lacks).
inline constexpr const char* not_on_route = "not on the route";

// The classes a spec constraint allows (coverage.cpp).
std::vector<std::string> allowed_classes(const odd::AttributeConstraint& c, const odd::Attribute& a);

// Fills CoverageItem::reason of every gap of the route and spec lists.
void explain_gaps(Coverage& c, const odd::OddProfile& profile, const odd::Taxonomy& taxonomy,
                  const Generation& generation, const TemplateSet* templates, const odd::OddSpec* spec);

} // namespace railodd::scenario
