#pragma once
// A concrete scenario as the OpenSCENARIO writer sees it: every actor placed on
// a lane of the map, every value fixed. The generator (generator.hpp) fills it
// from a template, an anchor on the route and one row of parameter values; the
// writer (xosc_writer.hpp) turns it into ID.xosc without further decisions.
#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace railodd::scenario {

// A place on the map: lane `lane_id` of road `road_id` at `s`, `offset` metres
// to the left of the lane centre. `reversed`: the actor faces against the
// road's s direction (OpenSCENARIO Orientation relative h = pi).
struct LanePlacement {
    std::string road_id;
    int lane_id = -1;
    double s = 0.0;
    double offset = 0.0;
    bool reversed = false;
    double heading = 0.0; // rad, added to the lane's direction (and to pi when reversed)
};

struct Dimensions {
    double length = 0.0;
    double width = 0.0;
    double height = 0.0;
};

// An entity of the scenario, defined by an asset of the catalog.
struct Actor {
    enum class Kind { vehicle, pedestrian, misc_object };

    std::string name;     // entity name, unique in the scenario ("Ego", "Obstacle", ...)
    Kind kind = Kind::vehicle;
    std::string category; // vehicleCategory ("train", "tram", "car", "truck", "bus", "motorbike",
                          // "bicycle"), pedestrianCategory ("pedestrian", "animal") or
                          // miscObjectCategory ("obstacle", ...)
    std::string asset_id; // catalog asset id
    std::string catalog_entry; // entry name in the generated OpenSCENARIO catalog
    std::string model3d;       // e.g. the CARLA blueprint id
    double mass_kg = 0.0;
    Dimensions dimensions;
    double max_speed_mps = 0.0;
    double max_acceleration = 0.0; // m/s^2
    double max_deceleration = 0.0; // m/s^2

    LanePlacement start;
    double speed_mps = 0.0;             // initial speed; 0: stands
    std::vector<LanePlacement> route;   // waypoints of an AssignRouteAction, in travel order (ego)
    // A motion started by the trigger: move to `target` at `target_speed_mps`
    // (a pedestrian stepping onto the track, a car driving onto the crossing).
    // The motion's path (its first point the start, its last the target);
    // the actor stops at its end.
    std::optional<LanePlacement> target;
    std::vector<LanePlacement> path;
    double target_speed_mps = 0.0;
    std::string place, move_to; // the template's places (templates.hpp Lateral), for the manifest and play checks
    std::optional<double> hazard_before_m; // the template's timing: at the target when the ego's front is this far short
    std::vector<std::pair<std::string, std::string>> properties; // <Properties>: odd attributes, behaviour file
};

// Environmental conditions from the perturbations (the taxonomy's
// Environmental Conditions), in the units of OpenSCENARIO 1.2.
struct Environment {
    std::string name = "Environment";
    std::string date_time = "2026-06-21T12:00:00"; // TimeOfDay, ISO 8601 without zone
    double sun_azimuth_rad = 0.0;
    double sun_elevation_rad = 1.0;
    double sun_illuminance_lux = 100000.0;
    double fractional_cloud_cover = 0.0;  // 0..1, written as oktas (fractionalCloudCover)
    double fog_visual_range_m = 100000.0;
    std::string precipitation = "dry"; // "dry", "rain", "snow"
    double precipitation_intensity_mm_h = 0.0;
    double wind_speed_mps = 0.0;
    double wind_direction_rad = 0.0;
    double air_temperature_c = 15.0;
    double friction_scale = 1.0;       // RoadCondition frictionScaleFactor (rail head condition)
};

// What a parameter stands for: a value the storyboard uses, or one no
// OpenSCENARIO action carries (declared so a player or controller can read
// it; also in the behaviour file's `conditions`).
enum class ParameterRole {
    storyboard,    // speeds, assets, the environment
    choice,        // a template choice, e.g. a signal's aspect
    degraded_mode, // the degraded mode's id
    mode_setting,  // a degraded mode's setting without an OpenSCENARIO mapping (GNSS, radio, lens)
};

