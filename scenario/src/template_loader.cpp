// Reads base-scenario templates against the taxonomy and the asset catalog.
// Every name in a template (element, attribute, value, placeholder, actor,
// asset) is resolved here, so that generation never meets an unknown one.
#include "railodd/scenario/templates.hpp"

#include "attribute_values.hpp"
#include "environment.hpp"
#include "railodd/util/yaml_support.hpp"

#include <algorithm>
#include <cmath>
#include <regex>
#include <set>

namespace railodd::scenario {

namespace {

class TemplateLoader {
public:
    TemplateLoader(TemplateSet& set, const odd::Taxonomy& taxonomy, const Catalog& catalog)
        : set_(set), tax_(taxonomy), cat_(catalog), file_(set.source) {}

    void root(const YAML::Node& root) {
        yaml::require(file_, root, root.IsMap(), "a template file must be a YAML map with a 'templates' list");
        yaml::check_keys(file_, root, {"name", "description", "taxonomy_version", "degraded_modes", "templates"},
                         "template file");
        if (const auto v = root["taxonomy_version"]) {
            const auto version = yaml::scalar(file_, v, "'taxonomy_version'");
            yaml::require(file_, v, version == tax_.version,
                          "templates are written for taxonomy version '" + version + "' but " + tax_.source +
                              " is version '" + tax_.version + "'");
        }
        if (const auto modes = root["degraded_modes"]) {
            degraded_modes(modes);
        }
        const auto list = root["templates"];
        yaml::require(file_, list ? list : root, list && list.IsSequence() && list.size() > 0,
                      "template file needs a non-empty 'templates' list");
        std::set<std::string> ids;
        for (const auto& node : list) {
            set_.templates.push_back(one(node));
            yaml::require(file_, node["id"], ids.insert(set_.templates.back().id).second,
                          "template '" + set_.templates.back().id + "' is listed twice");
        }
    }

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
    void choice_parameter(const YAML::Node& spec, const std::string& w, ParameterDomain& p);
    void mode_parameter(const YAML::Node& spec, const std::string& w, ParameterDomain& p);
    ModeSetting mode_setting(const YAML::Node& node, const std::string& what);

    Template one(const YAML::Node& node) {
        yaml::require(file_, node, node.IsMap() && node["id"], "each template needs an 'id'");
        Template t;
        t.id = yaml::name(file_, node["id"], "template id");
        t.line = yaml::line_of(node);
        const std::string what = "template '" + t.id + "'";
        yaml::check_keys(file_, node,
                         {"id", "text", "description", "anchor", "context", "ego", "actors", "parameters",
                          "perturbations", "constraints"},
                         what);
        yaml::require(file_, node, static_cast<bool>(node["text"]), what + ": 'text' is missing");
        t.text = yaml::scalar(file_, node["text"], what + ": 'text'");
        yaml::require(file_, node, static_cast<bool>(node["anchor"]), what + ": 'anchor' is missing");
        static_cast<ElementMatch&>(t.anchor) = match(node["anchor"], what + ": anchor", {"element", "where", "at", "route"});
        if (const auto route = node["anchor"]["route"]) {
            const auto r = yaml::scalar(file_, route, what + ": anchor 'route'");
            yaml::require(file_, route, r == "through" || r == "diverging",
                          what + ": anchor 'route' must be through or diverging, not '" + r + "'");
            yaml::require(file_, route, t.anchor.element.rfind("Scenery/Track layout/Switch", 0) == 0,
                          what + ": anchor 'route' needs a switch anchor, not '" + t.anchor.element + "'");
            t.anchor.diverging = r == "diverging";
        }
        if (const auto at = node["anchor"]["at"]) {
            const auto a = yaml::scalar(file_, at, what + ": anchor 'at'");
            yaml::require(file_, at, a == "start" || a == "middle" || a == "end",
                          what + ": anchor 'at' must be start, middle or end, not '" + a + "'");
            t.anchor.at = a == "start" ? AnchorAt::start : a == "middle" ? AnchorAt::middle : AnchorAt::end;
        }
        if (const auto list = node["context"]) {
            yaml::require(file_, list, list.IsSequence(), what + ": 'context' must be a list");
            for (const auto& c : list) {
                ContextRequirement r;
                static_cast<ElementMatch&>(r) = match(c, what + ": context", {"element", "where", "within_m"});
                if (c["within_m"]) {
                    r.within_m = yaml::number(file_, c["within_m"], what + ": context 'within_m'");
                    yaml::require(file_, c["within_m"], r.within_m > 0.0,
                                  what + ": context 'within_m' must be positive, not " + c["within_m"].Scalar());
                }
                t.context.push_back(std::move(r));
            }
        }
        ego(node["ego"], t, what);
        if (const auto list = node["actors"]) {
            yaml::require(file_, list, list.IsSequence(), what + ": 'actors' must be a list");
            for (const auto& a : list) {
                t.actors.push_back(actor(a, t, what));
            }
        }
        parameters(node, t, what);
        constraints(node["constraints"], t, what);
        placeholders(node["text"], t, what);
        return t;
    }

