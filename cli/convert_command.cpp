#include "convert_command.hpp"
#include "convert_outputs.hpp"
#include "option_checks.hpp"

#include "railodd/geometry/dump.hpp"
#include "railodd/geometry/road_fit.hpp"
#include "railodd/geometry/topology_report.hpp"
#include "railodd/ingest/dump.hpp"
#include "railodd/ingest/ogr_reader.hpp"
#include "railodd/util/errors.hpp"

#include <nlohmann/json.hpp>

#include <cstdlib>
#include <filesystem>
#include <iostream>
#include <regex>
#include <set>

#if defined(__GLIBC__)
#include <malloc.h>
#endif

namespace railodd::cli {

namespace fs = std::filesystem;

CLI::App* ConvertCommand::add(CLI::App& parent) {
    CLI::App* app = parent.add_subcommand("convert", "Convert an OSM extract (or GIS vector file) of a route");
    app->add_option("INPUT", opt_.input, ".osm, .osm.pbf, .osm.bz2, .osm.gz, .opl; or .geojson/.gpkg/.shp with --field-mapping")
        ->required();
    app->add_option("-o,--output", opt_.outdir, "Output directory")->required()->check(non_empty_path);
    app->add_option("--bbox", opt_.bbox, "Select by bounding box W,S,E,N (degrees)");
    app->add_option("--polygon", opt_.polygon, "Select by a GeoJSON (Multi)Polygon file");
    app->add_option("--relation", opt_.relation,
                    "Select the ways of an OSM rail route relation (id); odd_profile.* follow its member order");
    app->add_option("--field-mapping", opt_.field_mapping, "YAML mapping of vector fields onto OSM tags");
    app->add_option("--dem", opt_.dem, "Elevation raster(s) for the vertical profile (repeat for several tiles)");
    app->add_option("--node-noise", opt_.node_noise_m,
                    "Scatter (m) of mapped track nodes about the true centreline, the fit's model selection scale; "
                    "default: estimated per chain from its nodes")
        ->check(finite_range(0.01, 5.0));
    app->add_option("--fit-method", opt_.fit_method,
                    "How a track's design is read from its nodes: design (one search per chain) or windowed (the "
                    "older windowed fit, kept until the design search wins every benchmark row; docs/geometry.md)")
        ->capture_default_str()
        ->check(CLI::IsMember({"design", "windowed"}));
    app->add_flag("--independent-tracks", opt_.independent_tracks,
                  "Fit every track on its own nodes only: no parallel track's design offered (docs/geometry.md)");
    app->add_option("--road-corridor", opt_.road_corridor_m, "Read roads within this many metres of a track (0: none)")
        ->capture_default_str()
        ->check(finite_range(0.0, 10000.0));
    app->add_option("--feature-distance", opt_.feature_distance_m,
                    "Keep point features and platforms within this many metres of a track")
        ->capture_default_str()
        ->check(finite_range(0.0, 10000.0));
    app->add_option("--station-distance", opt_.station_distance_m, "Keep stations and halts within this many metres")
        ->capture_default_str()
        ->check(finite_range(0.0, 10000.0));
    app->add_option("--threads", opt_.threads, "Threads decoding PBF, fitting tracks and writing outputs (default: one per hardware thread; outputs do not depend on it)")
        ->check(unsigned_integer);
    app->add_flag("--strict", opt_.strict,
                  "Refuse the input (exit 2) where it would be repaired: a node id given twice at different locations");
    app->add_flag("--estimate-cant", opt_.estimate_cant,
                  "Estimate equilibrium cant from maxspeed and radius where railway:cant is not mapped (max 160 mm)");
    app->add_option("--odr-version", opt_.odr_version, "OpenDRIVE revision of map.xodr: 1.6, 1.7 or 1.8")
        ->capture_default_str()
        ->check(CLI::IsMember({"1.6", "1.7", "1.8"}));
    app->add_option("--date", opt_.date,
                    "The map's date, YYYY-MM-DDTHH:MM:SS[Z] (default: the OSM file's replication timestamp, else none)")
        ->check(CLI::Validator(
            [](std::string& d) -> std::string {
                static const std::regex iso(R"(\d{4}-\d\d-\d\dT\d\d:\d\d:\d\dZ?)");
                return std::regex_match(d, iso) ? std::string{} : "'" + d + "' is not YYYY-MM-DDTHH:MM:SS[Z]";
            },
            "DATE"));
    app->add_option("--taxonomy", opt_.taxonomy, "ODD taxonomy for odd_profile.* (default: data/odd/railway_odd.yaml)");
    app->add_option("--from", opt_.from, "Profile the route from this station (with --to; shortest path)");
    app->add_option("--to", opt_.to, "Profile the route to this station (with --from)");
    app->add_flag("--no-timings", opt_.no_timings, "Leave timings out of report.json (byte-identical reruns)");
    app->add_flag("--no-report", opt_.no_report, "Do not write report.html (the route's HTML page, `railodd report`)");
    app->add_flag("--debug-outputs", opt_.debug_outputs,
                  "Also write ingest.geojson (the selected input), geometry.geojson and roads.geojson (the fitted "
                  "centrelines in WGS84): diagnostics; `railodd report` reads the mapped nodes from ingest.geojson");
    app->add_flag("--odd-user-data", opt_.odd_user_data,
                  "Also write every ODD profile element as a <userData code=\"odd\"> on its road in map.xodr "
                  "(odd_profile.json holds them all, with road_id and s; on a network they are a third of the map)");
    return app;
}

void ConvertCommand::setup() {
    const bool vector = ingest::is_vector_source(opt_.input);
    if (vector && opt_.field_mapping.empty()) {
        throw UsageError(opt_.input, "a GIS vector source needs --field-mapping FILE.yaml (see docs/field-mapping.md)");
    }
    if (!vector && !opt_.field_mapping.empty()) {
        throw UsageError(opt_.input, "--field-mapping applies to GIS vector sources only, not OSM files");
    }
    if (opt_.from.empty() != opt_.to.empty()) {
        throw UsageError(opt_.from.empty() ? "--to" : "--from", "a route needs both --from NAME and --to NAME");
    }
    if (!opt_.bbox.empty()) {
        ingest::parse_bbox(opt_.bbox); // fail before any output directory is touched
    }
    if (opt_.threads > 0) {
        // libosmium sizes its decoding pool from this on first use.
        ::setenv("OSMIUM_POOL_THREADS", std::to_string(opt_.threads).c_str(), 1);
    }
}

namespace {

ingest::Selection make_selection(const ConvertOptions& o) {
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

void print_summary(const ingest::IngestResult& r, std::size_t in_map, const std::vector<fs::path>& written) {
    const auto& c = r.counts;
    std::cout << "railodd convert: " << r.source << " (" << r.selection << ")\n"
              << "  track ways: " << in_map << " of " << c.input_track_ways << " in the map, "
              << (c.input_track_ways - c.output_track_ways) << " dropped at ingest, "
              << (c.output_track_ways - in_map) << " not written (report.json)\n"
              << "  road ways:  " << c.output_road_ways << " of " << c.input_road_ways << "\n"
              << "  features:   " << c.output_features << " of " << c.input_features << "\n";
    for (const auto& p : written) {
        std::cout << "  wrote " << p.string() << '\n';
    }
}

} // namespace

namespace {

// Crossings found on the graph; features placed on the fitted centrelines.
void place_features(const ingest::IngestResult& r, Geometry& g, const ConvertOptions& o) {
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

Geometry fit_geometry(const ingest::IngestResult& r, const std::vector<std::string>& dem_files,
                      const geometry::FitOptions& fo, PhaseTimer& timer) {
    Geometry g;
    timer.start("track_graph");
    g.tracks = geometry::build_track_graph(r.tracks, r.features);
    timer.start("fit_tracks");
    g.fitted_tracks = geometry::fit_track_graph(g.tracks, fo);
#if defined(__GLIBC__)
    // The fit's worker threads leave their malloc arenas' free pages
    // resident, where this thread's later phases cannot reuse them: given
    // back, Cologne's peak falls by the 18 MB they held.
    malloc_trim(0);
#endif
    timer.start("vertical_profiles");
    std::optional<geometry::ElevationModel> dem;
    if (!dem_files.empty()) {
        dem.emplace(std::vector<std::filesystem::path>(dem_files.begin(), dem_files.end()));
    }
    g.profiles = geometry::fit_profiles(g.tracks, g.fitted_tracks, r.tracks, r.projection, dem ? &*dem : nullptr);
    timer.start("fit_roads");
    g.roads = geometry::build_track_graph(r.roads, {});
    g.fitted_roads = geometry::fit_road_graph(g.roads, geometry::RoadFitOptions{});
    timer.stop();
    return g;
}

} // namespace

namespace {

ingest::IngestResult read_input(const ConvertOptions& o) {
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
void check_duplicate_nodes(const ConvertOptions& o, const ingest::IngestResult& result) {
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
nlohmann::ordered_json stage_reports(const ingest::IngestResult& result, const Geometry& geo,
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

} // namespace

int ConvertCommand::run() {
    // Phase 1: ingest the selected tracks, features and roads into the local frame.
    ingest::IngestResult result = read_input(opt_);
    check_duplicate_nodes(opt_, result);

    // Phase 2: track graph, railway-grade centrelines and profiles, road
    // centrelines; then crossings, and features placed on the tracks.
    PhaseTimer timer;
    geometry::FitOptions fo;
    fo.noise_sigma_m = opt_.node_noise_m;
    fo.threads = opt_.threads;
    fo.parallel_guides = !opt_.independent_tracks;
    fo.method = opt_.fit_method == "windowed" ? geometry::FitMethod::windowed : geometry::FitMethod::design_search;
    Geometry geo = fit_geometry(result, opt_.dem, fo, timer);
    timer.start("cant");
    geometry::CantOptions cant;
    cant.estimate = opt_.estimate_cant;
    geo.cants = geometry::fit_cants(geo.tracks, geo.fitted_tracks, result.tracks, cant);
    timer.start("topology");
    place_features(result, geo, opt_);
    // Phase 3: the OpenDRIVE map.
    timer.start("opendrive");
    const xodr::MapInput map_input{result,     geo.tracks,       geo.fitted_tracks, geo.profiles,
                                   geo.cants,  geo.roads,        geo.fitted_roads,  geo.attachment,
                                   geo.crossings, &geo.indexed};
    xodr::MapOptions mo;
    mo.revision = xodr::parse_revision(opt_.odr_version);
    mo.name = fs::path(opt_.input).filename().string();
    mo.date = map_date(opt_.date, result);
    xodr::MapBuild map = xodr::build_map(map_input, mo);
    require_rail_roads(opt_.input, map);
    // The tracks' part of report.json while their indexes exist, and before
    // the profile does: the two never take memory at the same time.
    timer.start("geometry_report");
    nlohmann::ordered_json geometry_report = geometry::report_section(geo.tracks, geo.fitted_tracks, &geo.indexed);
    // Phases 4 and 5: ODD tags on every stretch and point of track, and every
    // output staged, then moved into place together. The large ones are
    // streamed: no output is ever held whole in memory.
    OutputStage stage(opt_.outdir);
    Profiled profiled = profile_and_write(stage, opt_, result, geo, map_input, map, mo.revision, timer);
    timer.stop();
    result.timings.insert(result.timings.end(), timer.seconds().begin(), timer.seconds().end());
    nlohmann::ordered_json report = stage_reports(result, geo, std::move(geometry_report), map, map_input,
                                                  profiled.route ? &*profiled.route : nullptr);
    if (!opt_.no_report) {
        write_page(stage, opt_.outdir, profiled, report, map.map, result);
    } else {
        stage.remove_on_commit("report.html"); // an earlier run's page shows another map
    }
    if (!opt_.no_timings) {
        report["timings_s"] = timings_json(result.timings);
    }
    stage.write_text("report.json", report.dump(2) + "\n");
    print_summary(result, ways_in_map(geo.tracks, map.rail), stage.commit());
    return exit_ok;
}

} // namespace railodd::cli
