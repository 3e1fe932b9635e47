#pragma once
// The asset catalog (data/scenario/assets.yaml, docs/scenarios.md "Catalog"):
// the actors a scenario can place, each with its simulator references and the
// ODD Dynamic Element (and attribute values) it stands for.
#include "railodd/odd/taxonomy.hpp"
#include "railodd/scenario/concrete.hpp"

#include <filesystem>
#include <string>
#include <utility>
#include <vector>

namespace railodd::scenario {

struct Asset {
    std::string id;
    std::string name;         // readable, used in scenario texts
    std::string element;      // taxonomy path, under "Dynamic Elements"
    Actor::Kind kind = Actor::Kind::vehicle;
    std::string osc_category; // vehicleCategory / pedestrianCategory / miscObjectCategory
    std::string carla_blueprint;
    std::string osc_entry;    // OpenSCENARIO catalog entry name (esmini's catalogs use the same names)
    Dimensions dimensions;
    double mass_kg = 0.0;
    double max_speed_mps = 0.0;
    double max_acceleration = 0.0;
    double max_deceleration = 0.0;
    // Taxonomy attributes of `element` the asset has fixed (pose, height, head_wear,
    // train_type, ...), as text; numbers in the attribute's unit.
    std::vector<std::pair<std::string, std::string>> attributes;
    int line = 0;

    const std::string* attribute(const std::string& name) const;
};

struct Catalog {
    std::string source;
    std::string name;
    std::vector<Asset> assets; // file order

    const Asset* find(const std::string& id) const;
    // Assets whose element is `element_path` or lies below it, in file order.
    std::vector<const Asset*> under(const std::string& element_path) const;
};

// Reads and checks a catalog against the taxonomy. Throws railodd::InputError
// "FILE:LINE: problem" for YAML errors, unknown keys, duplicate ids, elements
// not in the taxonomy or outside Dynamic Elements, attributes the element does
// not have, enum values the taxonomy does not list, non-numbers for numeric
// attributes, unknown kinds or OpenSCENARIO categories, and missing or
// non-positive dimensions.
Catalog load_catalog(const std::filesystem::path& path, const odd::Taxonomy& taxonomy);

// The Actor fields an asset defines (not its placement); its catalog entry
// is named for the target player (target.hpp entry_name).
Actor actor_from(const Asset& asset, const std::string& name, const std::string& entry);

} // namespace railodd::scenario
