#pragma once
// A route over the track graph with its own chainage, and the ODD profile
// along it (docs/odd.md "Routes"): between two stations (`railodd convert
// --from NAME --to NAME`, the shortest path a train can run) or along an OSM
// route relation (`--relation ID`, its member ways in member order).
#include "railodd/geometry/feature_attachment.hpp"
#include "railodd/geometry/track_fit.hpp"
#include "railodd/geometry/track_graph.hpp"
#include "railodd/ingest/types.hpp"
#include "railodd/odd/profile.hpp"
#include "railodd/odd/taxonomy.hpp"

#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

namespace railodd::odd {

// One stretch of one graph edge on the route. s is along the edge's fitted
// alignment; s_from is where the route enters the stretch and s_to where it
// leaves it, so s_from > s_to when the route runs against the alignment.
struct RoutePiece {
    std::size_t edge = 0;
    bool reversed = false; // traversed against the alignment (s falls as chainage grows)
    double s_from = 0.0;
    double s_to = 0.0;
    double chainage_start = 0.0; // route chainage at s_from
};

// Where consecutive member ways of a relation do not meet.
struct RouteGap {
    double chainage = 0.0;       // route chainage at the gap
    std::int64_t after_way = 0;  // the member way the route leaves
    std::int64_t before_way = 0; // the member way it continues on
    double distance_m = 0.0;     // straight line between the two ends
    bool bridged = false;        // joined by the shortest path over the selected tracks
    double bridge_length_m = 0.0;
};

struct Route {
    std::string from; // the station names as found in the data (a relation's from/to tags)
    std::string to;
    std::string description; // odd_profile's route description; empty: "FROM -> TO"
    double length_m = 0.0;
    std::vector<RoutePiece> pieces;  // in travel order
    std::vector<std::string> osm_ways; // "way:ID" of the edges on the route, for unparsed values
    // Routes along a relation only:
    std::int64_t relation = 0;
    std::string name;
    std::size_t member_ways = 0;     // way members of the relation (platforms included)
    std::size_t ways_on_route = 0;   // of those, track ways of the selection that the route runs
    std::vector<RouteGap> gaps;
};

// The shortest route from the station (halt, stop, tram stop) named `from`
// to the one named `to`: names match exactly, else ignoring case; when one
// name belongs to several attached features (a station node and its stop
// positions), every pairing is tried and the shortest kept. Trains pass a
// vertex only along a through route (consecutive edges of a chain) or a
// switch movement (a branch to the switch's stem). Throws railodd::InputError
// naming the station when no attached station has the name (listing the
// stations there are), and when no path joins the two.
Route find_route(const geometry::TrackGraph& graph, const geometry::FittedNetwork& fitted,
                 const geometry::Attachment& attachment, const std::vector<ingest::Feature>& features,
                 const std::string& from, const std::string& to);

// The route along the rail route relation `relation` (read by the OSM reader
// with --relation): its member ways in member order, each run in the
// direction that continues from the previous one (the first towards the
// second). Where consecutive members do not meet, the shortest path over the
// selected tracks bridges the gap; where none exists the route jumps to the
// next member and the gap is listed (route.gaps, report.json) rather than
// refused, as extracts clip relations. Member ways that are not tracks of
// the selection (platforms, ways outside the extract) are skipped. Throws
// railodd::InputError naming `file` and the relation when no member is a
// track of the graph.
Route relation_route(const geometry::TrackGraph& graph, const geometry::FittedNetwork& fitted,
                     const std::vector<ingest::Way>& tracks, const ingest::RouteRelation& relation,
                     const std::string& file);

// The profile along the route: elements on the route's pieces, clipped to
// them, with chainage along the route (ends swapped on reversed pieces so
// chainage_start <= chainage_end), ordered by chainage; road_id and s stay
// map coordinates (s moved in by what clipping cut off). route, length_m,
// tracks (number of pieces) and summary describe the route.
OddProfile along_route(const OddProfile& profile, const Route& route, const Taxonomy& taxonomy);

// report.json's "route" section: {from, to, length_m, pieces: [{edge,
// reversed, s_from, s_to, chainage_start}]}; along a relation also
// {relation, name, member_ways, ways_on_route, gaps: [{chainage, after_way,
// before_way, distance_m, bridged, bridge_length_m}]} after length_m.
nlohmann::ordered_json route_report(const Route& route);

} // namespace railodd::odd