    const odd::Element& element(const YAML::Node& at, const std::string& path, const std::string& what) {
        const odd::Element* e = tax_.find(path);
        yaml::require(file_, at, e != nullptr, what + ": element '" + path + "' is not in the taxonomy " + tax_.source);
        return *e;
    }

    const odd::Attribute& attribute(const YAML::Node& at, const odd::Element& e, const std::string& name,
                                    const std::string& what) {
        const odd::Attribute* a = tax_.attribute(e, name);
        yaml::require(file_, at, a != nullptr, what + ": element '" + e.path + "' has no attribute '" + name + "'");
        return *a;
    }

    std::vector<std::string> value_list(const YAML::Node& v, const std::string& what) {
        std::vector<std::string> out;
        if (v.IsSequence()) {
            for (const auto& x : v) {
                out.push_back(yaml::scalar(file_, x, what));
            }
        } else {
            out.push_back(yaml::scalar(file_, v, what));
        }
        yaml::require(file_, v, !out.empty(), what + " must not be empty");
        return out;
    }

    ElementMatch match(const YAML::Node& node, const std::string& what, std::initializer_list<std::string_view> keys) {
        yaml::require(file_, node, node.IsMap() && node["element"], what + " needs an 'element'");
        yaml::check_keys(file_, node, keys, what);
        ElementMatch m;
        m.line = yaml::line_of(node);
        m.element = yaml::scalar(file_, node["element"], what + ": 'element'");
        const odd::Element& e = element(node["element"], m.element, what);
        if (const auto where = node["where"]) {
            yaml::require(file_, where, where.IsMap(), what + ": 'where' must map attributes to conditions");
            for (const auto& kv : where) {
                m.where.push_back(condition(kv, e, what));
            }
        }
        return m;
    }

    AttributeCondition condition(const std::pair<YAML::Node, YAML::Node>& kv, const odd::Element& e,
                                 const std::string& what) {
        AttributeCondition c;
        c.attribute = kv.first.Scalar();
        c.line = yaml::line_of(kv.first);
        const odd::Attribute& a = attribute(kv.first, e, c.attribute, what);
        const std::string w = what + ": where '" + c.attribute + "'";
        if (a.type == odd::AttributeType::number) {
            yaml::require(file_, kv.second, kv.second.IsMap(), w + " takes {min, max} for a number");
            yaml::check_keys(file_, kv.second, {"min", "max"}, w);
            if (kv.second["min"]) c.min = yaml::number(file_, kv.second["min"], w + " min");
            if (kv.second["max"]) c.max = yaml::number(file_, kv.second["max"], w + " max");
            yaml::require(file_, kv.second, !(c.min && c.max && *c.min > *c.max), w + ": min is above max");
            return c;
        }
        c.values = value_list(kv.second, w);
        for (const auto& v : c.values) {
            const auto problem = check_value(a, v);
            yaml::require(file_, kv.second, problem.empty(), w + ": " + problem);
        }
        return c;
    }

