#pragma once
// The player a scenario set is written for (`railodd scenarios --target`,
// docs/scenarios.md "Targets"). esmini takes OpenSCENARIO 1.1 to 1.3 as the
// writer produces it; CARLA's ScenarioRunner takes OpenSCENARIO 1.0 and only
// the actions, conditions and positions its openscenario_support.md lists,
// so the writer consults the target's table (src/target_support.cpp) and
// lists what it could not express as `degraded_for_target`.
#include "railodd/scenario/catalog.hpp"

#include <string>
#include <string_view>

namespace railodd::scenario {

enum class Target { esmini, carla };

// "esmini" or "carla"; anything else throws std::invalid_argument naming both.
Target target_from(std::string_view name);
const char* to_string(Target t);

// The OpenSCENARIO minor revision a target reads when none is asked for:
// 2 for esmini, 0 for ScenarioRunner (it refuses every other revision).
int default_revision(Target t);
// Throws railodd::UsageError unless the target reads 1.rev_minor.
void check_revision_for(Target t, int rev_minor);

// The catalog entry name of an asset. ScenarioRunner spawns the CARLA
// blueprint named by a Vehicle's (MiscObject's) `name`, so its entries are
// named by their blueprints; esmini's by osc_entry.
const std::string& entry_name(const Asset& asset, Target t);

// Under carla, throws railodd::InputError (the catalog file and line) where
// two assets share a carla_blueprint: they would merge into one catalog entry.
// Nothing to check under esmini.
void check_catalog_for(const Catalog& catalog, Target t);

} // namespace railodd::scenario