// A scenario parameter: declared in the .xosc and used by the actions it
// drives, so that a ParameterValueDistribution can vary it.
struct Parameter {
    std::string name; // OpenSCENARIO parameter name without "$"
    std::string type; // "double", "string", "int"
    std::string value;
    ParameterRole role = ParameterRole::storyboard;
};

// A point of the ego's run and its distance from the run's start along the track.
struct TrackSample {
    double distance_m = 0.0;
    LanePlacement place;
};

struct ConcreteScenario {
    std::string id;          // file stem: ID.xosc
    std::string description; // the template's text with the placeholders filled
    std::string author = "railodd";
    std::string date = "2026-01-01T00:00:00"; // FileHeader date (from the map, for determinism)
    std::string map_file;    // LogicFile path, relative to the .xosc
    std::string catalog_dir; // catalog directory, relative to the .xosc
    std::vector<Parameter> parameters;
    Actor ego;                   // the train: vehicleCategory train or tram, on its rail lane
    std::vector<Actor> others;
    Environment environment;
    // The others' motions start when the ego has travelled this far from its start.
    double trigger_distance_m = 0.0;
    // The ego stands this long before it sets off: where the track before the
    // anchor is too short for the actors' moves to be timed by the ego's
    // distance alone (ActorTemplate::hazard_before_m).
    double ego_start_delay_s = 0.0;
    // What OpenSCENARIO 1.x has no action for (a degraded mode's GNSS or
    // radio loss, a signal's aspect): name -> value, declared as string
    // parameters and written to the behaviour file's `conditions`.
    std::vector<std::pair<std::string, std::string>> conditions;
    double stop_time_s = 60.0; // simulation stops at this time ...
    std::optional<LanePlacement> ego_end; // ... or when the ego reaches this place
    double ego_run_m = 0.0;               // along the track from its start to ego_end
    // The ego's run sampled along its line, first the start, last the end:
    // for players that follow positions rather than route over the map
    // (ScenarioRunner: CARLA's router plans on driving lanes only). Empty
    // unless the target needs it (GenerateOptions::target).
    std::vector<TrackSample> ego_track;
};


// Parameter names the writer knows: when ConcreteScenario::parameters declares
// one, the attribute it stands for is written as "$NAME" (the value stays in
// the declaration), so a ParameterValueDistribution can vary it.
namespace parameter_names {
inline constexpr const char* ego_speed = "EgoSpeed";                       // m/s, ego SpeedAction
inline constexpr const char* time_of_day = "TimeOfDay";                    // dateTime
inline constexpr const char* sun_elevation = "SunElevation";               // rad
inline constexpr const char* sun_azimuth = "SunAzimuth";                   // rad
inline constexpr const char* cloud_cover = "CloudCover";                   // oktas, as written
inline constexpr const char* fog_visual_range = "FogVisualRange";          // m
inline constexpr const char* precipitation_type = "PrecipitationType";     // dry / rain / snow
inline constexpr const char* precipitation_intensity = "PrecipitationIntensity"; // mm/h
inline constexpr const char* friction_scale = "FrictionScale";
// Per other actor NAME: NAME + "Asset" (catalog entry), NAME + "Speed" (m/s, target speed).
} // namespace parameter_names

// A template parameter's OpenSCENARIO name, in the writer's style
// ("signal_aspect" -> "SignalAspect").
std::string osc_parameter_name(const std::string& name);

// Names railodd declares itself in every scenario (parameter_names,
// DegradedMode, ACTORAsset and ACTORSpeed of each actor): a choice parameter
// of one of them would be silently dropped from the .xosc.
bool is_reserved_parameter(const std::string& osc_name, const std::vector<std::string>& actors);

} // namespace railodd::scenario
