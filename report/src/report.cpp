// The report's data document, section by section in the order of the page
// (report/web/data_format.md).
#include "railodd/report/report.hpp"

#include "parts.hpp"

#include "railodd/odd/odd_spec.hpp"
#include "railodd/odd/spec_check.hpp"
#include "railodd/odd/taxonomy.hpp"
#include "railodd/util/errors.hpp"

#include <optional>


namespace railodd::report {

using detail::cm;
using detail::ojson;
namespace fs = std::filesystem;

namespace {

// Violations beyond this are counted, not listed: a spec far from a national
// network's reality would list every element.
constexpr std::size_t max_violations = 5000;

// report.json where it is (convert writes it; a folder from elsewhere may lack it).
ojson optional_json(const fs::path& file) {
    return fs::is_regular_file(file) ? detail::read_checked_json(file, "convert report", detail::convert_report_shape())
                                     : ojson::object();
}

// As `railodd profile` chooses it: the option, else the file the profile was
// tagged with (as written, then beside it), else the shipped one.
fs::path taxonomy_of(const ReportOptions& o, const odd::OddProfile& profile) {
    if (!o.taxonomy.empty()) {
        return o.taxonomy;
    }
    const fs::path named{profile.taxonomy_file};
    if (!named.empty() && fs::is_regular_file(named)) {
        return named;
    }
    if (!named.empty() && named.is_relative() && fs::is_regular_file(o.map_dir / named)) {
        return o.map_dir / named;
    }
    return o.fallback_taxonomy;
}

ojson spec_json(const ReportOptions& o, const odd::OddProfile& profile, const detail::RoadData& roads) {
    if (o.odd_spec.empty()) {
        return nullptr;
    }
    const odd::Taxonomy taxonomy = odd::load_taxonomy(taxonomy_of(o, profile));
    const odd::SpecVerdict v = odd::check_spec(profile, odd::load_odd_spec(o.odd_spec, taxonomy), taxonomy);
    detail::Array violations;
    for (std::size_t i = 0; i < v.violations.size() && i < max_violations; ++i) {
        const auto& x = v.violations[i];
        std::string osm;
        for (const auto& id : x.osm_ids) {
            osm += (osm.empty() ? "" : ",") + id;
        }
        violations.push_back({{"element", x.element}, {"spec_element", x.spec_element}, {"attribute", x.attribute},
                              {"value", x.value}, {"unit", x.unit}, {"constraint", x.constraint}, {"note", x.note},
                              {"road", roads.index_of(x.road_id)}, {"s0", cm(x.s_start)}, {"s1", cm(x.s_end)},
                              {"track", x.track}, {"ch0", cm(x.chainage_start)}, {"ch1", cm(x.chainage_end)},
                              {"point", x.point}, {"osm", osm}});
    }
    ojson stretches = ojson::array();
    for (const auto& s : v.stretches) {
        stretches.push_back({{"track", s.track}, {"ch0", cm(s.chainage_start)}, {"ch1", cm(s.chainage_end)},
                             {"elements", s.elements}, {"violations", s.violations}});
    }
    return {{"name", v.spec_name}, {"source", v.spec_source}, {"passed", v.passed},
            {"elements_checked", v.elements_checked}, {"elements_outside", v.elements_outside},
            {"violations_total", v.violations.size()}, {"violations", ojson(std::move(violations))},
            {"stretches", std::move(stretches)}};
}

// report.json's counts: what was dropped or repaired and what the map holds.
ojson input_json(const ojson& report) {
    ojson opendrive = ojson::object();
    const ojson written = report.value("opendrive", ojson::object());
    for (const auto& [k, v] : written.items()) {
        if (v.is_number()) {
            opendrive[k] = v;
        } else if (v.is_array()) {
            opendrive[k] = v.size();
        }
    }
    const ojson vertical = report.value("vertical", ojson::object());
    return {{"dropped", report.value("dropped", ojson::array()).size()},
            {"repairs", report.value("repairs", ojson::array()).size()},
            {"input", report.value("input", ojson::object())},
            {"opendrive", std::move(opendrive)},
            {"elevation_sources", vertical.value("sources", ojson::object())}};
}

ojson meta_json(const ReportOptions& o, const odd::OddProfile& profile, const fs::path& play_file) {
    const std::string map_name = o.map_name.empty() ? o.map_dir.string() : o.map_name;
    return {{"title", o.title.empty() ? "railodd report: " + profile.route : o.title},
            {"route", profile.route},
            {"length_m", cm(profile.length_m)},
            {"tracks", profile.tracks},
            {"along_route", profile.along_route},
            {"railodd", "0.1.0"},
            {"map_dir", map_name},
            {"scenario_dir", o.scenario_dir.empty() ? ojson(nullptr) : ojson(o.scenario_dir.string())},
            {"play_file", play_file.empty() ? ojson(nullptr) : ojson(play_file.string())},
            {"tiles", o.tiles.empty() ? ojson(nullptr) : ojson(o.tiles)}};
}

fs::path play_file_of(const ReportOptions& o) {
    if (!o.play_file.empty()) {
        return fs::is_directory(o.play_file) ? o.play_file / "play.json" : o.play_file;
    }
    if (!o.scenario_dir.empty() && fs::is_regular_file(o.scenario_dir / "play.json")) {
        return o.scenario_dir / "play.json";
    }
    return {};
}

} // namespace

PageData page_data(const ReportOptions& o) {
    const odd::OddProfile profile = odd::read_profile(o.map_dir / "odd_profile.json");
    const ojson report = optional_json(o.map_dir / "report.json");
    return page_data(o, {&profile, &report});
}

ojson report_data(const ReportOptions& o) { return ojson::parse(page_data(o).json()); }

std::string PageData::json() const {
    std::string all;
    for (const auto& p : parts) {
        all += p;
    }
    return all;
}

PageData page_data(const ReportOptions& o, const Loaded& loaded) {
    const xodr_check::MapLines map = loaded.map ? detail::map_lines_of(*loaded.map, (o.map_dir / "map.xodr").string())
                                                : xodr_check::read_map_lines(o.map_dir / "map.xodr");
    const odd::OddProfile& profile = *loaded.profile;
    const ojson& report = *loaded.report;
    const detail::GeoFrame frame(map.geo_reference, map.file);
    const detail::RoadData roads(map, frame);
    const fs::path play_file = play_file_of(o);
    const ojson meta = meta_json(o, profile, play_file);

    PageData page{meta.at("title").get<std::string>(), {}};
    std::string text;
    detail::JsonText out(text);
    out.open('{').key("format").string("railodd_report_data").key("format_version").integer(1);
    out.key("meta").value(meta).key("bounds").value(roads.bounds_json());
    out.key("roads");
    roads.write_roads(out);
    std::optional<ProfileSection> own; // from the profile's elements, when the caller has no section
    if (!loaded.section) {
        std::vector<std::string> road_ids;
        for (const auto& r : map.roads) {
            road_ids.push_back(r.id);
        }
        own.emplace(profile, road_ids);
        for (const auto& e : profile.elements) {
            own->add(e);
        }
    }
    ProfileSection& section = loaded.section ? *loaded.section : *own;
    section.write_kinds(out);
    out.key("elements").raw(""); // its value is the next part
    page.parts.push_back(std::move(text));
    text = std::string();
    page.parts.push_back(section.take_rows());
    const ojson tracks = section.tracks_json();
    own.reset();
    out.key("summary").value(profile.summary).key("chains").value(detail::chains_json(profile, tracks));
    out.key("tracks").value(tracks);
    // The geometry section as it is (value() would copy it, at the page's peak).
    static const ojson no_geometry = ojson::object();
    const auto g = report.find("geometry");
    const detail::NodeFit nf =
        detail::node_fit(o.map_dir, g != report.end() ? *g : no_geometry, roads, frame, loaded.track_nodes, !o.one_thread);
    out.key("node_curvature").numbers(nf.curvature).key("spec").value(spec_json(o, profile, roads));
    // "fit": its figures, then the node arrays.
    out.key("fit").open('{');
    for (const auto& [k, v] : nf.fit.items()) {
        out.key(k).value(v);
    }
    out.key("node_pts").integers(nf.node_pts).key("node_res").integers(nf.node_res).close('}');
    out.key("input").value(input_json(report)).key("scenarios");
    out.value(o.scenario_dir.empty() ? ojson(nullptr) : detail::scenario_section(o.scenario_dir, play_file, roads));
    out.close('}');
    page.parts.push_back(std::move(text));
    return page;
}

} // namespace railodd::report
