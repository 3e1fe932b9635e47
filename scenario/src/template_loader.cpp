// Reads base-scenario templates against the taxonomy and the asset catalog.
// Every name in a template (element, attribute, value, placeholder, actor,
// asset) is resolved here, so that generation never meets an unknown one.
#include "template_loader.hpp"
#include "attribute_values.hpp"

#include <algorithm>
#include <cmath>
#include <regex>
#include <set>

namespace railodd::scenario {

namespace detail {

void TemplateLoader::root(const YAML::Node& root) {
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

Template TemplateLoader::one(const YAML::Node& node) {
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

const odd::Element& TemplateLoader::element(const YAML::Node& at, const std::string& path, const std::string& what) {
    const odd::Element* e = tax_.find(path);
    yaml::require(file_, at, e != nullptr, what + ": element '" + path + "' is not in the taxonomy " + tax_.source);
    return *e;
}

const odd::Attribute& TemplateLoader::attribute(const YAML::Node& at, const odd::Element& e, const std::string& name,
                                                const std::string& what) {
    const odd::Attribute* a = tax_.attribute(e, name);
    yaml::require(file_, at, a != nullptr, what + ": element '" + e.path + "' has no attribute '" + name + "'");
    return *a;
}

double TemplateLoader::in_range(const YAML::Node& v, double lo, double hi, const std::string& what) {
    const double x = yaml::number(file_, v, what);
    yaml::require(file_, v, x >= lo && x <= hi,
                  what + " must be from " + format_number(lo) + " to " + format_number(hi) + ", not " + v.Scalar());
    return x;
}

std::vector<std::string> TemplateLoader::value_list(const YAML::Node& v, const std::string& what) {
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

ElementMatch TemplateLoader::match(const YAML::Node& node, const std::string& what,
                                   std::initializer_list<std::string_view> keys) {
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

AttributeCondition TemplateLoader::condition(const std::pair<YAML::Node, YAML::Node>& kv, const odd::Element& e,
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

void TemplateLoader::ego(const YAML::Node& node, Template& t, const std::string& what) {
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

Lateral TemplateLoader::lateral(const YAML::Node& v, const std::string& what) {
    const auto s = yaml::scalar(file_, v, what);
    for (const auto l : {Lateral::on_track, Lateral::platform_edge, Lateral::beside_track, Lateral::crossing_approach,
                         Lateral::adjacent_track, Lateral::branch_track}) {
        if (s == to_string(l)) {
            return l;
        }
    }
    yaml::fail(file_, v, what + " must be on_track, platform_edge, beside_track, crossing_approach, adjacent_track or branch_track, not '" +
                             s + "'");
}

ActorTemplate TemplateLoader::actor(const YAML::Node& node, const Template& t, const std::string& what) {
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
    if (node["move_speed_kmh"]) a.move_speed_kmh = in_range(node["move_speed_kmh"], 0.1, 500.0, w + ": 'move_speed_kmh'");
    if (node["trigger_before_m"]) a.trigger_before_m = in_range(node["trigger_before_m"], 0.0, 1e5, w + ": 'trigger_before_m'");
    if (node["hazard_before_m"]) {
        yaml::require(file_, node["hazard_before_m"], !node["trigger_before_m"],
                      w + ": give 'hazard_before_m' or 'trigger_before_m', not both");
        a.hazard_before_m = in_range(node["hazard_before_m"], 0.0, 1e5, w + ": 'hazard_before_m'");
    }
    yaml::require(file_, node, !a.move_to || a.move_speed_kmh > 0.0, w + ": 'move_to' needs a positive 'move_speed_kmh'");
    yaml::require(file_, node["place"] ? node["place"] : node,
                  a.place != Lateral::branch_track || t.anchor.element.rfind("Scenery/Track layout/Switch", 0) == 0,
                  w + ": place branch_track needs a switch anchor, not '" + t.anchor.element + "'");
    yaml::require(file_, node["move_to"] ? node["move_to"] : node, a.move_to != Lateral::branch_track,
                  w + ": an actor cannot move onto the branch track");
    if (node["behaviour"]) a.behaviour = yaml::scalar(file_, node["behaviour"], w + ": 'behaviour'");
    return a;
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

} // namespace detail

const char* to_string(Lateral lateral) {
    switch (lateral) {
    case Lateral::on_track: return "on_track";
    case Lateral::platform_edge: return "platform_edge";
    case Lateral::beside_track: return "beside_track";
    case Lateral::crossing_approach: return "crossing_approach";
    case Lateral::adjacent_track: return "adjacent_track";
    case Lateral::branch_track: return "branch_track";
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
    detail::TemplateLoader(set, taxonomy, catalog).root(root);
    return set;
}

} // namespace railodd::scenario
