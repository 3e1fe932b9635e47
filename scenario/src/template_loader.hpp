#pragma once
// The template file's reader, shared by template_loader.cpp (the file, the
// template, its anchor, ego, actors, constraints) and template_parameters.cpp
// (parameters, perturbations, degraded modes). Internal to the scenario
// library.
#include "railodd/scenario/catalog.hpp"
#include "railodd/scenario/templates.hpp"

#include "attribute_values.hpp"
#include "environment.hpp"
#include "railodd/util/yaml_support.hpp"

#include <algorithm>
#include <cmath>
#include <initializer_list>
#include <set>
#include <string>
#include <string_view>
#include <vector>

namespace railodd::scenario::detail {

class TemplateLoader {
public:
    TemplateLoader(TemplateSet& set, const odd::Taxonomy& taxonomy, const Catalog& catalog)
        : set_(set), tax_(taxonomy), cat_(catalog), file_(set.source) {}

    void root(const YAML::Node& root);

private:
    TemplateSet& set_;
    const odd::Taxonomy& tax_;
    const Catalog& cat_;
    const std::string file_;

    void degraded_modes(const YAML::Node& map);
    // One per parameter kind, filling p from its spec (w names it in errors).
    void ego_speed_parameter(const YAML::Node& spec, const std::string& w, ParameterDomain& p);
    void asset_parameter(const YAML::Node& spec, const Template& t, const std::string& w, ParameterDomain& p);
    void map_parameter(const YAML::Node& spec, const Template& t, const std::string& w, ParameterDomain& p);
    void choice_parameter(const YAML::Node& spec, const Template& t, const std::string& w, ParameterDomain& p);
    void mode_parameter(const YAML::Node& spec, const std::string& w, ParameterDomain& p);
    ModeSetting mode_setting(const YAML::Node& node, const std::string& what);

    Template one(const YAML::Node& node);

    const odd::Element& element(const YAML::Node& at, const std::string& path, const std::string& what);

    const odd::Attribute& attribute(const YAML::Node& at, const odd::Element& e, const std::string& name,
                                    const std::string& what);

    std::vector<std::string> value_list(const YAML::Node& v, const std::string& what);

    // A number in [lo, hi]: a negative distance or a speed written as "0"
    // in the .xosc makes a scenario that cannot play as its template says.
    double in_range(const YAML::Node& v, double lo, double hi, const std::string& what);

    ElementMatch match(const YAML::Node& node, const std::string& what, std::initializer_list<std::string_view> keys);

    AttributeCondition condition(const std::pair<YAML::Node, YAML::Node>& kv, const odd::Element& e,
                                 const std::string& what);

    void ego(const YAML::Node& node, Template& t, const std::string& what);

    Lateral lateral(const YAML::Node& v, const std::string& what);

    ActorTemplate actor(const YAML::Node& node, const Template& t, const std::string& what);

    void parameters(const YAML::Node& node, Template& t, const std::string& what);
    ParameterDomain parameter(const std::string& name, const YAML::Node& spec, const Template& t, const std::string& what);
    ParameterDomain perturbation(const std::string& name, const YAML::Node& spec, const std::string& what);
    void constraints(const YAML::Node& node, Template& t, const std::string& what);
    void placeholders(const YAML::Node& at, Template& t, const std::string& what);
};

} // namespace railodd::scenario::detail
