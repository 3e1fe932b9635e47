#pragma once
// Helpers shared by the OpenSCENARIO writer's files: number formatting,
// attributes, parameter references, revision differences, and the atomic file
// write.
#include "railodd/scenario/concrete.hpp"
#include "railodd/scenario/xosc_writer.hpp"
#include "target_support.hpp"

#include <pugixml.hpp>

#include <filesystem>
#include <set>
#include <string>
#include <string_view>
#include <vector>

namespace railodd::scenario::xosc {

// Fixed notation, at most 6 decimals (micrometres, microradians), trailing
// zeros dropped, never "-0": stable across runs and locales. Non-finite
// values throw std::domain_error: they are a bug upstream, not a scenario.
std::string num(double v);

inline void attr(pugi::xml_node n, const char* name, const std::string& value) {
    n.append_attribute(name).set_value(value.c_str());
}
inline void attr(pugi::xml_node n, const char* name, const char* value) {
    n.append_attribute(name).set_value(value);
}
inline void attr(pugi::xml_node n, const char* name, double value) { attr(n, name, num(value)); }
inline void attr(pugi::xml_node n, const char* name, int value) { attr(n, name, std::to_string(value)); }

// Throws UsageError unless the target reads the revision (1.1 to 1.3 for
// esmini, 1.0 for carla).
void check_revision(const WriteOptions& opt);

// A new document: XML declaration, <OpenSCENARIO> and its <FileHeader>; returns
// the root element.
pugi::xml_node begin_document(pugi::xml_document& doc, const WriteOptions& opt, const std::string& date,
                              const std::string& description, const std::string& author);

// The document as text (two-space indent, UTF-8).
std::string to_text(const pugi::xml_document& doc);

// Writes `text` to a temporary file beside `file` and renames it into place.
void write_atomically(const std::filesystem::path& file, std::string_view text);

// The scenario's parameters, the revision and the target: what the writers
// of the scenario document need besides the scenario itself. It also records
// which declared parameters the document expresses and what the target made
// the writer drop, for XoscDocument::degraded_for_target.
class Context {
public:
    Context(const ConcreteScenario& sc, const WriteOptions& opt) : sc_(sc), opt_(opt) {}
    const ConcreteScenario& scenario() const { return sc_; }
    int rev_minor() const { return opt_.rev_minor; }
    Target target() const { return opt_.target; }

    bool declared(std::string_view name) const;
    // The value of an attribute of `element` that the parameter `name` may
    // drive: "$name" when it is declared and the target resolves references
    // in that element, else the literal. Marks the parameter expressed.
    std::string value(std::string_view element, std::string_view name, const std::string& literal) const;
    std::string value(std::string_view element, std::string_view name, double literal) const {
        return value(element, name, num(literal));
    }
    // Whether the target reads `element` (an action, condition or position)
    // at `where` and runs it (target_support::usable).
    bool usable(std::string_view element, target_support::Where where) const;
    const target_support::Profile& profile() const { return target_support::profile(opt_.target); }

    // A value the target cannot express and the writer leaves out: kept as a
    // parameter (declared with `type` and `value` unless the scenario declares
    // `name` already) and listed with the reason.
    void drop(const std::string& name, const std::string& type, const std::string& value,
              const std::string& reason) const;
    // Declarations the writer added for dropped values.
    const std::vector<Parameter>& added() const { return added_; }
    // Every declared parameter the document does not express, and every
    // dropped value, in declaration order (empty for esmini).
    std::vector<Degradation> degraded() const;

private:
    const ConcreteScenario& sc_;
    WriteOptions opt_;
    mutable std::set<std::string, std::less<>> expressed_;
    mutable std::vector<Parameter> added_;
    mutable std::vector<Degradation> dropped_;
};

// <LanePosition> (with its Orientation) as the child of `parent`.
void lane_position(pugi::xml_node parent, const LanePlacement& p, bool orientation = true);
// <Position><LanePosition/></Position> as the child of `parent`.
void position(pugi::xml_node parent, const LanePlacement& p, bool orientation = true);

// <PrivateAction><LongitudinalAction><SpeedAction> to `speed` (a number or
// "$Param") with step dynamics.
void speed_action(pugi::xml_node private_action_parent, const std::string& speed);

// Document sections written by the other files.
void write_init(pugi::xml_node storyboard, const Context& cx);
void write_story(pugi::xml_node storyboard, const Context& cx);
void write_stop_trigger(pugi::xml_node storyboard, const Context& cx);
void write_environment(pugi::xml_node parent, const Context& cx);
void write_catalog_entry(pugi::xml_node catalog, const Actor& a, const WriteOptions& opt);

// The parameter naming an actor's catalog entry: "EgoAsset" for the ego,
// NAME + "Asset" for the others.
std::string asset_parameter(const Actor& a, bool is_ego);

// The catalog entry parameter behind the entry's Property "type" where the
// target tells the ego by it (Profile::ego_type_property): "scenario" unless
// a CatalogReference assigns "ego_vehicle".
inline constexpr const char* actor_type_parameter = "ActorType";

} // namespace railodd::scenario::xosc
