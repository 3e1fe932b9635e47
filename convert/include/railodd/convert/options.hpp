#pragma once
// The options of one conversion, and the one table that describes them: the
// command line's flags (cli/convert_command.cpp) and the batch routes file's
// keys (cli/batch_routes.cpp) are both made from it, with its checks, so an
// option is added by one field and one row.
#include <cstdint>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <variant>
#include <vector>

namespace railodd::convert {

struct Options {
    std::string input;
    std::string outdir;
    std::string date; // the map's header date; empty: the data's own
    std::string bbox;
    std::string polygon;
    std::optional<std::int64_t> relation;
    std::string field_mapping;
    std::vector<std::string> dem; // elevation rasters (GeoTIFF, HGT, VRT; several tiles)
    double road_corridor_m = 300.0;
    double node_noise_m = 0.0; // 0: estimated per chain from its nodes (report.json geometry.summary.node_noise)
    std::string fit_method = "design"; // design (the design search) or windowed (geometry::FitMethod)
    bool independent_tracks = false; // no parallel track's design offered to a track's fit
    double feature_distance_m = 50.0;
    double station_distance_m = 500.0;
    unsigned threads = 0; // 0: one per hardware thread
    bool no_timings = false;
    bool no_report = false; // report.html not written
    bool debug_outputs = false; // ingest.geojson, geometry.geojson, roads.geojson written
    bool odd_user_data = false; // every profile element also a <userData code="odd"> on its road in map.xodr
    bool estimate_cant = false; // equilibrium cant where railway:cant is not mapped
    bool strict = false;        // input defects that are repaired otherwise (duplicate node ids) refuse the input
    std::string odr_version = "1.7";
    std::string taxonomy; // ODD taxonomy; empty: data/odd/railway_odd.yaml
    std::string from;     // --from/--to: odd_profile.* along the route between two stations
    std::string to;

    bool operator==(const Options&) const = default;
};

// How an option's value is written and checked.
enum class OptionKind {
    path,   // a file (a batch route's relative path is taken from the routes file's folder)
    paths,  // one or more files (repeated on the command line, a list in YAML)
    text,   // free text, or one of `choices`, or matching `pattern`
    number, // a finite number in [lo, hi]
    count,  // a non-negative integer
    integer, // an integer (an OSM id)
    bbox,   // W,S,E,N in degrees (a list of four numbers in YAML)
    flag,   // on or off
};

using OptionField = std::variant<std::string Options::*, std::vector<std::string> Options::*, double Options::*,
                                 bool Options::*, std::optional<std::int64_t> Options::*, unsigned Options::*>;

struct OptionSpec {
    std::string_view key; // batch YAML key; the flag is "--" + key with '-' for '_'
    OptionKind kind;
    OptionField field;
    std::string_view help;
    // Where a batch route may set it: not the input (a route's own key), the
    // output folder, the thread count or the timings (the batch's to choose).
    bool per_route = true;
    double lo = 0.0, hi = 0.0;                  // number: the allowed range
    std::vector<std::string_view> choices = {}; // text: the allowed values (none: any)
    std::string_view pattern = {};              // text: a regular expression the value matches (empty: any)
    std::string_view format = {};               // text: how `pattern` reads, for the error message
    std::string_view short_name = {};           // e.g. "-o"
    bool required = false;
    bool positional = false; // the command line's INPUT
    bool show_default = false;
};

// Every option of Options, one row each, in the order of --help.
std::span<const OptionSpec> option_table();

// The row of a key; nullptr where there is none.
const OptionSpec* find_option(std::string_view key);

// The command-line flag of a row: "--road-corridor" for road_corridor.
std::string flag_of(const OptionSpec& spec);

// Why `text` is no value of the option (empty where it is one): the check
// both the command line and the routes file run.
std::string check_value(const OptionSpec& spec, const std::string& text);

// Checks across options, before anything is read or written: a GIS vector
// source needs --field-mapping and an OSM file none, --from goes with --to,
// the bbox parses. Throws UsageError or InputError naming the option.
void check(const Options& options);

} // namespace railodd::convert
