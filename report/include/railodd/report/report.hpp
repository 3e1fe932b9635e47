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
#include <memory>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

namespace railodd::odd {
struct OddProfile;
struct TaggedElement;
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
    bool one_thread = false;            // the node fit's second half in turn, not beside (convert --threads 1)
};

namespace detail {
class JsonText;
}

// The page's share of the ODD profile (its element table, OSM id lists and
// the tracks' road pieces), built element by element: convert feeds it as
// it tags the network, a batch at a time, and never holds the profile whole.
class ProfileSection {
public:
    // head: the profile's tracks and along_route; road_ids: the map's roads
    // in order (the page's road indices).
    ProfileSection(const odd::OddProfile& head, const std::vector<std::string>& road_ids);
    ProfileSection(const ProfileSection&) = delete;
    ProfileSection& operator=(const ProfileSection&) = delete;
    ~ProfileSection();
    void add(const odd::TaggedElement& e); // in profile order
    // Keys "kinds" and "osm" into the open document.
    void write_kinds(detail::JsonText& out) const;
    // The value of "elements", moved out: no add() after it.
    std::string take_rows();
    // The value of "tracks": each track's road pieces.
    nlohmann::ordered_json tracks_json() const;

private:
    struct State;
    std::unique_ptr<State> state_;
};

// What a caller already holds (convert, before its outputs are in place):
// used instead of reading odd_profile.json, report.json and map.xodr.
struct Loaded {
    // The profile; with `section`, only its head and tail (route, summary,
    // track ends), the elements having gone into the section.
    const odd::OddProfile* profile = nullptr;
    const nlohmann::ordered_json* report = nullptr;
    const xodr::Map* map = nullptr; // null: map.xodr is read
    // The mapped track ways in the map's frame, one node list (x, y) per way
    // part; null: ingest.geojson is read.
    const std::vector<std::vector<std::array<double, 2>>>* track_nodes = nullptr;
    ProfileSection* section = nullptr; // the profile's elements, when `profile` holds none
};

// The data document as JSON text, and the page's title. The text is kept in
// parts, in order: the profile's element table (a national network's largest
// part) is moved in whole, never copied or grown into a second buffer.
struct PageData {
    std::string title;
    std::vector<std::string> parts;
    std::string json() const; // the parts joined
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
