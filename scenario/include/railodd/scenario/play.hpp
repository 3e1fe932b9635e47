#pragma once
// What a played scenario did: the player's recorded trajectories (esmini's
// dat2csv --extended), checked against what the scenario set's manifest says
// each actor should do, and the criticality figures of the run. Nothing here
// runs the player (the CLI's `railodd play` does); everything is read from
// the player's own output, not from railodd's model of the map.
#include <nlohmann/json.hpp>

#include <array>
#include <istream>
#include <map>
#include <optional>
#include <string>
#include <vector>

namespace railodd::scenario::play {

struct Sample {
    double t = 0.0;
    double x = 0.0, y = 0.0, h = 0.0; // world position (m) and heading (rad)
    std::string road_id;               // "-1" or empty: off the road network
    int lane_id = 0;
    double lane_offset = 0.0; // from the lane's centre (m)
    double s = 0.0;
    double speed = 0.0;
};

// Samples per entity, in time order.
using Trajectories = std::map<std::string, std::vector<Sample>>;

// dat2csv --extended CSV ("time, id, name, x, y, z, h, p, r, roadId, laneId,
// offset, t, s, speed, ..."). Throws railodd::InputError naming `source` and
// the line where a row is malformed.
Trajectories read_trajectories(std::istream& in, const std::string& source);

// The player's console log: its [error] and [warn] lines. Errors a player
// prints about what it ignores and that changes nothing in the run are
// counted apart (ignorable_errors), each listed in docs/scenarios.md.
struct PlayerLog {
    std::vector<std::string> errors;
    std::vector<std::string> ignorable_errors;
    std::vector<std::string> warnings; // distinct
};
PlayerLog read_player_log(std::istream& in);

struct Check {
    std::string name;
    bool passed = false;
    std::string detail;
};

struct ActorFigures {
    std::string name;
    double min_distance_m = 0.0;      // between the ego's and the actor's boxes over the run
    std::optional<double> onset_s;    // first time the actor is inside the ego's clearance
    std::optional<double> distance_at_onset_m; // along the track, ego front to the actor
    std::optional<double> ttc_at_onset_s;
    std::optional<double> arrival_s;           // when a moving actor reaches the end of its path
    std::optional<double> distance_at_arrival_m; // along the track, ego front to the actor, then
};

struct Criticality {
    double ego_speed_mps = 0.0;
    double stopping_distance_m = 0.0; // reaction time, then the asset's full service deceleration
    double sight_distance_m = 0.0;    // to the hazard along the track
    std::string sight_limited_by;     // "curve", "fog", "recorded run-up"
    bool can_stop = false;            // stopping distance < sight distance
    std::vector<ActorFigures> actors;
};

struct Options {
    double clearance_margin_m = 0.5; // beyond the ego's half width: its kinematic envelope
    double lane_tolerance_m = 0.05;  // the ego's largest distance from its lane centre
    double sight_corridor_m = 3.5;   // obstructions (cuttings, vegetation, masts) begin this far from the track centre
    double reaction_time_s = 1.0;    // detection to full braking
};

struct Analysis {
    std::vector<Check> checks;
    Criticality criticality;
    bool passed() const;
};

// `scenario`: the scenario's entry of manifest.json.
Analysis analyse(const nlohmann::json& scenario, const Trajectories& run, const PlayerLog& log, const Options& o);

// The map's lanes as esmini's odrplot writes them ("lane, ROAD, SECTION,
// LANE, TYPE" then "x, y, z, h" rows).
struct LaneLine {
    bool driving = false;
    std::vector<std::array<double, 2>> points;
};
std::vector<LaneLine> read_lane_lines(std::istream& in);

// The run as an SVG picture: lanes, recorded paths, train and actors at the
// hazard's onset; the whole run and the 160 m around the hazard.
std::string plot_svg(const nlohmann::json& scenario, const Trajectories& run, const std::vector<LaneLine>& lanes,
                     const Analysis& analysis);

} // namespace railodd::scenario::play
