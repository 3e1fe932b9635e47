#pragma once
// A route between two stations over the track graph (`railodd convert
// --from NAME --to NAME`, docs/odd.md "Routes"): the shortest path a train
// can run, with its own chainage, and the ODD profile along it.
#include "railodd/geometry/feature_attachment.hpp"
#include "railodd/geometry/track_fit.hpp"
#include "railodd/geometry/track_graph.hpp"
#include "railodd/ingest/types.hpp"
#include "railodd/odd/profile.hpp"
#include "railodd/odd/taxonomy.hpp"

#include <cstddef>
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

struct Route {
    std::string from; // the station names as found in the data
    std::string to;
    double length_m = 0.0;
    std::vector<RoutePiece> pieces;  // in travel order
    std::vector<std::string> osm_ways; // "way:ID" of the edges on the route, for unparsed values
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

// The profile along the route: elements on the route's pieces, clipped to
// them, with chainage along the route (ends swapped on reversed pieces so
// chainage_start <= chainage_end), ordered by chainage; road_id and s stay
// map coordinates (s moved in by what clipping cut off). route, length_m,
// tracks (number of pieces) and summary describe the route.
OddProfile along_route(const OddProfile& profile, const Route& route, const Taxonomy& taxonomy);

// report.json's "route" section: {from, to, length_m, pieces: [{edge,
// reversed, s_from, s_to, chainage_start}]}.
nlohmann::ordered_json route_report(const Route& route);

} // namespace railodd::odd
