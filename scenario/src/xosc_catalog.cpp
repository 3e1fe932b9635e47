// Catalog documents: the Vehicle / Pedestrian / MiscObject definitions the
// scenario's CatalogReferences name. Each entry carries the physical data of
// its asset and, in <Properties>, the actor's properties (ODD attributes,
// behaviour file) plus "carla_blueprint" = model3d for the CARLA adapter.
// Under the carla target the entries are OpenSCENARIO 1.0 as ScenarioRunner
// reads them: named by their blueprints (target.hpp entry_name), a
// Pedestrian's model the blueprint, vehicles typed by a parameter.
#include "railodd/scenario/xosc_writer.hpp"

#include "xosc_support.hpp"

#include <algorithm>
#include <set>

namespace railodd::scenario {

using xosc::attr;

namespace {

// Wheel size and track width by vehicle category: the schema requires axles,
// the assets do not describe them, and a plausible value beats a zero for
// tools that draw or simulate wheels.
struct AxleShape {
    double wheel_diameter;
    double track_width; // < 0: a fraction of the vehicle width
    double max_steering;
};

AxleShape axle_shape(const std::string& category) {
    if (category == "train") {
        return {0.92, 1.435, 0.0}; // standard gauge; rail vehicles do not steer
    }
    if (category == "tram") {
        return {0.68, 1.435, 0.0};
    }
    if (category == "bus" || category == "truck" || category == "semitrailer" || category == "trailer") {
        return {1.0, -0.85, 0.5};
    }
    if (category == "motorbike" || category == "bicycle") {
        return {0.66, 0.0, 0.5}; // single track
    }
    return {0.65, -0.85, 0.5}; // car, van
}

void axle(pugi::xml_node n, const AxleShape& shape, double x, double width, bool steers) {
    attr(n, "maxSteering", steers ? shape.max_steering : 0.0);
    attr(n, "wheelDiameter", shape.wheel_diameter);
    attr(n, "trackWidth", shape.track_width < 0.0 ? -shape.track_width * width : shape.track_width);
    attr(n, "positionX", x);
    attr(n, "positionZ", shape.wheel_diameter / 2.0);
}

// Reference point: the bounding box centre on the ground, so the box is
// centred at x = y = 0 and half its height up.
void bounding_box(pugi::xml_node parent, const Dimensions& d) {
    pugi::xml_node box = parent.append_child("BoundingBox");
    pugi::xml_node c = box.append_child("Center");
    attr(c, "x", 0.0);
    attr(c, "y", 0.0);
    attr(c, "z", d.height / 2.0);
    pugi::xml_node dim = box.append_child("Dimensions");
    attr(dim, "width", d.width);
    attr(dim, "length", d.length);
    attr(dim, "height", d.height);
}

// Under a target that tells the ego by a Property (Profile::ego_type_property)
// a vehicle's "type" is the entry parameter ActorType, "scenario" unless the
// ego's CatalogReference assigns "ego_vehicle" (xosc_writer.cpp): one entry
// serves a train as the ego and as a stabled train.
void actor_type(pugi::xml_node vehicle, pugi::xml_node props) {
    pugi::xml_node d = vehicle.append_child("ParameterDeclarations").append_child("ParameterDeclaration");
    attr(d, "name", xosc::actor_type_parameter);
    attr(d, "parameterType", "string");
    attr(d, "value", "scenario");
    pugi::xml_node p = props.append_child("Property");
    attr(p, "name", "type");
    attr(p, "value", std::string{"$"} + xosc::actor_type_parameter);
}

pugi::xml_node properties(pugi::xml_node parent, const Actor& a) {
    pugi::xml_node props = parent.append_child("Properties");
    bool has_blueprint = false;
    for (const auto& [name, value] : a.properties) {
        pugi::xml_node p = props.append_child("Property");
        attr(p, "name", name);
        attr(p, "value", value);
        has_blueprint = has_blueprint || name == "carla_blueprint";
    }
    if (!has_blueprint && !a.model3d.empty()) {
        pugi::xml_node p = props.append_child("Property");
        attr(p, "name", "carla_blueprint");
        attr(p, "value", a.model3d);
    }
    return props;
}

// OpenSCENARIO 1.0 has no model3d, and a Vehicle no mass; its Pedestrian
// requires `model` (ScenarioRunner spawns that blueprint).
void common_attributes(pugi::xml_node n, const Actor& a, const char* category_attribute, const WriteOptions& opt) {
    attr(n, "name", a.catalog_entry);
    attr(n, category_attribute, a.category);
    if (opt.rev_minor >= 1 || a.kind != Actor::Kind::vehicle) {
        attr(n, "mass", a.mass_kg);
    }
    if (opt.rev_minor < 1 && a.kind == Actor::Kind::pedestrian) {
        attr(n, "model", a.model3d.empty() ? a.catalog_entry : a.model3d);
    } else if (opt.rev_minor >= 1 && !a.model3d.empty()) {
        attr(n, "model3d", a.model3d);
    }
}

void vehicle(pugi::xml_node catalog, const Actor& a, const WriteOptions& opt) {
    pugi::xml_node v = catalog.append_child("Vehicle");
    common_attributes(v, a, "vehicleCategory", opt);
    bounding_box(v, a.dimensions);
    pugi::xml_node perf = v.append_child("Performance");
    attr(perf, "maxSpeed", a.max_speed_mps);
    attr(perf, "maxAcceleration", a.max_acceleration);
    attr(perf, "maxDeceleration", a.max_deceleration);
    // Axles (bogie centres for rail vehicles) 15 % of the length in from each end.
    const AxleShape shape = axle_shape(a.category);
    const double x = std::max(0.0, a.dimensions.length * 0.35);
    pugi::xml_node axles = v.append_child("Axles");
    axle(axles.append_child("FrontAxle"), shape, x, a.dimensions.width, true);
    axle(axles.append_child("RearAxle"), shape, -x, a.dimensions.width, false);
    pugi::xml_node props = properties(v, a);
    if (target_support::profile(opt.target).ego_type_property) {
        actor_type(v, props);
    }
}

} // namespace

void xosc::write_catalog_entry(pugi::xml_node catalog, const Actor& a, const WriteOptions& opt) {
    switch (a.kind) {
    case Actor::Kind::vehicle:
        vehicle(catalog, a, opt);
        return;
    case Actor::Kind::pedestrian: {
        pugi::xml_node p = catalog.append_child("Pedestrian");
        common_attributes(p, a, "pedestrianCategory", opt);
        bounding_box(p, a.dimensions);
        properties(p, a);
        return;
    }
    case Actor::Kind::misc_object: {
        pugi::xml_node m = catalog.append_child("MiscObject");
        common_attributes(m, a, "miscObjectCategory", opt);
        bounding_box(m, a.dimensions);
        properties(m, a);
        return;
    }
    }
}

std::string catalog_text(const std::string& catalog_name, const std::vector<Actor>& entries,
                         const WriteOptions& opt, const std::string& date) {
    pugi::xml_document doc;
    pugi::xml_node root = xosc::begin_document(doc, opt, date, "railodd catalog " + catalog_name, "railodd");
    pugi::xml_node catalog = root.append_child("Catalog");
    attr(catalog, "name", catalog_name);
    // The schema orders a catalog's children by kind: vehicles, pedestrians, misc objects.
    std::set<std::string> written;
    for (const auto kind : {Actor::Kind::vehicle, Actor::Kind::pedestrian, Actor::Kind::misc_object}) {
        for (const auto& a : entries) {
            if (a.kind == kind && written.insert(a.catalog_entry).second) {
                xosc::write_catalog_entry(catalog, a, opt);
            }
        }
    }
    target_support::check_document(root, opt.target);
    return xosc::to_text(doc);
}

void write_catalog(const std::string& catalog_name, const std::vector<Actor>& entries,
                   const std::filesystem::path& file, const WriteOptions& opt, const std::string& date) {
    xosc::write_atomically(file, catalog_text(catalog_name, entries, opt, date));
}

} // namespace railodd::scenario
