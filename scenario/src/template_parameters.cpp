// Parameters, perturbations and degraded modes of the template file
// (docs/scenarios.md "Templates", "Degraded modes"), each checked against the
// taxonomy and the catalog.
#include "template_loader.hpp"

namespace railodd::scenario::detail {

namespace {

// Representative values of each class of a numeric attribute: the middle of a
// closed range, twice the bound of an open-ended one.
std::vector<std::string> class_values(const odd::Attribute& a) {
    std::vector<std::string> out;
    for (const auto& b : a.bins) {
        double v = 0.5 * (b.lower + b.upper);
        if (!std::isfinite(b.upper)) {
            v = b.lower > 0.0 ? 2.0 * b.lower : b.lower + 1.0;
        } else if (!std::isfinite(b.lower)) {
            v = b.upper - std::max(1.0, std::abs(b.upper));
        }
        out.push_back(format_number(v));
    }
    return out;
}

} // namespace

// degraded_modes: {ID: {family, text, sets: [{element, attribute, value}]}}
void TemplateLoader::degraded_modes(const YAML::Node& map) {
    yaml::require(file_, map, map.IsMap(), "'degraded_modes' must map mode ids to {family, text, sets}");
    for (const auto& kv : map) {
        DegradedMode m;
        m.id = yaml::name(file_, kv.first, "degraded mode id");
        m.line = yaml::line_of(kv.first);
        const std::string w = "degraded mode '" + m.id + "'";
        for (const auto& other : set_.degraded_modes) {
            yaml::require(file_, kv.first, other.id != m.id, w + " is listed twice");
        }
        yaml::require(file_, kv.second, kv.second.IsMap() && kv.second["family"] && kv.second["text"],
                      w + " needs a 'family' and a 'text'");
        yaml::check_keys(file_, kv.second, {"family", "text", "sets"}, w);
        m.family = yaml::scalar(file_, kv.second["family"], w + ": 'family'");
        static const std::set<std::string> families{"none", "perception", "positioning", "communication", "adhesion"};
        yaml::require(file_, kv.second["family"], families.contains(m.family),
                      w + ": family must be none, perception, positioning, communication or adhesion, not '" + m.family + "'");
        m.text = yaml::scalar(file_, kv.second["text"], w + ": 'text'");
        if (const auto sets = kv.second["sets"]) {
            yaml::require(file_, sets, sets.IsSequence(), w + ": 'sets' must be a list of {element, attribute, value}");
            for (const auto& item : sets) {
                m.sets.push_back(mode_setting(item, w));
            }
        }
        yaml::require(file_, kv.second, m.family == "none" || !m.sets.empty(), w + ": 'sets' names no ODD value");
        set_.degraded_modes.push_back(std::move(m));
    }
}

ModeSetting TemplateLoader::mode_setting(const YAML::Node& node, const std::string& what) {
    yaml::require(file_, node, node.IsMap() && node["element"] && node["attribute"] && node["value"],
                  what + ": each setting needs an 'element', an 'attribute' and a 'value'");
    yaml::check_keys(file_, node, {"element", "attribute", "value"}, what + ": setting");
    ModeSetting s;
    s.element = yaml::scalar(file_, node["element"], what + ": 'element'");
    const odd::Element& e = element(node["element"], s.element, what);
    yaml::require(file_, node["element"],
                  s.element.rfind("Environmental Conditions/", 0) == 0 || s.element.rfind("Connectivity/", 0) == 0,
                  what + ": element '" + s.element + "' is not an Environmental Condition or Connectivity");
    s.attribute = yaml::scalar(file_, node["attribute"], what + ": 'attribute'");
    const odd::Attribute& a = attribute(node["attribute"], e, s.attribute, what);
    s.value = yaml::scalar(file_, node["value"], what + ": 'value'");
    const auto problem = check_value(a, s.value);
    yaml::require(file_, node["value"], problem.empty(), what + ": " + problem);
    s.environment = environment_supports(e.id, s.attribute);
    return s;
}

void TemplateLoader::parameters(const YAML::Node& node, Template& t, const std::string& what) {
    std::set<std::string> names;
    for (const char* section : {"parameters", "perturbations"}) {
        const auto map = node[section];
        if (!map) {
            continue;
        }
        yaml::require(file_, map, map.IsMap(), what + ": '" + section + "' must map placeholder names to domains");
        for (const auto& kv : map) {
            const auto name = kv.first.Scalar();
            yaml::require(file_, kv.first, names.insert(name).second, what + ": parameter '" + name + "' is declared twice");
            t.parameters.push_back(std::string(section) == "parameters" ? parameter(name, kv.second, t, what)
                                                                       : perturbation(name, kv.second, what));
            t.parameters.back().line = yaml::line_of(kv.first);
        }
    }
}

ParameterDomain TemplateLoader::parameter(const std::string& name, const YAML::Node& spec, const Template& t,
                                          const std::string& what) {
    const std::string w = what + ": parameter '" + name + "'";
    yaml::require(file_, spec, spec.IsMap() && spec["kind"],
                  w + " needs a 'kind' (ego_speed, asset, map, choice or degraded_mode)");
    yaml::check_keys(file_, spec, {"kind", "values", "limit_fractions", "actor", "from", "attribute"}, w);
    ParameterDomain p;
    p.name = name;
    const auto kind = yaml::scalar(file_, spec["kind"], w + ": 'kind'");
    if (kind == "ego_speed") {
        ego_speed_parameter(spec, w, p);
    } else if (kind == "asset") {
        asset_parameter(spec, t, w, p);
    } else if (kind == "map") {
        map_parameter(spec, t, w, p);
    } else if (kind == "choice") {
        choice_parameter(spec, t, w, p);
    } else if (kind == "degraded_mode") {
        mode_parameter(spec, w, p);
    } else {
        yaml::fail(file_, spec["kind"],
                   w + ": kind must be ego_speed, asset, map, choice or degraded_mode, not '" + kind + "'");
    }
    return p;
}

void TemplateLoader::ego_speed_parameter(const YAML::Node& spec, const std::string& w, ParameterDomain& p) {
    p.kind = ParameterKind::ego_speed;
    const odd::Element& ego = element(spec, "Dynamic Elements/Rail vehicle/Ego train", w);
    const odd::Attribute& speed = attribute(spec, ego, "speed", w);
    p.unit = speed.unit;
    yaml::require(file_, spec, static_cast<bool>(spec["values"]) != static_cast<bool>(spec["limit_fractions"]),
                  w + " takes either 'values' (km/h) or 'limit_fractions' (of the local speed limit)");
    if (spec["values"]) {
        p.values = value_list(spec["values"], w + ": 'values'");
        for (const auto& v : p.values) {
            const auto problem = check_value(speed, v);
            yaml::require(file_, spec["values"], problem.empty() && parse_number(v) > 0.0,
                          w + ": speed " + (problem.empty() ? v + " must be positive" : problem));
        }
    } else {
        for (const auto& v : value_list(spec["limit_fractions"], w + ": 'limit_fractions'")) {
            const auto f = parse_number(v);
            yaml::require(file_, spec["limit_fractions"], f && *f > 0.0 && *f <= 1.5,
                          w + ": limit fraction '" + v + "' must be a number in (0, 1.5]");
            p.limit_fractions.push_back(*f);
            p.values.push_back(v + " x limit");
        }
    }
}

void TemplateLoader::asset_parameter(const YAML::Node& spec, const Template& t, const std::string& w, ParameterDomain& p) {
    p.kind = ParameterKind::actor_asset;
    yaml::require(file_, spec, static_cast<bool>(spec["actor"]), w + ": an asset parameter names its 'actor'");
    p.actor = yaml::scalar(file_, spec["actor"], w + ": 'actor'");
    const ActorTemplate* actor = nullptr;
    for (const auto& a : t.actors) {
        actor = a.name == p.actor ? &a : actor;
    }
    const std::string klass = p.actor == "Ego" ? t.ego.asset_class : actor ? actor->asset_class : "";
    yaml::require(file_, spec["actor"], p.actor == "Ego" || actor, w + ": the template has no actor '" + p.actor + "'");
    if (spec["values"]) {
        p.values = value_list(spec["values"], w + ": 'values'");
        for (const auto& id : p.values) {
            const Asset* a = cat_.find(id);
            yaml::require(file_, spec["values"], a != nullptr, w + ": asset '" + id + "' is not in the catalog " + cat_.source);
            yaml::require(file_, spec["values"], !cat_.under(klass).empty() && (a->element == klass || a->element.rfind(klass + "/", 0) == 0),
                          w + ": asset '" + id + "' (" + a->element + ") is not under the actor's class '" + klass + "'");
        }
    } else {
        for (const Asset* a : cat_.under(klass)) {
            p.values.push_back(a->id);
        }
    }
}

void TemplateLoader::map_parameter(const YAML::Node& spec, const Template& t, const std::string& w, ParameterDomain& p) {
    p.kind = ParameterKind::map_value;
    yaml::require(file_, spec, spec["attribute"] && spec["from"], w + ": a map parameter needs 'from' and 'attribute'");
    const auto from = yaml::scalar(file_, spec["from"], w + ": 'from'");
    const ElementMatch* source = nullptr;
    if (from == "anchor") {
        source = &t.anchor;
    } else if (from.rfind("context", 0) == 0) {
        // "context N": one space, then a whole index ("context 0.5" or "contexts0" are not indices).
        const double index =
            (from.size() > 8 && from[7] == ' ' ? parse_number(from.substr(8)) : std::nullopt).value_or(-1.0);
        yaml::require(file_, spec["from"],
                      index >= 0 && index == std::floor(index) && index < static_cast<double>(t.context.size()),
                      w + ": 'from' must be anchor or context N with N < " + std::to_string(t.context.size()));
        p.context = static_cast<int>(index);
        source = &t.context[static_cast<std::size_t>(p.context)];
    } else {
        yaml::fail(file_, spec["from"], w + ": 'from' must be anchor or context N, not '" + from + "'");
    }
    p.element = source->element;
    p.attribute = yaml::scalar(file_, spec["attribute"], w + ": 'attribute'");
    p.unit = attribute(spec["attribute"], element(spec, p.element, w), p.attribute, w).unit;
}

void TemplateLoader::choice_parameter(const YAML::Node& spec, const Template& t, const std::string& w,
                                      ParameterDomain& p) {
    p.kind = ParameterKind::choice;
    std::vector<std::string> actors{"Ego"};
    for (const auto& a : t.actors) {
        actors.push_back(a.name);
    }
    const std::string osc_name = osc_parameter_name(p.name);
    yaml::require(file_, spec, !is_reserved_parameter(osc_name, actors),
                  w + ": its OpenSCENARIO name '" + osc_name + "' is one railodd declares itself; choose another name");
    yaml::require(file_, spec, static_cast<bool>(spec["values"]), w + ": a choice lists its 'values'");
    p.values = value_list(spec["values"], w + ": 'values'");
    std::set<std::string> seen;
    for (const auto& v : p.values) {
        yaml::require(file_, spec["values"], seen.insert(v).second, w + ": value '" + v + "' is listed twice");
    }
}

void TemplateLoader::mode_parameter(const YAML::Node& spec, const std::string& w, ParameterDomain& p) {
    p.kind = ParameterKind::degraded_mode;
    yaml::require(file_, spec, !set_.degraded_modes.empty(),
                  w + ": the template file declares no 'degraded_modes'");
    if (spec["values"]) {
        for (const auto& id : value_list(spec["values"], w + ": 'values'")) {
            const auto m = std::find_if(set_.degraded_modes.begin(), set_.degraded_modes.end(),
                                        [&](const DegradedMode& d) { return d.id == id; });
            yaml::require(file_, spec["values"], m != set_.degraded_modes.end(),
                          w + ": '" + id + "' is not one of the file's degraded_modes");
            yaml::require(file_, spec["values"], std::none_of(p.modes.begin(), p.modes.end(),
                                                              [&](const DegradedMode& d) { return d.id == id; }),
                          w + ": degraded mode '" + id + "' is listed twice");
            p.modes.push_back(*m);
        }
    } else {
        p.modes = set_.degraded_modes;
    }
    for (const auto& m : p.modes) {
        p.values.push_back(m.id);
    }
}

ParameterDomain TemplateLoader::perturbation(const std::string& name, const YAML::Node& spec, const std::string& what) {
    const std::string w = what + ": perturbation '" + name + "'";
    yaml::require(file_, spec, spec.IsMap() && spec["element"] && spec["attribute"],
                  w + " needs an 'element' and an 'attribute'");
    yaml::check_keys(file_, spec, {"element", "attribute", "values", "all_classes"}, w);
    ParameterDomain p;
    p.name = name;
    p.kind = ParameterKind::perturbation;
    p.element = yaml::scalar(file_, spec["element"], w + ": 'element'");
    const odd::Element& e = element(spec["element"], p.element, w);
    yaml::require(file_, spec["element"], p.element.rfind("Environmental Conditions/", 0) == 0,
                  w + ": element '" + p.element + "' is not an Environmental Condition");
    p.attribute = yaml::scalar(file_, spec["attribute"], w + ": 'attribute'");
    const odd::Attribute& a = attribute(spec["attribute"], e, p.attribute, w);
    yaml::require(file_, spec["attribute"], environment_supports(e.id, p.attribute),
                  w + ": no OpenSCENARIO mapping for '" + p.element + "' " + p.attribute + " (supported: " +
                      supported_perturbations() + ")");
    p.unit = a.unit;
    const bool all = spec["all_classes"] && yaml::boolean(file_, spec["all_classes"], w + ": 'all_classes'");
    yaml::require(file_, spec, all != static_cast<bool>(spec["values"]), w + " takes either 'values' or 'all_classes: true'");
    if (all) {
        p.values = a.type == odd::AttributeType::number ? class_values(a) : a.values;
        yaml::require(file_, spec, !p.values.empty(), w + ": attribute '" + p.attribute + "' has no classes");
        return p;
    }
    p.values = value_list(spec["values"], w + ": 'values'");
    for (const auto& v : p.values) {
        const auto problem = check_value(a, v);
        yaml::require(file_, spec["values"], problem.empty(), w + ": " + problem);
    }
    return p;
}

} // namespace railodd::scenario::detail
