#pragma once
// OpenSCENARIO output: the scenario file (ID.xosc), the catalogs its entities
// reference and the ParameterValueDistribution that varies its parameters.
//
// The texts are deterministic: the same input gives byte-identical output
// (numbers in fixed notation with at most 6 decimals, no clock, no locale).
// The write_* functions write a temporary file beside the target and rename it
// into place, so a failed write leaves no half-written file; they throw
// railodd::OutputError naming the file.
//
// Entities are CatalogReferences: the physical description (bounding box,
// performance, axles, <Properties> with the ODD attributes and the CARLA
// blueprint) lives in the catalog entry written by catalog_text(), never in the
// scenario file. Actor::properties therefore only reach the output through the
// catalog.
#include "railodd/scenario/concrete.hpp"
#include "railodd/scenario/target.hpp"

#include <filesystem>
#include <string>
#include <utility>
#include <vector>

namespace railodd::scenario {

struct WriteOptions {
    // OpenSCENARIO 1.rev_minor: 2 (default), 1 or 3 for esmini, 0 for carla.
    // Others throw UsageError.
    int rev_minor = 2;
    // The player: the writer writes only what it reads (target.hpp).
    Target target = Target::esmini;
};

// Something of the scenario the target cannot express: the parameter that
// keeps it (declared in the document with `value`) and why.
struct Degradation {
    std::string name;
    std::string value;
    std::string reason;
};

struct XoscDocument {
    std::string text;
    // Empty for esmini. For carla every declared parameter no element
    // ScenarioRunner reads carries, and every value dropped from the
    // storyboard (declared for it), in declaration order.
    std::vector<Degradation> degraded_for_target;
};

// The catalog a CatalogReference of an actor of `kind` names:
// "VehicleCatalog", "PedestrianCatalog" or "MiscObjectCatalog". The catalog
// files must carry these names (catalog_text's `catalog_name`).
const char* catalog_name(Actor::Kind kind);

// The scenario document. Parameters declared in sc.parameters with the names of
// parameter_names (concrete.hpp) are referenced as "$Name" where they apply.
XoscDocument xosc_document(const ConcreteScenario& sc, const WriteOptions& opt = {});
std::string xosc_text(const ConcreteScenario& sc, const WriteOptions& opt = {});
void write_xosc(const ConcreteScenario& sc, const std::filesystem::path& file, const WriteOptions& opt = {});

// A catalog document <Catalog name=catalog_name> with one Vehicle, Pedestrian
// or MiscObject per distinct catalog_entry (of actors sharing an entry name,
// the first one written defines it). Entries are ordered vehicles,
// pedestrians, misc objects as the schema requires, each group in the order
// given. Entries of any kind are written; the scenario finds them only if the
// catalog's name is catalog_name(kind).
// Vehicle reference point: the centre of the bounding box projected to the
// ground (BoundingBox Center x = 0, axles symmetric about it).
std::string catalog_text(const std::string& catalog_name, const std::vector<Actor>& entries,
                         const WriteOptions& opt = {}, const std::string& date = "2026-01-01T00:00:00");
void write_catalog(const std::string& catalog_name, const std::vector<Actor>& entries,
                   const std::filesystem::path& file, const WriteOptions& opt = {},
                   const std::string& date = "2026-01-01T00:00:00");

// One parameter assignment set: (parameter name without "$", value).
using ValueSet = std::vector<std::pair<std::string, std::string>>;

// A ParameterValueDistribution over `scenario_file_rel` (path relative to the
// distribution file): a deterministic ValueSetDistribution with one
// ParameterValueSet per non-empty entry of `value_sets` (the schema requires
// an assignment per set; without any, Deterministic stays empty).
// OpenSCENARIO 1.0 has no ParameterValueDistribution: rev_minor 0 throws
// UsageError.
std::string distribution_text(const std::string& scenario_file_rel, const std::vector<ValueSet>& value_sets,
                              const std::string& description, const std::string& date,
                              const WriteOptions& opt = {});
void write_parameter_distribution(const std::string& scenario_file_rel, const std::vector<ValueSet>& value_sets,
                                  const std::string& description, const std::string& date,
                                  const std::filesystem::path& file, const WriteOptions& opt = {});

} // namespace railodd::scenario
