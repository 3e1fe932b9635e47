#include "railodd/odd/odd_spec.hpp"

#include <algorithm>

namespace railodd::odd {

const AttributeConstraint* ElementConstraint::find(const std::string& attribute) const {
    for (const auto& c : attributes) {
        if (c.attribute == attribute) {
            return &c;
        }
    }
    return nullptr;
}

const ElementConstraint* OddSpec::find(const std::string& path) const {
    for (const auto& e : elements) {
        if (e.path == path) {
            return &e;
        }
    }
    return nullptr;
}

bool admits_number(const AttributeConstraint& constraint, const Attribute& attribute, double value) {
    if ((constraint.min && value < *constraint.min) || (constraint.max && value > *constraint.max)) {
        return false;
    }
    if (constraint.bins.empty()) {
        return true;
    }
    // The value must fall into one of the allowed classes, judged with the
    // taxonomy's own bounds so that open and closed ends are honoured.
    const auto label = classify(attribute, value);
    return std::find(constraint.bins.begin(), constraint.bins.end(), label) != constraint.bins.end();
}

bool admits_value(const AttributeConstraint& constraint, const std::string& value) {
    return constraint.values.empty() ||
           std::find(constraint.values.begin(), constraint.values.end(), value) != constraint.values.end();
}

bool admits_flag(const AttributeConstraint& constraint, bool value) {
    return !constraint.value || *constraint.value == value;
}

} // namespace railodd::odd
