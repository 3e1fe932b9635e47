#pragma once
// Base-scenario templates (data/scenario/templates.yaml, docs/scenarios.md
// "Templates"): a parameterised text whose {placeholders} are ODD elements and
// attributes, the infrastructure the scenario needs on the route, the actors
// and where they stand, the parameter domains, the perturbations and the
// constraints. Loaded against the taxonomy and the asset catalog so that every
// name in it is known.
#include "railodd/odd/taxonomy.hpp"
#include "railodd/scenario/catalog.hpp"

#include <filesystem>
#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace railodd::scenario {

// A condition on one attribute of a profile element: a numeric range or a set
// of allowed values.
struct AttributeCondition {
    std::string attribute;
    std::optional<double> min; // inclusive
    std::optional<double> max; // inclusive
    std::vector<std::string> values;
    int line = 0;
};

struct ElementMatch {
    std::string element; // taxonomy path; matches the element and everything below it
    std::vector<AttributeCondition> where;
    int line = 0;
};

enum class AnchorAt { start, middle, end }; // where on a stretch element the anchor point lies

struct AnchorRequirement : ElementMatch {
    AnchorAt at = AnchorAt::start;
    // At a switch: run on through it (the smoothest continuation) or onto
    // its diverging track.
    bool diverging = false;
};

// Another element the route must have within `within_m` before the anchor (in
// the ego's direction of travel): "a curve followed within 500 m by a level
// crossing" is a level-crossing anchor with a curve context.
struct ContextRequirement : ElementMatch {
    double within_m = 500.0;
};

// Where an actor stands, across the track: on the rail lane, at the platform
// edge (on the platform's side), beside the track, or on the road approaching
// a level crossing.
// branch_track: on a switch anchor's other track (the diverging one of a
// facing switch, the joining one of a trailing switch), |along_m| from the
// switch along it.
// adjacent_track: where a neighbouring track of a double line lies (4.0 m
// centre to centre), on the platform's side or the left.
enum class Lateral { on_track, platform_edge, beside_track, crossing_approach, adjacent_track, branch_track };
const char* to_string(Lateral lateral);

struct EgoTemplate {
    std::string asset_class = "Dynamic Elements/Rail vehicle/Ego train";
    double run_up_m = 800.0;  // start this far before the anchor (less where the track begins)
    double min_run_up_m = 100.0; // anchors with less track before them are skipped
    double overrun_m = 200.0; // the run ends this far past the anchor
    // Or the train stops this far short of the anchor (a buffer stop, the
    // end of a platform): the run ends there and needs no track beyond.
    std::optional<double> stop_before_m;
};

struct ActorTemplate {
    std::string name;        // entity name in the scenario
    std::string asset_class; // taxonomy path the actor's asset lies under
    Lateral place = Lateral::on_track;
    double along_m = 0.0;    // along the track from the anchor, positive in travel direction
    std::optional<Lateral> move_to; // moves there when triggered
    double move_speed_kmh = 0.0;
    double trigger_before_m = 0.0;  // the move starts when the ego is this far from the anchor
    // Or: the move is timed so that the actor reaches its target (the hazard
    // happens) when the ego's front is this far short of it.
    std::optional<double> hazard_before_m;
    std::string behaviour;          // the asset element's behaviour value, or free text for behavior.yaml
    int line = 0;
};

enum class ParameterKind {
    ego_speed,    // km/h: values, or fractions of the local speed limit
    actor_asset,  // an asset id for an actor: every asset under its class, or a list
    map_value,    // bound to an attribute of the anchor or of a context element
    perturbation, // an Environmental Conditions attribute value
    choice,       // one of a list of words (a signal's aspect): an OpenSCENARIO string parameter
    degraded_mode, // one of the template set's degraded modes (DegradedMode)
};

// One ODD value a degraded mode stands for. Values with an OpenSCENARIO
// mapping (environment.hpp) set the scenario's environment; the others
// (GNSS, train radio, a dirty lens) are carried as parameters and in the
// behaviour file.
struct ModeSetting {
    std::string element;   // taxonomy path
    std::string attribute;
    std::string value;
    bool environment = false; // applied to the OpenSCENARIO environment
};

// A degraded operating mode (templates file, `degraded_modes`): perception,
// positioning, communication or adhesion, with the ODD values it stands for.
struct DegradedMode {
    std::string id;
    std::string family; // perception, positioning, communication, adhesion, none
    std::string text;   // for scenario texts
    std::vector<ModeSetting> sets;
    int line = 0;
};
const char* to_string(ParameterKind kind);

struct ParameterDomain {
    std::string name; // the placeholder
    ParameterKind kind = ParameterKind::perturbation;
    std::vector<std::string> values;      // text of each value (numbers as written)
    std::vector<double> limit_fractions;  // ego_speed: fractions of the local limit
    std::string actor;                    // actor_asset
    int context = -1;                     // map_value: -1 anchor, else index into context
    std::string element;                  // map_value, perturbation: taxonomy path
    std::string attribute;                // map_value, perturbation
    std::string unit;                     // from the taxonomy, for texts
    std::vector<DegradedMode> modes;      // degraded_mode: per value
    int line = 0;
};

struct Exclusion {
    std::vector<std::pair<std::string, std::string>> values; // parameter name -> value
    int line = 0;
};

struct Template {
    std::string id;
    std::string text;
    std::vector<std::string> placeholders; // in text order
    AnchorRequirement anchor;
    std::vector<ContextRequirement> context;
    EgoTemplate ego;
    std::vector<ActorTemplate> actors;
    std::vector<ParameterDomain> parameters; // parameters, then perturbations, file order
    bool speed_within_limit = true;          // ego speed <= the limit at the anchor
    std::vector<Exclusion> exclusions;
    int line = 0;

    const ParameterDomain* parameter(const std::string& name) const;
};

struct TemplateSet {
    std::string source;
    std::vector<DegradedMode> degraded_modes;
    std::vector<Template> templates;
};

// Reads and checks the templates. Throws railodd::InputError "FILE:LINE:
// problem" naming the template and element for: YAML errors, unknown keys,
// duplicate ids, elements or attributes not in the taxonomy, values outside an
// enum or outside every bin of the attribute, placeholders without a parameter,
// parameters of unknown actors or contexts, actor classes with no asset in the
// catalog, assets not in the catalog or not under the actor's class, and
// exclusions naming unknown parameters or values.
TemplateSet load_templates(const std::filesystem::path& path, const odd::Taxonomy& taxonomy, const Catalog& catalog);

} // namespace railodd::scenario
