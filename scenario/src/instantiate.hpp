#pragma once
// Turning one row of parameter values at one anchor into a concrete scenario
// and its traceability record. Internal to the scenario library.
#include "railodd/scenario/generator.hpp"

#include <cstddef>
#include <map>
#include <string>
#include <vector>

namespace railodd::scenario {

// What a template run knows while it instantiates rows.
struct TemplateContext {
    const odd::OddProfile& profile;
    const LineIndex& lines;
    const Template& tmpl;
    const Catalog& catalog;
    const odd::Taxonomy& taxonomy;
    const GenerateOptions& options;
    const std::vector<Anchor>& anchors;
    std::vector<std::size_t> varied; // indices into tmpl.parameters of dimensions 1..n (0 is the anchor)
    std::map<std::string, const Asset*> default_assets; // per actor ("Ego" too): the first asset of its class
    std::vector<std::vector<CoveredValue>> anchor_cover; // per anchor: what of the map it exercises
    std::vector<const Asset*> ego_assets; // the ego's class, in catalog order
};

// Fills the context's per-template caches: default assets and, per anchor,
// the map elements it exercises (the anchor, its context, the stretches it
// lies on), so that rows do not rescan the profile.
void prepare(TemplateContext& ctx);

// The ego's speed in km/h for a row, and what it was derived from.
struct EgoSpeed {
    double kmh = 0.0;
    std::string basis;
};

// The asset an actor gets in a row: its asset parameter's value, else the
// first asset of its class.
const Asset& asset_for(const TemplateContext& ctx, const Row& row, const std::string& actor);
EgoSpeed ego_speed_for(const TemplateContext& ctx, const Row& row);

// The ego's asset for a row run at `kmh`: its asset parameter's value; else
// the first asset of its class, or where that cannot run so fast the first
// of the class that can (a template that names no train runs a high-speed
// line with a train built for it). Null where no asset of the class can.
const Asset* ego_for(const TemplateContext& ctx, const Row& row, double kmh);

// The row's placeholder values, the scenario text, the declared OpenSCENARIO
// parameters, the environment from the perturbations and their coverage.
void fill_parameters(const TemplateContext& ctx, const Row& row, const EgoSpeed& speed, ScenarioRecord& rec);

ScenarioRecord instantiate(const TemplateContext& ctx, const Row& row, const std::string& id);

} // namespace railodd::scenario
