#pragma once
// Perturbations (Environmental Conditions of the taxonomy) as OpenSCENARIO
// environment values: which element attributes have a mapping, and applying
// one value to an Environment.
#include "railodd/scenario/concrete.hpp"

#include <string>

namespace railodd::scenario {

// Whether the writer can express the attribute of the taxonomy element (by id,
// e.g. "en.wx.rain", "intensity") in an OpenSCENARIO Environment.
bool environment_supports(const std::string& element_id, const std::string& attribute);

// Sets the part of `env` the value stands for; the value was checked against
// the taxonomy. Throws std::invalid_argument for an unsupported attribute.
void apply_perturbation(Environment& env, const std::string& element_id, const std::string& attribute,
                        const std::string& value);

// The readable list of supported "element id / attribute" pairs, for messages.
std::string supported_perturbations();

} // namespace railodd::scenario
