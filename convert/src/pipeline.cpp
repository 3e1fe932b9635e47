#include "railodd/convert/convert.hpp"

#include "outputs.hpp"

#include "railodd/geometry/dump.hpp"
#include "railodd/geometry/profiles.hpp"
#include "railodd/geometry/road_fit.hpp"
#include "railodd/geometry/topology_report.hpp"
#include "railodd/ingest/dump.hpp"
#include "railodd/ingest/ogr_reader.hpp"
#include "railodd/util/errors.hpp"

#include <nlohmann/json.hpp>

#include <filesystem>
#include <iostream>
#include <set>

#if defined(__GLIBC__)
#include <malloc.h>
#endif

namespace railodd::convert {

namespace fs = std::filesystem;

namespace {

// Memory, the pipeline's policy (the outputs' is in output_sinks.hpp): the
// profile is streamed a batch of tracks at a time and never held whole; the
// tracks' 2 m indexes go before the tagging, which indexes each batch itself
// (profile_and_write); and the worker threads of the fit and of the
// profile's writer leave their malloc arenas' free pages resident, where
// this thread's later phases cannot reuse them, so they are given back after
// each (Cologne: the 18 MB the fit's held).
void release_thread_arenas() {
#if defined(__GLIBC__)
    malloc_trim(0);
#endif
}

ingest::Selection make_selection(const Options& o) {
    ingest::Selection sel;
    if (!o.bbox.empty()) {
        sel.bbox = ingest::parse_bbox(o.bbox);
    }
    if (!o.polygon.empty()) {
        sel.polygon = ingest::load_polygon_geojson(o.polygon);
    }
    sel.relation = o.relation;
    return sel;
}

nlohmann::ordered_json make_report(const ingest::IngestResult& r) {
    nlohmann::ordered_json report;
    report["railodd"] = {{"version", "0.1.0"}, {"command", "convert"}};
    nlohmann::ordered_json sections = ingest::report_sections(r);
    for (auto& [key, value] : sections.items()) {
        report[key] = std::move(value);
    }
    return report;
}

nlohmann::ordered_json timings_json(const std::vector<std::pair<std::string, double>>& timings) {
    nlohmann::ordered_json t = nlohmann::ordered_json::object();
    for (const auto& [phase, seconds] : timings) {
        t[phase] = seconds;
    }
    return t;
}

// The track ways with at least one stretch written to the map; the others
// are in report.json (ingest's "dropped", the map's "tracks_not_written").
std::size_t ways_in_map(const geometry::TrackGraph& tracks, const xodr::RailNetwork& rail) {
    std::set<std::int64_t> ways;
    for (std::size_t e = 0; e < tracks.edges.size() && e < rail.pieces.size(); ++e) {
        if (!rail.pieces[e].empty()) {
            for (const auto& w : tracks.edges[e].ways) {
                ways.insert(w.way_id);
            }
        }
    }
    return ways.size();
}

// A map without a single rail road is no map (the ASAM schema requires a
// road): refused, saying why, before anything is written.
void require_rail_roads(const std::string& input, const xodr::MapBuild& map) {
    bool any = false;
    for (const auto& p : map.rail.pieces) {
        any = any || !p.empty();
    }
    if (any) {
        return;
    }
    std::string why;
    for (std::size_t i = 0; i < map.rail.unwritten.size() && i < 3; ++i) {
        why += (i ? "; " : "") + map.rail.unwritten[i].reason;
    }
    throw InputError(input, "no track could be written to the map" + (why.empty() ? "" : " (" + why + ")"));
}

// Crossings found on the graph; features placed on the fitted centrelines.
void place_features(const ingest::IngestResult& r, geometry::FittedMap& g, const Options& o) {
    g.indexed.reserve(g.fitted_tracks.edges.size());
    for (const auto& e : g.fitted_tracks.edges) {
        g.indexed.emplace_back(e.alignment, 2.0);
    }
    g.attachment = geometry::attach_features(g.tracks, g.indexed, r.features, o.feature_distance_m, o.station_distance_m);
    g.crossings = geometry::find_crossings(g.tracks, r.tracks, r.roads, r.features);
}

// The map's date: --date, else the data's own (the OSM file header's
// replication timestamp), else none. Never the file's mtime, which changes
// with every copy: the same data gives the same map on every machine.
std::string map_date(const std::string& option, const ingest::IngestResult& r) {
    std::string d = option.empty() ? r.timestamp : option;
    if (!d.empty() && d.back() != 'Z') {
        d += 'Z';
    }
    return d;
}

geometry::FitOptions fit_options(const Options& o) {
    geometry::FitOptions fo;
    fo.noise_sigma_m = o.node_noise_m;
    fo.threads = o.threads;
    fo.parallel_guides = !o.independent_tracks;
    fo.method = o.fit_method == "windowed" ? geometry::FitMethod::windowed : geometry::FitMethod::design_search;
    return fo;
}

// Track graph, railway-grade centrelines and profiles, road centrelines.
geometry::FittedMap fit_geometry(const ingest::IngestResult& r, const Options& o, PhaseTimer& timer) {
    geometry::FittedMap g;
    timer.start("track_graph");
    g.tracks = geometry::build_track_graph(r.tracks, r.features);
    timer.start("fit_tracks");
    g.fitted_tracks = geometry::fit_track_graph(g.tracks, fit_options(o));
    release_thread_arenas();
    timer.start("vertical_profiles");
    std::optional<geometry::ElevationModel> dem;
    if (!o.dem.empty()) {
        dem.emplace(std::vector<std::filesystem::path>(o.dem.begin(), o.dem.end()));
    }
    g.profiles = geometry::fit_profiles(g.tracks, g.fitted_tracks, r.tracks, r.projection, dem ? &*dem : nullptr);
    timer.start("fit_roads");
    g.roads = geometry::build_track_graph(r.roads, {});
    g.fitted_roads = geometry::fit_road_graph(g.roads, geometry::RoadFitOptions{});
    timer.stop();
    return g;
}

ingest::IngestResult read_input(const Options& o) {
    const ingest::Selection selection = make_selection(o);
    if (ingest::is_vector_source(o.input)) {
        return ingest::read_vector(o.input, o.field_mapping, selection);
    }
    ingest::IngestOptions io;
    io.selection = selection;
    io.road_corridor_m = o.road_corridor_m;
    io.feature_distance_m = o.feature_distance_m;
    io.station_distance_m = o.station_distance_m;
    return ingest::read_osm(o.input, io);
}

// A node id given twice at different locations (a careless merge): said on
// stderr, the ids named, the first copy kept; refused with --strict.
void check_duplicate_nodes(const Options& o, const ingest::IngestResult& result) {
    const std::size_t n = result.counts.duplicate_nodes;
    if (n == 0) {
        return;
    }
    std::string ids;
    std::size_t named = 0;
    for (const auto& r : result.repairs) {
        if (r.kind == "node" && r.osm_type == "node" && named < 5) {
            ids += (named++ ? ", " : "") + std::to_string(r.id);
        }
    }
    const std::string what = std::to_string(n) + (n == 1 ? " node id occurs" : " node ids occur") +
                             " again at another location (" + ids + (n > named ? ", ..." : "") + ")";
    if (o.strict) {
        throw InputError(o.input, what + "; refused with --strict");
    }
    std::cerr << "railodd: warning: " << o.input << ": " << what
              << ": the first location of each is kept, the later ignored (report.json repairs)\n";
}

// report.json's sections of every stage, in pipeline order (the route's last,
// when the profile follows one).
nlohmann::ordered_json stage_reports(const ingest::IngestResult& result, const geometry::FittedMap& geo,
                                     nlohmann::ordered_json geometry_report, const xodr::MapBuild& map,
                                     const xodr::MapInput& map_input, const odd::Route* route) {
    nlohmann::ordered_json report = make_report(result);
    report["geometry"] = std::move(geometry_report);
    report["vertical"] = geometry::profiles_report(geo.tracks, geo.profiles);
    report["cant"] = geometry::cants_report(geo.cants);
    report["topology"] = geometry::topology_report(geo.crossings, geo.attachment, result.features);
    report["opendrive"] = xodr::map_report(map, map_input);
    report["roads"] = geometry::report_section(geo.roads, geo.fitted_roads)["summary"];
    if (route) {
        report["route"] = odd::route_report(*route);
    }
    return report;
}

// The map's options: its revision, name and date.
xodr::MapOptions map_options(const Options& o, const ingest::IngestResult& r) {
    xodr::MapOptions mo;
    mo.revision = xodr::parse_revision(o.odr_version);
    mo.name = fs::path(o.input).filename().string();
    mo.date = map_date(o.date, r);
    return mo;
}

// report.json and (unless --no-report) report.html, staged beside the rest.
void write_reports(OutputStage& stage, const Options& o, ingest::IngestResult& result, const geometry::FittedMap& geo,
                   nlohmann::ordered_json geometry_report, const xodr::MapBuild& map, const xodr::MapInput& map_input,
                   Profiled& profiled) {
    nlohmann::ordered_json report = stage_reports(result, geo, std::move(geometry_report), map, map_input,
                                                  profiled.route ? &*profiled.route : nullptr);
    if (!o.no_report) {
        write_page(stage, o, profiled, report, map.map, result);
    } else {
        stage.remove_on_commit("report.html"); // an earlier run's page shows another map
    }
    if (!o.no_timings) {
        report["timings_s"] = timings_json(result.timings);
    }
    stage.write_text("report.json", report.dump(2) + "\n");
}

} // namespace

Result run(const Options& o) {
    check(o);
    // Phase 1: ingest the selected tracks, features and roads into the local frame.
    ingest::IngestResult result = read_input(o);
    check_duplicate_nodes(o, result);
    // Phase 2: track graph, railway-grade centrelines and profiles, road
    // centrelines, cant; then crossings, and features placed on the tracks.
    PhaseTimer timer;
    geometry::FittedMap geo = fit_geometry(result, o, timer);
    timer.start("cant");
    geometry::CantOptions cant;
    cant.estimate = o.estimate_cant;
    geo.cants = geometry::fit_cants(geo.tracks, geo.fitted_tracks, result.tracks, cant);
    timer.start("topology");
    place_features(result, geo, o);
    // Phase 3: the OpenDRIVE map.
    timer.start("opendrive");
    const xodr::MapInput map_input{result, geo};
    const xodr::MapOptions mo = map_options(o, result);
    xodr::MapBuild map = xodr::build_map(map_input, mo);
    require_rail_roads(o.input, map);
    // The tracks' part of report.json while their indexes exist, and before
    // the profile does: the two never take memory at the same time.
    timer.start("geometry_report");
    nlohmann::ordered_json geometry_report =
        geometry::report_section(geo.tracks, geo.fitted_tracks, &geo.indexed, o.threads != 1);
    // Phases 4 and 5: ODD tags on every stretch and point of track, and every
    // output staged, then moved into place together. The large ones are
    // streamed: no output is ever held whole in memory.
    OutputStage stage(o.outdir);
    Profiled profiled = profile_and_write(stage, o, result, geo, map_input, map, mo.revision, timer);
    release_thread_arenas();
    timer.stop();
    result.timings.insert(result.timings.end(), timer.seconds().begin(), timer.seconds().end());
    write_reports(stage, o, result, geo, std::move(geometry_report), map, map_input, profiled);
    Result out{result.source, result.selection, result.counts, ways_in_map(geo.tracks, map.rail), {}};
    out.written = stage.commit();
    return out;
}

} // namespace railodd::convert