    void ego(const YAML::Node& node, Template& t, const std::string& what) {
        if (node) {
            yaml::require(file_, node, node.IsMap(), what + ": 'ego' must be a map");
            yaml::check_keys(file_, node, {"asset_class", "run_up_m", "min_run_up_m", "overrun_m", "stop_before_m"},
                             what + ": ego");
            if (node["asset_class"]) t.ego.asset_class = yaml::scalar(file_, node["asset_class"], what + ": ego 'asset_class'");
            if (node["run_up_m"]) t.ego.run_up_m = yaml::number(file_, node["run_up_m"], what + ": 'run_up_m'");
            if (node["min_run_up_m"]) t.ego.min_run_up_m = yaml::number(file_, node["min_run_up_m"], what + ": 'min_run_up_m'");
            if (node["overrun_m"]) t.ego.overrun_m = yaml::number(file_, node["overrun_m"], what + ": 'overrun_m'");
            yaml::require(file_, node, !(node["overrun_m"] && node["stop_before_m"]),
                          what + ": ego takes 'overrun_m' or 'stop_before_m', not both");
            if (node["stop_before_m"]) t.ego.stop_before_m = yaml::number(file_, node["stop_before_m"], what + ": 'stop_before_m'");
            for (const char* key : {"run_up_m", "min_run_up_m", "overrun_m", "stop_before_m"}) {
                if (const auto v = node[key]) {
                    yaml::require(file_, v, yaml::number(file_, v, key) >= 0.0,
                                  what + ": ego '" + key + "' must not be negative, not " + v.Scalar());
                }
            }
        }
        const YAML::Node& at = node ? node : YAML::Node();
        element(at, t.ego.asset_class, what + ": ego");
        yaml::require(file_, at, !cat_.under(t.ego.asset_class).empty(),
                      what + ": ego: the catalog " + cat_.source + " has no asset under '" + t.ego.asset_class + "'");
    }

    Lateral lateral(const YAML::Node& v, const std::string& what) {
        const auto s = yaml::scalar(file_, v, what);
        for (const auto l : {Lateral::on_track, Lateral::platform_edge, Lateral::beside_track, Lateral::crossing_approach,
                             Lateral::adjacent_track}) {
            if (s == to_string(l)) {
                return l;
            }
        }
        yaml::fail(file_, v, what + " must be on_track, platform_edge, beside_track, crossing_approach or adjacent_track, not '" +
                                 s + "'");
    }

    ActorTemplate actor(const YAML::Node& node, const Template& t, const std::string& what) {
        yaml::require(file_, node, node.IsMap() && node["name"] && node["asset_class"],
                      what + ": each actor needs a 'name' and an 'asset_class'");
        ActorTemplate a;
        a.name = yaml::scalar(file_, node["name"], what + ": actor 'name'");
        a.line = yaml::line_of(node);
        const std::string w = what + ": actor '" + a.name + "'";
        yaml::check_keys(file_, node,
                         {"name", "asset_class", "place", "along_m", "move_to", "move_speed_kmh", "trigger_before_m",
                          "hazard_before_m", "behaviour"},
                         w);
        yaml::require(file_, node["name"], a.name != "Ego", w + ": the name Ego is the train's");
        for (const auto& other : t.actors) {
            yaml::require(file_, node["name"], other.name != a.name, w + " is listed twice");
        }
        a.asset_class = yaml::scalar(file_, node["asset_class"], w + ": 'asset_class'");
        element(node["asset_class"], a.asset_class, w);
        yaml::require(file_, node["asset_class"], !cat_.under(a.asset_class).empty(),
                      w + ": the catalog " + cat_.source + " has no asset under '" + a.asset_class + "'");
        if (node["place"]) a.place = lateral(node["place"], w + ": 'place'");
        if (node["along_m"]) a.along_m = yaml::number(file_, node["along_m"], w + ": 'along_m'");
        if (node["move_to"]) a.move_to = lateral(node["move_to"], w + ": 'move_to'");
        if (node["move_speed_kmh"]) a.move_speed_kmh = yaml::number(file_, node["move_speed_kmh"], w + ": 'move_speed_kmh'");
        if (node["trigger_before_m"]) a.trigger_before_m = yaml::number(file_, node["trigger_before_m"], w + ": 'trigger_before_m'");
        if (node["hazard_before_m"]) {
            yaml::require(file_, node["hazard_before_m"], !node["trigger_before_m"],
                          w + ": give 'hazard_before_m' or 'trigger_before_m', not both");
            a.hazard_before_m = yaml::number(file_, node["hazard_before_m"], w + ": 'hazard_before_m'");
        }
        yaml::require(file_, node, !a.move_to || a.move_speed_kmh > 0.0, w + ": 'move_to' needs a positive 'move_speed_kmh'");
        if (node["behaviour"]) a.behaviour = yaml::scalar(file_, node["behaviour"], w + ": 'behaviour'");
        return a;
    }

