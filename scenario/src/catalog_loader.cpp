// Reads the asset catalog against the taxonomy: an asset that names an element
// or attribute value the taxonomy does not know could never be matched to the
// ODD, so it is refused with its line instead of silently covering nothing.
#include "railodd/scenario/catalog.hpp"

#include "attribute_values.hpp"
#include "railodd/util/yaml_support.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <set>
#include <string_view>

namespace railodd::scenario {

namespace {

// OpenSCENARIO 1.2 enumerations (VehicleCategory, PedestrianCategory, MiscObjectCategory).
constexpr std::array vehicle_categories{"bicycle", "bus", "car", "motorbike", "semitrailer",
                                        "trailer", "train", "tram", "truck", "van"};
constexpr std::array pedestrian_categories{"animal", "pedestrian", "wheelchair"};
constexpr std::array misc_categories{"barrier", "building", "crosswalk", "gantry", "none", "obstacle", "parkingSpace",
                                     "patch", "pole", "railing", "roadMark", "soundBarrier", "streetLamp",
                                     "trafficIsland", "tree", "vegetation", "wind"};

template <std::size_t N>
bool listed(const std::array<const char*, N>& list, const std::string& v) {
    return std::any_of(list.begin(), list.end(), [&](const char* c) { return v == c; });
}

class CatalogLoader {
public:
    CatalogLoader(Catalog& catalog, const odd::Taxonomy& taxonomy) : cat_(catalog), tax_(taxonomy), file_(catalog.source) {}

    void root(const YAML::Node& root) {
        yaml::require(file_, root, root.IsMap(), "an asset catalog must be a YAML map with an 'assets' list");
        yaml::check_keys(file_, root, {"catalog", "description", "taxonomy_version", "assets"}, "catalog");
        if (root["catalog"]) {
            cat_.name = yaml::scalar(file_, root["catalog"], "'catalog'");
        }
        if (const auto v = root["taxonomy_version"]) {
            const auto version = yaml::scalar(file_, v, "'taxonomy_version'");
            yaml::require(file_, v, version == tax_.version,
                          "catalog is written for taxonomy version '" + version + "' but " + tax_.source +
                              " is version '" + tax_.version + "'");
        }
        const auto list = root["assets"];
        yaml::require(file_, list ? list : root, list && list.IsSequence() && list.size() > 0,
                      "catalog needs a non-empty 'assets' list");
        for (const auto& node : list) {
            cat_.assets.push_back(asset(node));
        }
    }

private:
    Catalog& cat_;
    const odd::Taxonomy& tax_;
    const std::string file_;
    std::set<std::string> ids_;

    Asset asset(const YAML::Node& node) {
        yaml::require(file_, node, node.IsMap() && node["id"], "each asset needs an 'id'");
        Asset a;
        a.id = yaml::name(file_, node["id"], "asset id");
        a.line = yaml::line_of(node);
        const std::string what = "asset '" + a.id + "'";
        yaml::check_keys(file_, node,
                         {"id", "name", "element", "kind", "osc_category", "carla_blueprint", "osc_entry", "dimensions",
                          "mass", "performance", "attributes"},
                         what);
        yaml::require(file_, node["id"], ids_.insert(a.id).second, what + " is listed twice");
        a.name = node["name"] ? yaml::scalar(file_, node["name"], what + ": 'name'") : a.id;
        element(node, a, what);
        kind(node, a, what);
        a.carla_blueprint = required(node, "carla_blueprint", what);
        a.osc_entry = node["osc_entry"] ? yaml::scalar(file_, node["osc_entry"], what + ": 'osc_entry'") : a.id;
        dimensions(node, a, what);
        a.mass_kg = positive(node, node["mass"], what + ": 'mass'");
        performance(node, a, what);
        if (const auto attrs = node["attributes"]) {
            yaml::require(file_, attrs, attrs.IsMap(), what + ": 'attributes' must map attribute names to values");
            const odd::Element* e = tax_.find(a.element);
            for (const auto& kv : attrs) {
                const auto name = kv.first.Scalar();
                const odd::Attribute* attr = tax_.attribute(*e, name);
                yaml::require(file_, kv.first, attr != nullptr,
                              what + ": element '" + a.element + "' has no attribute '" + name + "'");
                const auto value = yaml::scalar(file_, kv.second, what + ": '" + name + "'");
                const auto problem = check_value(*attr, value);
                yaml::require(file_, kv.second, problem.empty(), what + ": attribute '" + name + "': " + problem);
                a.attributes.emplace_back(name, value);
            }
        }
        return a;
    }

    std::string required(const YAML::Node& node, const char* key, const std::string& what) {
        yaml::require(file_, node, static_cast<bool>(node[key]), what + ": '" + key + "' is missing");
        return yaml::scalar(file_, node[key], what + ": '" + key + "'");
    }

    double positive(const YAML::Node& parent, const YAML::Node& v, const std::string& what) {
        yaml::require(file_, v ? v : parent, static_cast<bool>(v), what + " is missing");
        const double x = yaml::number(file_, v, what);
        yaml::require(file_, v, x > 0.0 && std::isfinite(x), what + " must be positive and finite, not " + v.Scalar());
        return x;
    }

