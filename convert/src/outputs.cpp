// convert's last phases: the network tagged into every output at once
// (output_sinks.hpp), the profile along a route when one is asked for, and
// the page.
#include "outputs.hpp"
#include "output_sinks.hpp"

#include "railodd/odd/taxonomy.hpp"
#include "railodd/util/beside.hpp"

#include <filesystem>

namespace railodd::convert {

namespace {

std::filesystem::path taxonomy_path(const std::string& option) {
    return option.empty() ? std::filesystem::path{RAILODD_DATA_DIR} / "odd" / "railway_odd.yaml"
                          : std::filesystem::path{option};
}

using TrackNodes = std::vector<std::vector<std::array<double, 2>>>;

// The mapped track ways in the map's frame, one node list per way part.
TrackNodes track_nodes(const ingest::IngestResult& result) {
    TrackNodes lines;
    for (const auto& way : result.tracks) {
        for (const auto& part : way.parts) {
            auto& line = lines.emplace_back();
            for (const auto& n : part) {
                line.push_back({n.xy.x, n.xy.y});
            }
        }
    }
    return lines;
}

report::ReportOptions page_options(OutputStage& stage, const Options& o) {
    report::ReportOptions ro;
    ro.one_thread = o.threads == 1;
    ro.map_dir = stage.staged_path("map.xodr").parent_path();
    ro.map_name = o.outdir;
    ro.fallback_taxonomy = taxonomy_path({});
    return ro;
}

bool along_a_route(const Options& o, const ingest::IngestResult& r) { return !o.from.empty() || r.relation; }

// With --from/--to, the route between the two stations; else with
// --relation, the relation's member ways (the map stays the whole selection).
odd::Route find_route(const Options& o, const ingest::IngestResult& r, const geometry::FittedMap& g) {
    return o.from.empty() ? odd::relation_route(g.tracks, g.fitted_tracks, r.tracks, *r.relation, r.source)
                          : odd::find_route(g.tracks, g.fitted_tracks, g.attachment, r.features, o.from, o.to);
}

// The outputs of the profile itself: what the page and report.json keep of
// it, then its files (last: they take the batches).
void add_profile_outputs(Outputs& outputs, OutputStage& stage, const Options& o, Profiled& p, const xodr::Map& map) {
    outputs.push_back(std::make_unique<PageSectionOutput>(p, o.no_report ? nullptr : &map));
    outputs.push_back(std::make_unique<ProfileFilesOutput>(stage, o.threads != 1));
}

// A whole profile through outputs as one batch, its elements moved out (not
// copied); the head and tail are the profile without them.
void feed_whole(odd::OddProfile& profile, odd::ProfileSink& sink) {
    std::deque<odd::TaggedElement> elements;
    std::swap(elements, profile.elements);
    const odd::OddProfile head = profile;
    sink.begin(head);
    sink.add(elements);
    sink.end(head);
}

} // namespace

Profiled profile_and_write(OutputStage& stage, const Options& o, const ingest::IngestResult& r, geometry::FittedMap& geo,
                           const xodr::MapInput& map_input, const xodr::MapBuild& map, xodr::Revision revision,
                           PhaseTimer& timer) {
    // The tagger builds each batch's alignment indexes itself: the network's
    // (a fifth of the peak on Cologne) go first.
    std::vector<geometry::IndexedAlignment>().swap(geo.indexed);
    timer.start("odd_tagging");
    const odd::Taxonomy taxonomy = odd::load_taxonomy(taxonomy_path(o.taxonomy));
    Profiled p;
    Outputs network; // fed the whole network as it is tagged
    network.push_back(std::make_unique<MapOutput>(stage, map.map, revision, o.odd_user_data, beside(o)));
    network.push_back(std::make_unique<DebugOutput>(stage, o.debug_outputs, r, geo, beside(o)));
    // Along a route (found first: a station that is not there fails the run
    // before the tagging), the profile is the network's, whole, cut to it.
    odd::OddProfile whole;
    if (along_a_route(o, r)) {
        p.route = find_route(o, r, geo);
        network.push_back(std::make_unique<odd::WholeProfile>(whole));
    } else {
        add_profile_outputs(network, stage, o, p, map.map);
    }
    odd::tag_network({map_input, map}, taxonomy, network);
    timer.start("write_outputs");
    if (p.route) {
        odd::OddProfile along = odd::along_route(whole, *p.route, taxonomy);
        odd::OddProfile().elements.swap(whole.elements);
        Outputs route;
        add_profile_outputs(route, stage, o, p, map.map);
        feed_whole(along, route);
    }
    return p;
}

std::launch beside(const Options& o) { return util::beside(o.threads != 1); }

void write_page(OutputStage& stage, const Options& o, Profiled& profiled,
                const nlohmann::ordered_json& report, const xodr::Map& map, ingest::IngestResult& result) {
    PhaseTimer timer;
    timer.start("report_html");
    const TrackNodes nodes = track_nodes(result);
    const report::PageData page =
        report::page_data(page_options(stage, o), {&profiled.profile, &report, &map, &nodes, profiled.section.get()});
    profiled.section.reset();
    stage.write_with("report.html", [&](std::ostream& out) { report::write_html(page, out); });
    timer.stop();
    result.timings.insert(result.timings.end(), timer.seconds().begin(), timer.seconds().end());
}

} // namespace railodd::convert
