#include "railodd/ingest/osm_reader.hpp"

#include "feature_selection.hpp"
#include "land_use.hpp"
#include "local_frame.hpp"
#include "osm_passes.hpp"
#include "osm_relations.hpp"
#include "pbf_strings.hpp"
#include "text_coordinates.hpp"
#include "road_selection.hpp"
#include "segment_grid.hpp"
#include "way_parts.hpp"

#include "railodd/util/errors.hpp"
#include "railodd/util/phase_timer.hpp"

#include <osmium/io/any_input.hpp>
#include <osmium/io/file.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <optional>
#include <regex>
#include <vector>

namespace railodd::ingest {

namespace fs = std::filesystem;

namespace {

// Beyond the selection's bounds, the box whose nodes may matter: a selected
// way is kept whole and may run out of the selection, and features count up
// to station_distance_m from a track. Ways that reach into the box are read,
// point features off them only inside it.
constexpr double selection_margin_m = 2000.0;

BBox selection_box(const Selection& sel, const IngestOptions& o) {
    BBox b = sel.bbox.value_or(sel.polygon ? sel.polygon->bounds : BBox{-180, -90, 180, 90});
    if (sel.bbox && sel.polygon) {
        b = {std::max(b.west, sel.polygon->bounds.west), std::max(b.south, sel.polygon->bounds.south),
             std::min(b.east, sel.polygon->bounds.east), std::min(b.north, sel.polygon->bounds.north)};
    }
    const double m = selection_margin_m + std::max({o.feature_distance_m, o.station_distance_m, 0.0});
    const double dlat = m / 111000.0;
    const double max_lat = std::max(std::abs(b.south), std::abs(b.north)) + dlat;
    if (max_lat >= 89.0) { // near a pole: every longitude
        return {-180.0, std::max(-90.0, b.south - dlat), 180.0, std::min(90.0, b.north + dlat)};
    }
    const double dlon = m / (111000.0 * std::cos(max_lat * 3.14159265358979323846 / 180.0));
    return {b.west - dlon, b.south - dlat, b.east + dlon, b.north + dlat};
}

bool any_node_selected(const Way& way, const Selection& sel) {
    for (const auto& part : way.parts) {
        for (const auto& n : part) {
            if (sel.contains(n.lonlat)) {
                return true;
            }
        }
    }
    return false;
}

// Spatial selection and node accounting of the track ways read.
void select_tracks(std::vector<RawWay>& raw, const NodeLocations& locs, const Selection& sel, IngestResult& result) {
    for (auto& r : raw) {
        std::string outline = area_outline_reason(r);
        BuiltWay built = build_way(std::move(r), locator_of(locs));
        if (built.drop_reason.empty()) {
            built.drop_reason = std::move(outline);
        }
        const bool unlocated = built.way.parts.empty() && built.way.missing_nodes == built.way.node_count;
        // A way of which nothing is located cannot be placed: it is kept in the
        // accounting (and dropped) rather than silently left out of the selection.
        if (sel.spatial() && !unlocated && !any_node_selected(built.way, sel)) {
            continue;
        }
        ++result.counts.input_track_ways;
        result.counts.missing_track_nodes += built.way.missing_nodes;
        if (!built.drop_reason.empty()) {
            result.dropped.push_back({"track", "way", built.way.id, built.drop_reason});
            continue;
        }
        add_repairs(result, "track", built);
        result.tracks.push_back(std::move(built.way));
    }
    drop_duplicate_tracks(result.tracks, result.dropped);
}

SegmentGrid track_grid(const std::vector<Way>& tracks, double cell) {
    SegmentGrid grid(cell);
    std::vector<XY> pts;
    for (const auto& way : tracks) {
        for (const auto& part : way.parts) {
            pts.clear();
            for (const auto& n : part) {
                pts.push_back(n.xy);
            }
            grid.add_polyline(pts);
        }
    }
    return grid;
}

std::vector<std::int64_t> sorted_track_node_ids(const std::vector<Way>& tracks) {
    std::vector<std::int64_t> ids;
    for (const auto& way : tracks) {
        for (const auto& part : way.parts) {
            for (const auto& n : part) {
                ids.push_back(n.id);
            }
        }
    }
    std::sort(ids.begin(), ids.end());
    ids.erase(std::unique(ids.begin(), ids.end()), ids.end());
    return ids;
}

// The file header's replication timestamp ("2020-07-20T12:44:03Z"), if it
// has one in that form.
std::string data_timestamp(const fs::path& file) {
    std::string t;
    try {
        osmium::io::Reader reader{osmium::io::File{file.string()}, osmium::osm_entity_bits::nothing};
        const auto header = reader.header();
        t = header.get("osmosis_replication_timestamp", header.get("timestamp"));
        reader.close();
    } catch (const std::exception&) {
        return {}; // the passes report what is wrong with the file
    }
    static const std::regex iso(R"(\d{4}-\d\d-\d\dT\d\d:\d\d:\d\dZ)");
    return std::regex_match(t, iso) ? t : std::string{};
}

// A readable OSM file; a PBF one's string tables hold no NUL (pbf_strings.hpp),
// an XML or OPL one's coordinates no exponent libosmium overflows on
// (text_coordinates.hpp).
void check_osm_input(const fs::path& file) {
    std::error_code ec;
    if (!fs::is_regular_file(file, ec)) {
        throw InputError(file.string(), fs::exists(file, ec) ? "not a regular file" : "no such file");
    }
    if (osmium::io::File{file.string()}.format() == osmium::io::file_format::pbf) {
        check_pbf_strings(file);
    }
    check_text_coordinates(file);
}

// Every node the ways read reference.
NodeLocations wanted_nodes(const WayScan& ways) {
    NodeLocations locs;
    for (const auto& w : ways.tracks) {
        locs.want_all(w.refs);
    }
    for (const auto& f : ways.area_features) {
        locs.want_all(f.refs);
    }
    for (const auto& r : ways.roads) {
        locs.want_all(r.refs);
    }
    for (const auto& l : ways.land_use) {
        locs.want_all(l.way.refs);
    }
    locs.seal();
    return locs;
}

void add_duplicate_node_repairs(const NodeScan& nodes, IngestResult& result) {
    result.counts.duplicate_nodes = nodes.duplicates.size();
    for (const auto& d : nodes.duplicates) {
        char at[64];
        std::snprintf(at, sizeof at, "%.7f, %.7f", d.ignored.lon, d.ignored.lat);
        result.repairs.push_back({"node", "node", d.id,
                                  std::string{"the id occurs again at another location ("} + at +
                                      "): the first location kept, the later one ignored"});
    }
}

// Refuses a selection left without a usable track, saying why.
void require_tracks(const fs::path& file, const Selection& sel, const RelationScan& relations,
                    const IngestResult& result) {
    if (!result.tracks.empty()) {
        return;
    }
    if (sel.relation) {
        throw InputError(file.string(), "relation " + std::to_string(*sel.relation) + " has no railway track member " +
                                            "with located nodes in the selection (" + result.selection + "; " +
                                            std::to_string(relations.route_ways.size()) + " member way(s))");
    }
    throw InputError(file.string(), "no usable railway track way in the selection (" + result.selection + "); " +
                                        std::to_string(result.dropped.size()) + " track way(s) dropped" +
                                        (result.dropped.empty() ? std::string{}
                                                                : ", e.g. way " +
                                                                      std::to_string(result.dropped.front().id) +
                                                                      ": " + result.dropped.front().reason));
}

// Land-use areas that may hold a track: from the ways pass when it kept
// them all, else read around the tracks.
void add_land_use(const fs::path& file, const IngestOptions& options, WayScan& ways, const RelationScan& relations,
                  const NodeLocations& locs, IngestResult& result) {
    const LandUseContext lc{file, lonlat_bounds(result.tracks, 0.0),
                            lonlat_bounds(result.tracks, options.land_use_search_m)};
    if (ways.land_use_complete) {
        build_land_use(std::move(ways.land_use), relations.land_use, locator_of(locs), lc, result);
    } else {
        read_land_use_near(lc, relations, result);
    }
}

// Roads in the corridor around the tracks, likewise.
void add_roads(const fs::path& file, const IngestOptions& options, const SegmentGrid& grid, WayScan& ways,
               const NodeLocations& locs, IngestResult& result) {
    RoadContext rc{file, options.road_corridor_m, grid, lonlat_bounds(result.tracks, options.road_corridor_m)};
    if (ways.roads_complete) {
        select_prefetched_roads(std::move(ways.roads), locs, rc, result);
    } else {
        read_corridor_roads(rc, result);
    }
}

} // namespace

IngestResult read_osm(const fs::path& file, const IngestOptions& options) {
    check_osm_input(file);
    const Selection& sel = options.selection;
    PhaseTimer timer;
    IngestResult result;
    result.source = file.string();
    result.timestamp = data_timestamp(file);
    result.selection = sel.describe();

    // Phase 1: a route relation restricts the tracks to its member ways;
    // land-use multipolygons name the member ways to read.
    RelationScan relations;
    if (sel.relation || options.land_use) {
        timer.start("read_relations");
        relations = scan_relations(file, sel.relation);
        result.relation = relations.route;
        if (relations.route_text_repaired) {
            result.repairs.push_back({"route", "relation", relations.route->id, text_repair_action});
        }
    }

    // Phase 2: with a bounding box or polygon, the nodes in and near it
    // first, so that only the ways reaching them are held: memory follows the
    // selection, not the file (a track way none of whose nodes is in the
    // file lies in no selection, and is accounted only without one).
    std::optional<BBox> near_box;
    std::vector<std::int64_t> near_nodes;
    if (sel.spatial()) {
        timer.start("read_selected_nodes");
        near_box = selection_box(sel, options);
        near_nodes = node_ids_in(file, *near_box);
    }

    // Phase 3: track, platform, station and land-use ways; only their node ids are known yet.
    timer.start("read_ways");
    const std::size_t road_refs_cap = options.road_corridor_m > 0 ? options.road_prefetch_refs : 0;
    const LandUseWanted land_use{relations.land_use_members, options.land_use ? options.land_use_prefetch_refs : 0};
    WayScan ways = scan_track_ways(file, sel.relation ? &relations.route_ways : nullptr, road_refs_cap, land_use,
                                   near_box ? &near_nodes : nullptr);
    std::vector<std::int64_t>().swap(near_nodes);
    NodeLocations locs = wanted_nodes(ways);

    // Phase 4: locations of exactly those nodes, and railway point features.
    timer.start("read_nodes");
    NodeScan nodes = scan_nodes(file, locs, near_box ? &*near_box : nullptr);
    result.counts.input_nodes = nodes.node_count;
    add_duplicate_node_repairs(nodes, result);

    // Phase 5: the selection, the local frame and the track geometry in it.
    timer.start("select_and_project");
    select_tracks(ways.tracks, locs, sel, result);
    require_tracks(file, sel, relations, result);
    result.projection = LocalProjection(centre_of(result.tracks));
    project_ways(result.tracks, result.projection);
    check_frame_extent(result.tracks, file.string());
    result.counts.input_track_nodes = sorted_track_node_ids(result.tracks).size();
    // Cells small against the corridor: queries stop at the first segment in reach.
    const SegmentGrid grid = track_grid(result.tracks, 50.0);

    // Phase 6: features on or near the selected tracks.
    timer.start("select_features");
    FeatureContext ctx{sel, options, grid, result.projection, sorted_track_node_ids(result.tracks)};
    select_features(std::move(nodes.point_features), std::move(ways.area_features), locs, ctx, result);

    // Phase 7: land-use areas that may hold a track.
    if (options.land_use) {
        timer.start("read_land_use");
        add_land_use(file, options, ways, relations, locs, result);
    }

    // Phase 8: roads in the corridor around the tracks.
    if (options.road_corridor_m > 0) {
        timer.start("read_roads");
        add_roads(file, options, grid, ways, locs, result);
    }
    timer.stop();
    finalize(result);
    result.timings = timer.seconds();
    return result;
}

} // namespace railodd::ingest