    void parameters(const YAML::Node& node, Template& t, const std::string& what);
    ParameterDomain parameter(const std::string& name, const YAML::Node& spec, const Template& t, const std::string& what);
    ParameterDomain perturbation(const std::string& name, const YAML::Node& spec, const std::string& what);
    void constraints(const YAML::Node& node, Template& t, const std::string& what);
    void placeholders(const YAML::Node& at, Template& t, const std::string& what);
};


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
        choice_parameter(spec, w, p);
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

void TemplateLoader::choice_parameter(const YAML::Node& spec, const std::string& w, ParameterDomain& p) {
    p.kind = ParameterKind::choice;
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
            p.modes.push_back(*m);
        }
    } else {
        p.modes = set_.degraded_modes;
    }
    for (const auto& m : p.modes) {
        p.values.push_back(m.id);
    }
}

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

void TemplateLoader::constraints(const YAML::Node& node, Template& t, const std::string& what) {
    if (!node) {
        return;
    }
    const std::string w = what + ": constraints";
    yaml::require(file_, node, node.IsMap(), w + " must be a map");
    yaml::check_keys(file_, node, {"speed_within_limit", "exclude"}, w);
    if (node["speed_within_limit"]) {
        t.speed_within_limit = yaml::boolean(file_, node["speed_within_limit"], w + ": 'speed_within_limit'");
    }
    const auto list = node["exclude"];
    if (!list) {
        return;
    }
    yaml::require(file_, list, list.IsSequence(), w + ": 'exclude' must be a list of {parameter: value} maps");
    for (const auto& item : list) {
        yaml::require(file_, item, item.IsMap() && item.size() > 0, w + ": each exclusion maps parameters to values");
        Exclusion x;
        x.line = yaml::line_of(item);
        for (const auto& kv : item) {
            const auto name = kv.first.Scalar();
            const ParameterDomain* p = t.parameter(name);
            yaml::require(file_, kv.first, p && p->kind != ParameterKind::map_value,
                          w + ": exclusion names '" + name + "', which is not a varied parameter");
            const auto value = yaml::scalar(file_, kv.second, w + ": '" + name + "'");
            yaml::require(file_, kv.second, std::find(p->values.begin(), p->values.end(), value) != p->values.end(),
                          w + ": '" + value + "' is not a value of parameter '" + name + "'");
            x.values.emplace_back(name, value);
        }
        t.exclusions.push_back(std::move(x));
    }
}

void TemplateLoader::placeholders(const YAML::Node& at, Template& t, const std::string& what) {
    static const std::regex placeholder(R"(\{([^{}]*)\})");
    for (auto it = std::sregex_iterator(t.text.begin(), t.text.end(), placeholder); it != std::sregex_iterator(); ++it) {
        const std::string name = (*it)[1].str();
        yaml::require(file_, at, t.parameter(name) != nullptr,
                      what + ": placeholder {" + name + "} in the text has no parameter or perturbation");
        if (std::find(t.placeholders.begin(), t.placeholders.end(), name) == t.placeholders.end()) {
            t.placeholders.push_back(name);
        }
    }
}

} // namespace

const char* to_string(Lateral lateral) {
    switch (lateral) {
    case Lateral::on_track: return "on_track";
    case Lateral::platform_edge: return "platform_edge";
    case Lateral::beside_track: return "beside_track";
    case Lateral::crossing_approach: return "crossing_approach";
    case Lateral::adjacent_track: return "adjacent_track";
    }
    return "?";
}

const char* to_string(ParameterKind kind) {
    switch (kind) {
    case ParameterKind::ego_speed: return "ego_speed";
    case ParameterKind::actor_asset: return "asset";
    case ParameterKind::map_value: return "map";
    case ParameterKind::perturbation: return "perturbation";
    case ParameterKind::choice: return "choice";
    case ParameterKind::degraded_mode: return "degraded_mode";
    }
    return "?";
}

const ParameterDomain* Template::parameter(const std::string& name) const {
    for (const auto& p : parameters) {
        if (p.name == name) {
            return &p;
        }
    }
    return nullptr;
}

TemplateSet load_templates(const std::filesystem::path& path, const odd::Taxonomy& taxonomy, const Catalog& catalog) {
    TemplateSet set;
    set.source = path.string();
    const YAML::Node root = yaml::load_file(path, "template file");
    TemplateLoader(set, taxonomy, catalog).root(root);
    return set;
}

} // namespace railodd::scenario
