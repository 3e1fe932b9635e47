// The scenario document (ID.xosc) and the ParameterValueDistribution document.
// The storyboard is written by xosc_storyboard.cpp, the environment by
// xosc_environment.cpp, the catalogs by xosc_catalog.cpp; what each target
// reads is in target_support.cpp.
#include "railodd/scenario/xosc_writer.hpp"

#include "xosc_support.hpp"

#include "railodd/util/errors.hpp"

#include <algorithm>

namespace railodd::scenario {

using xosc::attr;

const char* catalog_name(Actor::Kind kind) {
    switch (kind) {
    case Actor::Kind::vehicle:
        return "VehicleCatalog";
    case Actor::Kind::pedestrian:
        return "PedestrianCatalog";
    case Actor::Kind::misc_object:
        return "MiscObjectCatalog";
    }
    return "VehicleCatalog";
}

namespace {

// 1.2 renamed the parameter type "integer" to "int"; 1.1 knows only "integer".
std::string parameter_type(const std::string& type, int rev_minor) {
    if (type == "int" || type == "integer") {
        return rev_minor < 2 ? "integer" : "int";
    }
    return type;
}

// Filled after the storyboard (the node stays first in the document): the
// writer may add declarations for values the target made it drop.
void write_parameters(pugi::xml_node decls, const ConcreteScenario& sc, const xosc::Context& cx) {
    auto declare = [&](const Parameter& p) {
        pugi::xml_node d = decls.append_child("ParameterDeclaration");
        attr(d, "name", p.name);
        attr(d, "parameterType", parameter_type(p.type, cx.rev_minor()));
        attr(d, "value", p.value);
    };
    for (const auto& p : sc.parameters) {
        declare(p);
    }
    for (const auto& p : cx.added()) {
        declare(p);
    }
}

// Every location points at the one catalog directory: the catalogs are told
// apart by their name attribute, not by their folder. All three, or only the
// kinds the scenario uses where the target warns about a missing catalog.
void write_catalog_locations(pugi::xml_node root, const ConcreteScenario& sc, const xosc::Context& cx) {
    pugi::xml_node locations = root.append_child("CatalogLocations");
    for (const auto kind : {Actor::Kind::vehicle, Actor::Kind::pedestrian, Actor::Kind::misc_object}) {
        const bool used = sc.ego.kind == kind || std::any_of(sc.others.begin(), sc.others.end(),
                                                             [&](const Actor& a) { return a.kind == kind; });
        if (used || cx.profile().all_catalog_locations) {
            attr(locations.append_child(catalog_name(kind)).append_child("Directory"), "path", sc.catalog_dir);
        }
    }
}

void write_entity(pugi::xml_node entities, const Actor& a, bool is_ego, const xosc::Context& cx) {
    pugi::xml_node object = entities.append_child("ScenarioObject");
    attr(object, "name", a.name);
    pugi::xml_node ref = object.append_child("CatalogReference");
    attr(ref, "catalogName", catalog_name(a.kind));
    attr(ref, "entryName", cx.value("CatalogReference", xosc::asset_parameter(a, is_ego), a.catalog_entry));
    if (is_ego && cx.profile().ego_type_property) {
        // The entry's Property type is $ActorType (xosc_catalog.cpp): the ego's
        // reference makes it ego_vehicle, whatever else uses the same entry.
        pugi::xml_node assign = ref.append_child("ParameterAssignments").append_child("ParameterAssignment");
        attr(assign, "parameterRef", xosc::actor_type_parameter);
        attr(assign, "value", "ego_vehicle");
    }
}

} // namespace

XoscDocument xosc_document(const ConcreteScenario& sc, const WriteOptions& opt) {
    pugi::xml_document doc;
    pugi::xml_node root = xosc::begin_document(doc, opt, sc.date, sc.description, sc.author);
    const xosc::Context cx{sc, opt};
    pugi::xml_node decls = root.append_child("ParameterDeclarations");
    write_catalog_locations(root, sc, cx);
    attr(root.append_child("RoadNetwork").append_child("LogicFile"), "filepath", sc.map_file);

    pugi::xml_node entities = root.append_child("Entities");
    write_entity(entities, sc.ego, true, cx);
    for (const auto& a : sc.others) {
        write_entity(entities, a, false, cx);
    }

    pugi::xml_node storyboard = root.append_child("Storyboard");
    xosc::write_init(storyboard, cx);
    xosc::write_story(storyboard, cx);
    xosc::write_stop_trigger(storyboard, cx);
    write_parameters(decls, sc, cx);
    target_support::check_document(root, opt.target);
    return {xosc::to_text(doc), cx.degraded()};
}

std::string xosc_text(const ConcreteScenario& sc, const WriteOptions& opt) { return xosc_document(sc, opt).text; }

void write_xosc(const ConcreteScenario& sc, const std::filesystem::path& file, const WriteOptions& opt) {
    xosc::write_atomically(file, xosc_text(sc, opt));
}

std::string distribution_text(const std::string& scenario_file_rel, const std::vector<ValueSet>& value_sets,
                              const std::string& description, const std::string& date, const WriteOptions& opt) {
    if (opt.rev_minor < 1) {
        throw UsageError("OpenSCENARIO 1." + std::to_string(opt.rev_minor),
                         "has no ParameterValueDistribution (added in 1.1)");
    }
    pugi::xml_document doc;
    pugi::xml_node root = xosc::begin_document(doc, opt, date, description, "railodd");
    pugi::xml_node dist = root.append_child("ParameterValueDistribution");
    attr(dist.append_child("ScenarioFile"), "filepath", scenario_file_rel);
    pugi::xml_node deterministic = dist.append_child("Deterministic");
    const bool any = std::any_of(value_sets.begin(), value_sets.end(), [](const ValueSet& v) { return !v.empty(); });
    if (!any) {
        return xosc::to_text(doc); // an empty Deterministic is valid: the scenario as declared
    }
    pugi::xml_node sets = deterministic.append_child("DeterministicMultiParameterDistribution")
                              .append_child("ValueSetDistribution");
    for (const auto& set : value_sets) {
        if (set.empty()) {
            continue; // a ParameterValueSet needs an assignment: the declared values run anyway
        }
        pugi::xml_node s = sets.append_child("ParameterValueSet");
        for (const auto& [name, value] : set) {
            pugi::xml_node a = s.append_child("ParameterAssignment");
            attr(a, "parameterRef", name);
            attr(a, "value", value);
        }
    }
    return xosc::to_text(doc);
}

void write_parameter_distribution(const std::string& scenario_file_rel, const std::vector<ValueSet>& value_sets,
                                  const std::string& description, const std::string& date,
                                  const std::filesystem::path& file, const WriteOptions& opt) {
    xosc::write_atomically(file, distribution_text(scenario_file_rel, value_sets, description, date, opt));
}

} // namespace railodd::scenario
