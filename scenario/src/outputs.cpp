// Writing a scenario set into the output stage: nothing reaches the output
// directory unless every file was written (OutputStage::commit).
#include "railodd/scenario/outputs.hpp"

#include "railodd/scenario/xosc_writer.hpp"

#include <map>
#include <set>

namespace railodd::scenario {

namespace {

// Per template, the distinct sets of the scenario parameters its scenarios
// use, for a ParameterValueDistribution over the template's first scenario.
std::map<std::string, std::vector<ValueSet>> value_sets(const Generation& g) {
    std::map<std::string, std::vector<ValueSet>> out;
    std::map<std::string, std::set<ValueSet>> seen;
    for (const auto& s : g.scenarios) {
        ValueSet set;
        for (const auto& p : s.scenario.parameters) {
            set.emplace_back(p.name, p.value);
        }
        if (seen[s.template_id].insert(set).second) {
            out[s.template_id].push_back(std::move(set));
        }
    }
    return out;
}

} // namespace

bool has_distributions(const OutputInfo& info) { return info.osc_minor >= 1; }

void write_scenario_set(OutputStage& stage, const Generation& g, const Coverage& coverage,
                        const odd::OddProfile& profile, const OutputInfo& info) {
    const WriteOptions opt{info.osc_minor, info.target};
    Degradations degraded;
    for (const auto& s : g.scenarios) {
        XoscDocument doc = xosc_document(s.scenario, opt);
        stage.write_text(s.scenario.id + ".xosc", doc.text);
        degraded[s.scenario.id] = std::move(doc.degraded_for_target);
        stage.write_text(s.scenario.id + ".behavior.yaml", behavior_yaml(s, profile));
    }
    for (const auto kind : {Actor::Kind::vehicle, Actor::Kind::pedestrian, Actor::Kind::misc_object}) {
        std::vector<Actor> entries;
        for (const auto& a : g.catalog_entries) {
            if (a.kind == kind) {
                entries.push_back(a);
            }
        }
        if (!entries.empty()) {
            const std::string name = catalog_name(kind);
            stage.write_text("catalogs/" + name + ".xosc", catalog_text(name, entries, opt, info.date));
        }
    }
    const auto sets = value_sets(g);
    for (const auto& r : g.runs) {
        const auto it = sets.find(r.template_id);
        if (it == sets.end() || !has_distributions(info)) {
            continue; // no scenario: nothing to distribute over
        }
        std::string first;
        for (const auto& s : g.scenarios) {
            if (s.template_id == r.template_id) {
                first = s.scenario.id;
                break;
            }
        }
        stage.write_text("distributions/" + r.template_id + ".xosc",
                         distribution_text("../" + first + ".xosc", it->second,
                                           "Parameter values of template " + r.template_id + " (anchored at " + first +
                                               ")",
                                           info.date, opt));
    }
    stage.write_text("manifest.json", manifest_json(g, profile, info, degraded).dump(1) + "\n");
    stage.write_text("coverage.json", coverage_json(coverage).dump(1) + "\n");
    stage.write_text("coverage.txt", coverage_table(coverage));
}

} // namespace railodd::scenario
