// Placeholders become text (number with unit and class, asset names), the
// varied values become OpenSCENARIO parameters so that a
// ParameterValueDistribution can vary them, and perturbations set the
// environment.
#include "attribute_values.hpp"
#include "environment.hpp"
#include "instantiate.hpp"

#include <cctype>
#include <cmath>
#include <set>
#include <numbers>

namespace railodd::scenario {

namespace {

namespace pn = parameter_names;

std::string with_unit(const std::string& value, const std::string& unit) {
    return unit.empty() ? value : value + " " + unit;
}

// The text and raw value of a map-bound placeholder at the anchor.
std::pair<std::string, std::string> map_value(const TemplateContext& ctx, const ParameterDomain& p, const Anchor& a) {
    const std::size_t i = p.context < 0 ? a.element : a.context[static_cast<std::size_t>(p.context)];
    const auto* v = ctx.profile.elements[i].find(p.attribute);
    if (!v) {
        return {"unknown", ""}; // not mapped at this anchor
    }
    if (const double* x = std::get_if<double>(v)) {
        const auto raw = format_number(std::round(*x * 10.0) / 10.0);
        return {with_unit(raw, p.unit), raw};
    }
    if (const bool* b = std::get_if<bool>(v)) {
        return {*b ? "true" : "false", *b ? "true" : "false"};
    }
    return {std::get<std::string>(*v), std::get<std::string>(*v)};
}

void declare(ConcreteScenario& sc, const char* name, const std::string& type, const std::string& value,
             ParameterRole role = ParameterRole::storyboard) {
    for (const auto& p : sc.parameters) {
        if (p.name == name) {
            return;
        }
    }
    sc.parameters.push_back({name, type, value, role});
}

std::string fixed(double v) {
    char buf[40];
    std::snprintf(buf, sizeof buf, "%.6f", v);
    std::string s = buf;
    s.erase(s.find_last_not_of('0') + 1);
    if (s.back() == '.') {
        s.pop_back();
    }
    return s;
}

// The OpenSCENARIO parameters a perturbation drives, so a distribution can vary them.
void declare_environment(ConcreteScenario& sc, const std::string& element_id, const std::string& attribute) {
    const Environment& e = sc.environment;
    if (element_id == "en.wx.rain" || element_id == "en.wx.snow") {
        declare(sc, pn::precipitation_type, "string", e.precipitation);
        declare(sc, pn::precipitation_intensity, "double", fixed(e.precipitation_intensity_mm_h));
    } else if (element_id == "en.pt.fog" || element_id == "en.pt.dust" || element_id == "en.pt.smoke") {
        declare(sc, pn::fog_visual_range, "double", fixed(e.fog_visual_range_m));
    } else if (element_id == "en.il.time") {
        if (attribute == "period") {
            // Declared as a string holding the ISO date-time: players read
            // the attribute's text either way, and esmini 3.6 refuses
            // dateTime-typed parameters ("not supported yet"), leaving the
            // time of day unapplied.
            declare(sc, pn::time_of_day, "string", e.date_time);
            declare(sc, pn::sun_azimuth, "double", fixed(e.sun_azimuth_rad));
        }
        declare(sc, pn::sun_elevation, "double", fixed(e.sun_elevation_rad));
    } else if (element_id == "en.rs.head") {
        declare(sc, pn::friction_scale, "double", fixed(e.friction_scale));
    }
}

// A degraded mode's settings: those with an OpenSCENARIO mapping change the
// environment, the others are carried as conditions; all are recorded as the
// ODD values the scenario exercises.
void apply_mode(const TemplateContext& ctx, const DegradedMode& m, ScenarioRecord& rec) {
    ConcreteScenario& sc = rec.scenario;
    declare(sc, "DegradedMode", "string", m.id, ParameterRole::degraded_mode);
    sc.conditions.emplace_back("degraded_mode", m.id);
    sc.conditions.emplace_back("degraded_mode_family", m.family);
    for (const auto& set : m.sets) {
        const odd::Element* el = ctx.taxonomy.find(set.element);
        const odd::Attribute* attr = ctx.taxonomy.attribute(*el, set.attribute);
        if (set.environment) {
            apply_perturbation(sc.environment, el->id, set.attribute, set.value);
            declare_environment(sc, el->id, set.attribute);
        } else {
            // No OpenSCENARIO action: a string parameter (GNSS availability ->
            // GNSSAvailability, Lens condition / condition -> LensCondition)
            // a player or controller can read, and the behaviour file.
            const std::string leaf = set.element.substr(set.element.rfind('/') + 1);
            const bool says_it = leaf.size() >= set.attribute.size() &&
                                 leaf.compare(leaf.size() - set.attribute.size(), set.attribute.size(), set.attribute) == 0;
            declare(sc, osc_parameter_name(says_it ? leaf : leaf + " " + set.attribute).c_str(), "string", set.value,
                    ParameterRole::mode_setting);
            sc.conditions.emplace_back(set.element + " " + set.attribute, set.value);
        }
        rec.odd_elements.push_back({set.element, "", "", "", "degraded_mode"});
        rec.odd_elements.push_back({set.element, set.attribute, set.value, value_class(*attr, set.value), "degraded_mode"});
    }
}

} // namespace

std::string osc_parameter_name(const std::string& name) {
    std::string out;
    bool up = true;
    for (const char c : name) {
        if (c == '_' || c == '-' || c == ' ') {
            up = true;
            continue;
        }
        out += up ? static_cast<char>(std::toupper(static_cast<unsigned char>(c))) : c;
        up = false;
    }
    return out;
}

bool is_reserved_parameter(const std::string& osc_name, const std::vector<std::string>& actors) {
    static const std::set<std::string> fixed_names = {
        pn::ego_speed, pn::time_of_day, pn::sun_elevation, pn::sun_azimuth, pn::cloud_cover, pn::fog_visual_range,
        pn::precipitation_type, pn::precipitation_intensity, pn::friction_scale, "DegradedMode"};
    if (fixed_names.contains(osc_name)) {
        return true;
    }
    for (const auto& a : actors) {
        if (osc_name == a + "Asset" || osc_name == a + "Speed") {
            return true;
        }
    }
    return false;
}

void fill_parameters(const TemplateContext& ctx, const Row& row, const EgoSpeed& speed, ScenarioRecord& rec) {
    ConcreteScenario& sc = rec.scenario;
    declare(sc, pn::ego_speed, "double", fixed(sc.ego.speed_mps));
    for (const auto& p : ctx.tmpl.parameters) {
        std::size_t dim = 0;
        while (dim < ctx.varied.size() && &ctx.tmpl.parameters[ctx.varied[dim]] != &p) {
            ++dim;
        }
        const std::string raw = dim < ctx.varied.size() ? p.values[row[dim + 1]] : "";
        switch (p.kind) {
        case ParameterKind::ego_speed:
            rec.values.emplace_back(p.name, format_number(std::round(speed.kmh)) + " km/h");
            rec.raw.emplace_back(p.name, format_number(speed.kmh));
            break;
        case ParameterKind::actor_asset: {
            const Asset& asset = *ctx.catalog.find(raw);
            rec.values.emplace_back(p.name, asset.name);
            rec.raw.emplace_back(p.name, asset.id);
            declare(sc, (p.actor + "Asset").c_str(), "string", entry_name(asset, ctx.options.target));
            break;
        }
        case ParameterKind::map_value: {
            const auto [text, value] = map_value(ctx, p, rec.anchor);
            rec.values.emplace_back(p.name, text);
            rec.raw.emplace_back(p.name, value);
            break;
        }
        case ParameterKind::perturbation: {
            const odd::Element* el = ctx.taxonomy.find(p.element);
            const odd::Attribute* attr = ctx.taxonomy.attribute(*el, p.attribute);
            apply_perturbation(sc.environment, el->id, p.attribute, raw);
            declare_environment(sc, el->id, p.attribute);
            const std::string klass = value_class(*attr, raw);
            rec.values.emplace_back(p.name, attr->type == odd::AttributeType::number && klass != raw
                                                ? with_unit(raw, p.unit) + " (" + klass + ")"
                                                : with_unit(raw, p.unit));
            rec.raw.emplace_back(p.name, raw);
            rec.odd_elements.push_back({p.element, "", "", "", "perturbation"});
            rec.odd_elements.push_back({p.element, p.attribute, raw, klass, "perturbation"});
            break;
        }
        case ParameterKind::choice:
            rec.values.emplace_back(p.name, raw);
            rec.raw.emplace_back(p.name, raw);
            declare(sc, osc_parameter_name(p.name).c_str(), "string", raw, ParameterRole::choice);
            sc.conditions.emplace_back(p.name, raw);
            break;
        case ParameterKind::degraded_mode: {
            const DegradedMode& m = p.modes[row[dim + 1]];
            rec.values.emplace_back(p.name, m.text);
            rec.raw.emplace_back(p.name, m.id);
            apply_mode(ctx, m, rec);
            break;
        }
        }
    }
    std::string text = ctx.tmpl.text;
    for (const auto& [name, value] : rec.values) {
        const std::string key = "{" + name + "}";
        for (auto at = text.find(key); at != std::string::npos; at = text.find(key, at + value.size())) {
            text.replace(at, key.size(), value);
        }
    }
    sc.description = text;
}

} // namespace railodd::scenario