    void element(const YAML::Node& node, Asset& a, const std::string& what) {
        a.element = required(node, "element", what);
        const odd::Element* e = tax_.find(a.element);
        if (!e) {
            e = tax_.find_id(a.element);
            if (e) {
                a.element = e->path;
            }
        }
        yaml::require(file_, node["element"], e != nullptr,
                      what + ": element '" + a.element + "' is not in the taxonomy " + tax_.source);
        yaml::require(file_, node["element"], a.element.rfind("Dynamic Elements/", 0) == 0,
                      what + ": element '" + a.element + "' is not a Dynamic Element");
    }

    void kind(const YAML::Node& node, Asset& a, const std::string& what) {
        const auto k = required(node, "kind", what);
        a.osc_category = required(node, "osc_category", what);
        const auto& at = node["osc_category"];
        if (k == "vehicle") {
            a.kind = Actor::Kind::vehicle;
            yaml::require(file_, at, listed(vehicle_categories, a.osc_category),
                          what + ": '" + a.osc_category + "' is not an OpenSCENARIO vehicleCategory");
        } else if (k == "pedestrian") {
            a.kind = Actor::Kind::pedestrian;
            yaml::require(file_, at, listed(pedestrian_categories, a.osc_category),
                          what + ": '" + a.osc_category + "' is not an OpenSCENARIO pedestrianCategory");
        } else if (k == "misc_object") {
            a.kind = Actor::Kind::misc_object;
            yaml::require(file_, at, listed(misc_categories, a.osc_category),
                          what + ": '" + a.osc_category + "' is not an OpenSCENARIO miscObjectCategory");
        } else {
            yaml::fail(file_, node["kind"], what + ": kind must be vehicle, pedestrian or misc_object, not '" + k + "'");
        }
    }

    void dimensions(const YAML::Node& node, Asset& a, const std::string& what) {
        const auto d = node["dimensions"];
        yaml::require(file_, d ? d : node, d && d.IsMap(), what + ": 'dimensions' {length, width, height} is missing");
        yaml::check_keys(file_, d, {"length", "width", "height"}, what + ": dimensions");
        a.dimensions.length = positive(d, d["length"], what + ": dimensions 'length'");
        a.dimensions.width = positive(d, d["width"], what + ": dimensions 'width'");
        a.dimensions.height = positive(d, d["height"], what + ": dimensions 'height'");
    }

    void performance(const YAML::Node& node, Asset& a, const std::string& what) {
        const auto p = node["performance"];
        yaml::require(file_, p ? p : node, p && p.IsMap(),
                      what + ": 'performance' {max_speed_kmh, max_acceleration, max_deceleration} is missing");
        yaml::check_keys(file_, p, {"max_speed_kmh", "max_acceleration", "max_deceleration"}, what + ": performance");
        a.max_speed_mps = positive(p, p["max_speed_kmh"], what + ": 'max_speed_kmh'") / 3.6;
        a.max_acceleration = positive(p, p["max_acceleration"], what + ": 'max_acceleration'");
        a.max_deceleration = positive(p, p["max_deceleration"], what + ": 'max_deceleration'");
    }
};

} // namespace

const std::string* Asset::attribute(const std::string& name) const {
    for (const auto& [n, v] : attributes) {
        if (n == name) {
            return &v;
        }
    }
    return nullptr;
}

const Asset* Catalog::find(const std::string& id) const {
    for (const auto& a : assets) {
        if (a.id == id) {
            return &a;
        }
    }
    return nullptr;
}

std::vector<const Asset*> Catalog::under(const std::string& element_path) const {
    std::vector<const Asset*> out;
    for (const auto& a : assets) {
        if (a.element == element_path || a.element.rfind(element_path + "/", 0) == 0) {
            out.push_back(&a);
        }
    }
    return out;
}

Catalog load_catalog(const std::filesystem::path& path, const odd::Taxonomy& taxonomy) {
    Catalog catalog;
    catalog.source = path.string();
    const YAML::Node root = yaml::load_file(path, "asset catalog");
    CatalogLoader(catalog, taxonomy).root(root);
    return catalog;
}

Actor actor_from(const Asset& asset, const std::string& name, const std::string& entry) {
    Actor a;
    a.name = name;
    a.kind = asset.kind;
    a.category = asset.osc_category;
    a.asset_id = asset.id;
    a.catalog_entry = entry;
    a.model3d = asset.carla_blueprint;
    a.mass_kg = asset.mass_kg;
    a.dimensions = asset.dimensions;
    a.max_speed_mps = asset.max_speed_mps;
    a.max_acceleration = asset.max_acceleration;
    a.max_deceleration = asset.max_deceleration;
    a.properties.emplace_back("odd_element", asset.element);
    for (const auto& [n, v] : asset.attributes) {
        a.properties.emplace_back(n, v);
    }
    return a;
}

} // namespace railodd::scenario
