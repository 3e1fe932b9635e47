#pragma once
// railodd::xodr_check: an independent checker of ASAM OpenDRIVE 1.6 / 1.7 / 1.8
// files. It re-evaluates every plan-view record in closed form (it does not use
// railodd::geometry, so it can catch the writer's and the fitter's bugs) and
// checks continuity, links, junctions, the rail extensions and elevation.
// Everything here is plain data; pugixml stays inside the library.
#include <cstddef>
#include <filesystem>
#include <limits>
#include <map>
#include <string>
#include <vector>

namespace railodd::xodr_check {

// Limits of the checks (docs/validate.md). The defaults are the rail-grade ones.
struct Limits {
    double gap_m = 1e-3;                // position gap between records, roads, junction contacts
    double heading_rad = 1e-4;          // heading jump (compared modulo 2 pi)
    double rail_curvature_per_m = 1e-6; // curvature jump on rail roads
    double s_chain_relative = 1e-6;     // s_i + length_i = s_{i+1}
    double length_m = 1e-3;             // sum of record lengths = road @length; s ranges of references
    double elevation_gap_m = 1e-3;      // elevation polynomials between records
    double link_height_m = 0.05;        // height step between linked roads and junction contacts
    double link_grade = 0.01;           // grade change there (rise over run, taken along the link)
};

enum class Severity { error, warning };

struct Finding {
    Severity severity = Severity::error;
    std::string object; // "road", "junction", "station", "file"
    std::string id;
    double s = std::numeric_limits<double>::quiet_NaN(); // NaN: not at a position on a road
    std::string check;   // e.g. "geometry_gap", "link_heading", "switch_track"
    std::string message; // measured value and limit
};

// The worst value of one figure and where it was measured.
struct Worst {
    double value = 0.0;
    std::string where;
    void update(double v, const std::string& at) {
        if (v > value) {
            value = v;
            where = at;
        }
    }
};

struct Summary {
    std::string version; // "1.7" from the header
    std::size_t roads = 0;
    std::size_t rail_roads = 0;
    std::map<std::string, std::size_t> geometries_by_kind; // line, arc, spiral, poly3, paramPoly3
    std::size_t junctions = 0;
    std::size_t connections = 0;
    std::size_t switches = 0;
    std::size_t stations = 0;
    std::size_t links_checked = 0; // road-road links and junction contacts compared geometrically
    std::size_t short_records = 0; // plan-view records under 1 cm (readers divide by a record's length)
    double shortest_record_m = std::numeric_limits<double>::infinity();
    std::string shortest_record_at;
    Worst gap_m;                   // geometry joints, road links, junction contacts
    Worst heading_jump_rad;
    Worst rail_curvature_jump; // 1/m, rail roads only
    Worst elevation_gap_m;
    Worst link_height_m; // height step across road links and junction contacts
    Worst link_grade;    // grade change there, along the link
};

struct CheckResult {
    std::string file;
    Summary summary;
    std::vector<Finding> findings; // errors first, then warnings; each in document order
    std::size_t errors() const;
    std::size_t warnings() const;
    bool passed() const { return errors() == 0; }
};

// Parses and checks a file. Throws railodd::InputError naming the file when it
// cannot be read or is not an OpenDRIVE document.
CheckResult check_file(const std::filesystem::path& file, const Limits& limits = {});

// The same on a document held in memory; `name` stands for the file in messages.
CheckResult check_text(const std::string& xml, const std::string& name, const Limits& limits = {});

// XSD validation with the external validators: xmllint for 1.6 / 1.7, Python's
// xmlschema (XSD 1.1) for 1.8. The core schema is looked up in xsd_dir and
// below it by the name the header's revMinor calls for.
struct SchemaResult {
    bool ran = false;
    bool valid = false;
    std::string validator;           // the command line that was run
    std::string xsd;                 // the core schema used
    std::vector<std::string> errors; // the validator's first error lines
    std::size_t error_count = 0;     // all error lines the validator printed
};
SchemaResult validate_schema(const std::filesystem::path& file, const std::string& version,
                             const std::filesystem::path& xsd_dir);

// SUMO's netconvert on the file: its errors and what it made of the rail network.
struct NetconvertResult {
    bool ran = false;
    int exit_code = -1;
    std::vector<std::string> errors; // stderr lines starting with "Error"
    std::size_t edges = 0;           // non-internal edges in the written net
    std::size_t rail_edges = 0;      // of them, edges with a lane allowing rail or tram
    bool passed() const { return ran && exit_code == 0 && errors.empty(); }
};
NetconvertResult run_netconvert(const std::filesystem::path& file);

// Readable verdict (counts, worst figures against their limits, the first
// max_findings findings, PASS / FAIL) and the same as JSON text.
struct Verdict {
    const CheckResult* checks = nullptr;
    const SchemaResult* schema = nullptr;         // null: not asked for
    const NetconvertResult* netconvert = nullptr; // null: not asked for
    Limits limits;
    bool passed() const;
};
std::string verdict_text(const Verdict& v, std::size_t max_findings = 20);
std::string verdict_json(const Verdict& v);

} // namespace railodd::xodr_check
