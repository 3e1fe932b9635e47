#include "railodd/convert/options.hpp"

#include "railodd/ingest/ogr_reader.hpp"
#include "railodd/ingest/selection.hpp"
#include "railodd/util/errors.hpp"
#include "railodd/util/value_checks.hpp"

#include <algorithm>
#include <regex>

namespace railodd::convert {

namespace {

using K = OptionKind;
using O = Options;

// The order of --help. A number's range is what the fit and the readers take
// in; beyond it an input is a mistake, not a wish.
const std::vector<OptionSpec>& table() {
    static const std::vector<OptionSpec> rows = {
        {.key = "input", .kind = K::path, .field = &O::input,
         .help = ".osm, .osm.pbf, .osm.bz2, .osm.gz, .opl; or .geojson/.gpkg/.shp with --field-mapping",
         .per_route = false, .required = true, .positional = true},
        {.key = "output", .kind = K::path, .field = &O::outdir, .help = "Output directory", .per_route = false,
         .short_name = "-o", .required = true},
        {.key = "bbox", .kind = K::bbox, .field = &O::bbox, .help = "Select by bounding box W,S,E,N (degrees)"},
        {.key = "polygon", .kind = K::path, .field = &O::polygon, .help = "Select by a GeoJSON (Multi)Polygon file"},
        {.key = "relation", .kind = K::integer, .field = &O::relation,
         .help = "Select the ways of an OSM rail route relation (id); odd_profile.* follow its member order"},
        {.key = "field_mapping", .kind = K::path, .field = &O::field_mapping,
         .help = "YAML mapping of vector fields onto OSM tags"},
        {.key = "dem", .kind = K::paths, .field = &O::dem,
         .help = "Elevation raster(s) for the vertical profile (repeat for several tiles)"},
        {.key = "node_noise", .kind = K::number, .field = &O::node_noise_m,
         .help = "Scatter (m) of mapped track nodes about the true centreline, the fit's model selection scale; "
                 "default: estimated per chain from its nodes",
         .lo = 0.01, .hi = 5.0},
        {.key = "fit_method", .kind = K::text, .field = &O::fit_method,
         .help = "How a track's design is read from its nodes: design (one search per chain) or windowed (the older "
                 "windowed fit, kept until the design search wins every benchmark row; docs/geometry.md)",
         .choices = {"design", "windowed"}, .show_default = true},
        {.key = "independent_tracks", .kind = K::flag, .field = &O::independent_tracks,
         .help = "Fit every track on its own nodes only: no parallel track's design offered (docs/geometry.md)"},
        {.key = "road_corridor", .kind = K::number, .field = &O::road_corridor_m,
         .help = "Read roads within this many metres of a track (0: none)", .lo = 0.0, .hi = 10000.0,
         .show_default = true},
        {.key = "feature_distance", .kind = K::number, .field = &O::feature_distance_m,
         .help = "Keep point features and platforms within this many metres of a track", .lo = 0.0, .hi = 10000.0,
         .show_default = true},
        {.key = "station_distance", .kind = K::number, .field = &O::station_distance_m,
         .help = "Keep stations and halts within this many metres", .lo = 0.0, .hi = 10000.0, .show_default = true},
        {.key = "threads", .kind = K::count, .field = &O::threads,
         .help = "Threads decoding PBF, fitting tracks and writing outputs (default: one per hardware thread; "
                 "outputs do not depend on it)",
         .per_route = false},
        {.key = "strict", .kind = K::flag, .field = &O::strict,
         .help = "Refuse the input (exit 2) where it would be repaired: a node id given twice at different locations"},
        {.key = "estimate_cant", .kind = K::flag, .field = &O::estimate_cant,
         .help = "Estimate equilibrium cant from maxspeed and radius where railway:cant is not mapped (max 160 mm)"},
        {.key = "odr_version", .kind = K::text, .field = &O::odr_version,
         .help = "OpenDRIVE revision of map.xodr: 1.6, 1.7 or 1.8", .choices = {"1.6", "1.7", "1.8"},
         .show_default = true},
        {.key = "date", .kind = K::text, .field = &O::date,
         .help = "The map's date, YYYY-MM-DDTHH:MM:SS[Z] (default: the OSM file's replication timestamp, else none)",
         .pattern = R"(\d{4}-\d\d-\d\dT\d\d:\d\d:\d\dZ?)", .format = "YYYY-MM-DDTHH:MM:SS[Z]"},
        {.key = "taxonomy", .kind = K::path, .field = &O::taxonomy,
         .help = "ODD taxonomy for odd_profile.* (default: data/odd/railway_odd.yaml)"},
        {.key = "from", .kind = K::text, .field = &O::from,
         .help = "Profile the route from this station (with --to; shortest path)"},
        {.key = "to", .kind = K::text, .field = &O::to, .help = "Profile the route to this station (with --from)"},
        {.key = "no_timings", .kind = K::flag, .field = &O::no_timings,
         .help = "Leave timings out of report.json (byte-identical reruns)", .per_route = false},
        {.key = "no_report", .kind = K::flag, .field = &O::no_report,
         .help = "Do not write report.html (the route's HTML page, `railodd report`)"},
        {.key = "debug_outputs", .kind = K::flag, .field = &O::debug_outputs,
         .help = "Also write ingest.geojson (the selected input), geometry.geojson and roads.geojson (the fitted "
                 "centrelines in WGS84): diagnostics; `railodd report` reads the mapped nodes from ingest.geojson"},
        {.key = "odd_user_data", .kind = K::flag, .field = &O::odd_user_data,
         .help = "Also write every ODD profile element as a <userData code=\"odd\"> on its road in map.xodr "
                 "(odd_profile.json holds them all, with road_id and s; on a network they are a third of the map)"},
    };
    return rows;
}

std::string quoted(const std::string& text) { return "'" + text + "'"; }

std::string check_text(const OptionSpec& spec, const std::string& text) {
    if (!spec.choices.empty() && std::find(spec.choices.begin(), spec.choices.end(), text) == spec.choices.end()) {
        std::string list;
        for (const std::string_view c : spec.choices) {
            list += (list.empty() ? "" : ", ") + std::string{c};
        }
        return quoted(text) + " is not one of " + list;
    }
    if (!spec.pattern.empty() && !std::regex_match(text, std::regex{std::string{spec.pattern}})) {
        return quoted(text) + " is not " + std::string{spec.format};
    }
    return {};
}

} // namespace

std::span<const OptionSpec> option_table() { return table(); }

const OptionSpec* find_option(std::string_view key) {
    for (const OptionSpec& s : table()) {
        if (s.key == key) {
            return &s;
        }
    }
    return nullptr;
}

std::string flag_of(const OptionSpec& spec) {
    std::string f = "--" + std::string{spec.key};
    std::replace(f.begin(), f.end(), '_', '-');
    return f;
}

std::string check_value(const OptionSpec& spec, const std::string& text) {
    switch (spec.kind) {
    case OptionKind::path:
    case OptionKind::paths:
        return util::check_non_empty_path(text);
    case OptionKind::text:
        return check_text(spec, text);
    case OptionKind::number:
        return util::check_finite_in(text, spec.lo, spec.hi);
    case OptionKind::count:
        return util::check_non_negative_integer(text);
    case OptionKind::integer:
        return std::regex_match(text, std::regex{"-?[0-9]{1,18}"}) ? std::string{} : quoted(text) + " is not an integer";
    case OptionKind::bbox:
        try {
            ingest::parse_bbox(text);
        } catch (const Error& e) {
            return e.problem();
        }
        return {};
    case OptionKind::flag:
        return {};
    }
    return {};
}

void check(const Options& o) {
    const bool vector = ingest::is_vector_source(o.input);
    if (vector && o.field_mapping.empty()) {
        throw UsageError(o.input, "a GIS vector source needs --field-mapping FILE.yaml (see docs/field-mapping.md)");
    }
    if (!vector && !o.field_mapping.empty()) {
        throw UsageError(o.input, "--field-mapping applies to GIS vector sources only, not OSM files");
    }
    if (o.from.empty() != o.to.empty()) {
        throw UsageError(o.from.empty() ? "--to" : "--from", "a route needs both --from NAME and --to NAME");
    }
    if (!o.bbox.empty()) {
        ingest::parse_bbox(o.bbox); // fail before any output directory is touched
    }
}

} // namespace railodd::convert
