#include "outputs.hpp"
#include "sink_thread.hpp"

#include "railodd/geometry/dump.hpp"
#include "railodd/ingest/dump.hpp"
#include "railodd/odd/profile_files.hpp"
#include "railodd/odd/profile_outputs.hpp"
#include "railodd/odd/tagger.hpp"
#include "railodd/odd/taxonomy.hpp"
#include "railodd/xodr/xml_writer.hpp"

#include <filesystem>
#include <functional>
#include <future>

namespace railodd::convert {

namespace {

std::filesystem::path taxonomy_path(const std::string& option) {
    return option.empty() ? std::filesystem::path{RAILODD_DATA_DIR} / "odd" / "railway_odd.yaml"
                          : std::filesystem::path{option};
}

// A second thread's work runs beside this one's, or (--threads 1) when asked for.
std::launch beside(const Options& o) { return o.threads != 1 ? std::launch::async : std::launch::deferred; }

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

report::ReportOptions page_options(OutputStage& stage, const std::string& outdir) {
    report::ReportOptions ro;
    ro.map_dir = stage.staged_path("map.xodr").parent_path();
    ro.map_name = outdir;
    ro.fallback_taxonomy = taxonomy_path({});
    return ro;
}

// With --from/--to, the profile along the route between the two stations;
// else with --relation, along the relation's member ways (the map stays the
// whole selection); the route for report.json.
std::optional<odd::Route> route_profile(const Options& o, const ingest::IngestResult& r, const geometry::FittedMap& g,
                                        const odd::Taxonomy& taxonomy, const odd::OddProfile& network,
                                        odd::OddProfile& along) {
    if (o.from.empty() && !r.relation) {
        return std::nullopt;
    }
    odd::Route route = o.from.empty()
                           ? odd::relation_route(g.tracks, g.fitted_tracks, r.tracks, *r.relation, r.source)
                           : odd::find_route(g.tracks, g.fitted_tracks, g.attachment, r.features, o.from, o.to);
    along = odd::along_route(network, route, taxonomy);
    return route;
}

// The diagnostic GeoJSON files (the selected input; the fitted track and road
// centrelines sampled back to WGS84), with --debug-outputs only. Without it,
// any left by an earlier run go: they would describe another map.
void write_debug_outputs(OutputStage& stage, bool wanted, const ingest::IngestResult& result, const geometry::FittedMap& geo) {
    if (!wanted) {
        for (const char* name : {"ingest.geojson", "geometry.geojson", "roads.geojson"}) {
            stage.remove_on_commit(name);
        }
        return;
    }
    stage.write_with("ingest.geojson", [&](std::ostream& out) { ingest::write_geojson(result, out); });
    stage.write_with("geometry.geojson", [&](std::ostream& out) {
        geometry::write_geojson(geo.tracks, geo.fitted_tracks, result.projection, "track", out);
    });
    stage.write_with("roads.geojson", [&](std::ostream& out) {
        geometry::write_geojson(geo.roads, geo.fitted_roads, result.projection, "road", out);
    });
}

// The profile's files and (with a page to write) the page's section, fed
// together as the network is tagged; the head and tail kept.
class ProfileTee final : public odd::ProfileSink {
public:
    ProfileTee(odd::ProfileSink& files, Profiled& out, const xodr::Map* page_map)
        : files_(files), out_(out), page_map_(page_map) {}
    void begin(const odd::OddProfile& head) override {
        files_.begin(head);
        if (page_map_) {
            std::vector<std::string> road_ids;
            for (const auto& road : page_map_->roads) {
                road_ids.push_back(road.id);
            }
            out_.section = std::make_unique<report::ProfileSection>(head, road_ids);
        }
    }
    void add(std::deque<odd::TaggedElement>& batch) override {
        if (out_.section) {
            for (const auto& e : batch) {
                out_.section->add(e);
            }
        }
        files_.add(batch);
    }
    void end(const odd::OddProfile& tail) override {
        files_.end(tail);
        out_.profile = tail;
    }

private:
    odd::ProfileSink& files_;
    Profiled& out_;
    const xodr::Map* page_map_;
};

// odd_profile.json, .geojson and .csv, one writer for the three (ProfileFiles),
// fed by `feed`: the whole network as it is tagged, or a whole profile.
void write_profile_files(OutputStage& stage, const std::function<void(odd::ProfileSink&)>& feed) {
    stage.write_with("odd_profile.json", [&](std::ostream& json) {
        stage.write_with("odd_profile.geojson", [&](std::ostream& geojson) {
            stage.write_with("odd_profile.csv", [&](std::ostream& csv) {
                odd::ProfileFiles files(json, geojson, csv, stage.scratch_path("odd_profile.rows"));
                feed(files);
            });
        });
    });
}

// A whole profile through a sink as one batch (the head and tail: the
// profile without its elements, which are not copied).
void feed_whole(odd::OddProfile& profile, odd::ProfileSink& sink) {
    std::deque<odd::TaggedElement> elements;
    std::swap(elements, profile.elements);
    const odd::OddProfile head = profile;
    std::swap(elements, profile.elements);
    sink.begin(head);
    sink.add(profile.elements);
    sink.end(head);
}

// The whole network's profile straight into its files, while map.xodr (and
// the debug outputs) are written on another thread: both only read the map.
// With one thread (--threads 1) all of it runs in turn on this one.
Profiled stream_profile(OutputStage& stage, const Options& o, const ingest::IngestResult& r, geometry::FittedMap& geo,
                        const odd::TaggerInput& in, const odd::Taxonomy& taxonomy, xodr::Revision revision,
                        PhaseTimer& timer) {
    std::future<void> map_written = std::async(beside(o), [&] {
        stage.write_with("map.xodr", [&](std::ostream& out) { xodr::write_xodr(in.map.map, revision, out, {}); });
        write_debug_outputs(stage, o.debug_outputs, r, geo);
    });
    Profiled p;
    write_profile_files(stage, [&](odd::ProfileSink& files) {
        // The files are written on a thread of their own; the page's section
        // is fed here, so that what it keeps for the page lies in this
        // thread's heap (fed on the writer's, it left Cologne's peak 8 MB higher).
        std::optional<SinkThread> writer;
        if (o.threads != 1) {
            writer.emplace(files);
        }
        ProfileTee tee(writer ? static_cast<odd::ProfileSink&>(*writer) : files, p, o.no_report ? nullptr : &in.map.map);
        odd::tag_network(in, taxonomy, tee);
    });
    timer.start("write_outputs");
    map_written.get();
    return p;
}

// The profile made whole: along a route, or carried into map.xodr's userData.
Profiled whole_profile(OutputStage& stage, const Options& o, const ingest::IngestResult& r, geometry::FittedMap& geo,
                       const odd::TaggerInput& in, const odd::Taxonomy& taxonomy, xodr::Revision revision,
                       PhaseTimer& timer) {
    odd::OddProfile network = odd::tag_route(in, taxonomy);
    xodr::ExtraUserData odd_user_data; // the whole network's elements with each road, when asked for
    if (o.odd_user_data) {
        odd_user_data = odd::OddUserData(network);
    }
    Profiled p;
    odd::OddProfile along;
    p.route = route_profile(o, r, geo, taxonomy, network, along);
    timer.start("write_outputs");
    odd::OddProfile& profile = p.route ? along : network;
    // The profile's files on a second thread, the rest on this one: each file
    // has one writer, so no byte depends on the thread count.
    std::future<void> profile_written = std::async(beside(o), [&] {
        write_profile_files(stage, [&](odd::ProfileSink& files) { feed_whole(profile, files); });
    });
    stage.write_with("map.xodr", [&](std::ostream& out) { xodr::write_xodr(in.map.map, revision, out, odd_user_data); });
    write_debug_outputs(stage, o.debug_outputs, r, geo);
    profile_written.get();
    p.profile = p.route ? std::move(along) : std::move(network);
    return p;
}

} // namespace

Profiled profile_and_write(OutputStage& stage, const Options& o, const ingest::IngestResult& r, geometry::FittedMap& geo,
                           const xodr::MapInput& map_input, const xodr::MapBuild& map, xodr::Revision revision,
                           PhaseTimer& timer) {
    // The tagger builds each batch's alignment indexes itself: the network's
    // (a fifth of the peak on Cologne) go first.
    std::vector<geometry::IndexedAlignment>().swap(geo.indexed);
    timer.start("odd_tagging");
    const odd::TaggerInput in{map_input, map};
    const odd::Taxonomy taxonomy = odd::load_taxonomy(taxonomy_path(o.taxonomy));
    const bool whole = o.odd_user_data || !o.from.empty() || r.relation;
    return whole ? whole_profile(stage, o, r, geo, in, taxonomy, revision, timer)
                 : stream_profile(stage, o, r, geo, in, taxonomy, revision, timer);
}

void write_page(OutputStage& stage, const std::string& outdir, Profiled& profiled,
                const nlohmann::ordered_json& report, const xodr::Map& map, ingest::IngestResult& result) {
    PhaseTimer timer;
    timer.start("report_html");
    const TrackNodes nodes = track_nodes(result);
    const report::PageData page =
        report::page_data(page_options(stage, outdir), {&profiled.profile, &report, &map, &nodes, profiled.section.get()});
    profiled.section.reset();
    stage.write_with("report.html", [&](std::ostream& out) { report::write_html(page, out); });
    timer.stop();
    result.timings.insert(result.timings.end(), timer.seconds().begin(), timer.seconds().end());
}

} // namespace railodd::convert
