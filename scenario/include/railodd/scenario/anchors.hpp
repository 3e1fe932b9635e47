#pragma once
// Anchoring templates on the real route (docs/scenarios.md "Anchors"): the
// places where the ODD profile satisfies a template's infrastructure
// requirement, and the lane positions along the track around them.
#include "railodd/odd/profile.hpp"
#include "railodd/scenario/concrete.hpp"
#include "railodd/scenario/templates.hpp"

#include <cstddef>
#include <cstdint>
#include <limits>
#include <map>
#include <set>
#include <optional>
#include <string>
#include <vector>

namespace railodd::scenario {

// Chainage to lane positions. A line is one track (graph edge) of a whole-map
// profile, continued at both ends across switches onto the smoothest
// following track (line_index.cpp), or the whole route of a route profile;
// the horizontal-geometry elements tile every line, so they carry the road
// and s of each chainage.
class LineIndex {
public:
    explicit LineIndex(const odd::OddProfile& profile);

    std::size_t line_of(const odd::TaggedElement& e) const { return along_route_ ? 0 : e.track; }
    bool has_line(std::size_t line) const { return lines_.contains(line); }
    double start(std::size_t line) const;
    double end(std::size_t line) const;
    // The rail lane's centre at `chainage`, facing the direction of growing chainage.
    std::optional<LanePlacement> at(std::size_t line, double chainage) const;
    // Waypoints from c0 to c1: both ends and the middle of every road run between.
    std::vector<LanePlacement> waypoints(std::size_t line, double c0, double c1) const;
    // The line that runs along the switch element's track up to the switch
    // and then onto its diverging track (whole-map profiles); nullopt where
    // the profile has no such track. Its chainages up to the switch are the
    // track's own.
    std::optional<std::size_t> diverging(std::size_t switch_element) const;
    // The rail lane `distance` metres from a switch along its other track
    // (the diverging track of a facing switch, the joining one of a trailing
    // switch), away from the switch; nullopt where there is none or it is shorter.
    std::optional<LanePlacement> branch_place(std::size_t switch_element, double distance) const;
    // Where the line entered the road it is on at `chainage` (the chainage
    // itself where no piece holds it).
    double road_entry(std::size_t line, double chainage) const;

private:
    struct Piece {
        double c0, c1;
        std::string road_id;
        double s0, s1;
        bool reversed;
    };
    bool along_route_ = false;
    std::map<std::size_t, std::vector<Piece>> lines_; // by chainage
    std::map<std::size_t, std::size_t> diverging_;    // switch element -> its diverging line
    struct Branch {
        std::size_t track = 0;
        bool against = false;            // entered at its end: run against its chainage
        bool trailing = false;           // joins from behind the train: no diverging run
        double c_start = 0.0, c_end = 0.0; // the track's own chainages
    };
    std::map<std::size_t, Branch> branches_;          // switch element -> its other track
    std::optional<Branch> branch_of(const odd::OddProfile& profile, std::size_t element) const;
    const Piece* piece(std::size_t line, double chainage) const;
    std::vector<Piece> extend(const std::vector<odd::TrackEnd>& ends, const odd::TrackEnd& own) const;
    double append(std::vector<Piece>& out, std::size_t track, bool against, bool forward, double at) const;
    void run_on(std::vector<Piece>& out, const std::vector<odd::TrackEnd>& ends, std::int64_t node, double heading,
                bool forward, double at, std::set<std::size_t> used, std::set<std::int64_t> passed) const;
    std::vector<Piece> diverging_line(const odd::OddProfile& profile, std::size_t element,
                                      const std::map<std::size_t, std::vector<Piece>>& extended) const;
};

struct Anchor {
    std::size_t element = 0;          // index into profile.elements
    std::vector<std::size_t> context; // per context requirement: the matched element
    std::size_t line = 0;
    double chainage = 0.0;            // the anchor point
    LanePlacement place;
    double start_chainage = 0.0;      // the ego's start ...
    double end_chainage = 0.0;        // ... and end of its run
    double speed_limit_kmh = std::numeric_limits<double>::quiet_NaN(); // at the anchor; NaN: unknown
};

struct SkippedAnchor {
    std::size_t element = 0;
    std::string reason;
};

struct Anchoring {
    std::vector<Anchor> anchors; // by line, then chainage
    std::vector<SkippedAnchor> skipped;
};

// Whether the element is `match.element` or below it and satisfies its conditions.
bool matches(const odd::TaggedElement& e, const ElementMatch& match);

// Every place on the profile where the template's anchor and context
// requirements hold, the ego travelling in the direction of growing chainage.
// Anchors with less than the template's minimum run-up before them, with too
// little track before them for an actor's hazard_before_m (the train's front,
// `ego_half_length_m` ahead of its reference point, must start further off),
// or too little after them to run past are skipped with the reason.
Anchoring find_anchors(const odd::OddProfile& profile, const LineIndex& lines, const Template& t,
                       double ego_half_length_m = 0.0);

} // namespace railodd::scenario
