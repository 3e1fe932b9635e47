#pragma once
// railodd::report: one self-contained HTML page of a converted route (the map
// coloured by ODD attributes, the curvature diagram, elevation, gradient, cant
// and speed along the chainage, the ODD summary and spec check, scenario
// coverage and play results, fit quality). Written by `railodd report` and by
// `railodd convert` (docs/report.md, "report.html").
//
// The page is report/web/template.html with Leaflet, uPlot and the app
// (report/web/app/) inlined from the binary, and the data document
// (report/web/data_format.md) in a <script type="application/json">: it opens
// from disk with no network.
#include <array>
#include <filesystem>
#include <iosfwd>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

namespace railodd::odd {
struct OddProfile;
}
namespace railodd::xodr {
struct Map;
}

namespace railodd::report {

struct ReportOptions {
    std::filesystem::path map_dir;      // a convert output folder: map.xodr, odd_profile.json, report.json, ...
    std::filesystem::path scenario_dir; // empty: no scenario section
    std::filesystem::path play_file;    // play.json; empty: scenario_dir/play.json when it exists
    std::filesystem::path odd_spec;     // empty: no spec check
    std::filesystem::path taxonomy;     // for odd_spec: this, else the profile's own file, else fallback_taxonomy
    std::filesystem::path fallback_taxonomy;
    std::string tiles;                  // basemap URL template ({z}/{x}/{y}); empty: none
    std::string title;                  // empty: from the route
    std::string map_name;               // how the map folder is named in the page; empty: map_dir
};

// What a caller already holds (convert, before its outputs are in place):
// used instead of reading odd_profile.json, report.json and map.xodr.
struct Loaded {
    const odd::OddProfile* profile = nullptr;
    const nlohmann::ordered_json* report = nullptr;
    const xodr::Map* map = nullptr; // null: map.xodr is read
    // The mapped track ways in the map's frame, one node list (x, y) per way
    // part; null: ingest.geojson is read.
    const std::vector<std::vector<std::array<double, 2>>>* track_nodes = nullptr;
};

// The data document as JSON text, and the page's title.
struct PageData {
    std::string title;
    std::string json;
};

// Throws railodd::InputError naming the file that is missing or unreadable
// (map.xodr and odd_profile.json are required; report.json, ingest.geojson
// are used when present; scenario files and the spec when named).
PageData page_data(const ReportOptions& options);
PageData page_data(const ReportOptions& options, const Loaded& loaded);

// The data document parsed, for tools and tests.
nlohmann::ordered_json report_data(const ReportOptions& options);

// The page: the template with the libraries, the app and the data inlined.
void write_html(const PageData& data, std::ostream& out);
std::string render_html(const nlohmann::ordered_json& data);

} // namespace railodd::report
