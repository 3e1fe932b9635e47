#pragma once
// A network through the whole pipeline (ingest, graph, fit, profiles, cant,
// features placed, crossings) and tagged by tag_network with a given batch
// size, each batch recorded: for the batch tests on the sample route and on
// real extracts.
#include "railodd/geometry/crossings.hpp"
#include "railodd/geometry/feature_attachment.hpp"
#include "railodd/geometry/fitted_map.hpp"
#include "railodd/geometry/profiles.hpp"
#include "railodd/geometry/road_fit.hpp"
#include "railodd/ingest/osm_reader.hpp"
#include "railodd/odd/tagger.hpp"
#include "railodd/xodr/map_builder.hpp"
#include "test_support.hpp"

#include <deque>
#include <vector>

namespace railodd::test {

struct Network {
    ingest::IngestResult ingest;
    geometry::TrackGraph tracks, roads;
    geometry::FittedNetwork fitted, fitted_roads;
    std::vector<geometry::VerticalProfile> profiles;
    std::vector<std::vector<geometry::CantStretch>> cants;
    geometry::Attachment attachment;
    geometry::Crossings crossings;
    std::vector<geometry::IndexedAlignment> indexed;
    odd::Taxonomy taxonomy;
};

// The geometry stage's result as the map builder and the tagger take it;
// with_indexes: the tracks' 2 m indexes too (as convert hands them on).
inline geometry::FittedMap fitted_map(const Network& n, bool with_indexes) {
    geometry::FittedMap g{n.tracks, n.fitted, n.profiles, n.cants, n.attachment, n.crossings, n.roads, n.fitted_roads, {}};
    if (with_indexes) {
        g.indexed = n.indexed;
    }
    return g;
}

inline Network network_of(const fs::path& osm) {
    Network x;
    x.ingest = ingest::read_osm(osm, {});
    x.tracks = geometry::build_track_graph(x.ingest.tracks, x.ingest.features);
    x.fitted = geometry::fit_track_graph(x.tracks, geometry::FitOptions{});
    x.profiles = geometry::fit_profiles(x.tracks, x.fitted, x.ingest.tracks, x.ingest.projection, nullptr);
    x.cants = geometry::fit_cants(x.tracks, x.fitted, x.ingest.tracks, geometry::CantOptions{true});
    x.roads = geometry::build_track_graph(x.ingest.roads, {});
    x.fitted_roads = geometry::fit_road_graph(x.roads, geometry::RoadFitOptions{});
    for (const auto& e : x.fitted.edges) {
        x.indexed.emplace_back(e.alignment, 2.0);
    }
    x.attachment = geometry::attach_features(x.tracks, x.indexed, x.ingest.features, 50.0, 500.0);
    x.crossings = geometry::find_crossings(x.tracks, x.ingest.tracks, x.ingest.roads, x.ingest.features);
    x.taxonomy = odd::load_taxonomy(fs::path{RAILODD_SOURCE_DIR} / "data/odd/railway_odd.yaml");
    return x;
}

// Every batch kept as it came, and the profile they make.
class BatchRecorder final : public odd::ProfileSink {
public:
    void begin(const odd::OddProfile& head) override {
        ++begins;
        whole = head;
    }
    void add(std::deque<odd::TaggedElement>& batch) override {
        batches.push_back(batch);
        whole.elements.insert(whole.elements.end(), batch.begin(), batch.end());
    }
    void end(const odd::OddProfile& tail) override {
        ++ends;
        tail_elements += tail.elements.size();
        whole.unparsed = tail.unparsed;
        whole.summary = tail.summary;
    }
    int begins = 0, ends = 0;
    std::size_t tail_elements = 0;
    std::vector<std::deque<odd::TaggedElement>> batches;
    odd::OddProfile whole;
};

// prebuilt: the tracks' indexes handed to the tagger, as convert once did.
inline BatchRecorder tag_in_batches(const Network& n, std::size_t batch, bool prebuilt) {
    const geometry::FittedMap g = fitted_map(n, prebuilt);
    const xodr::MapInput in{n.ingest, g};
    const xodr::MapBuild build = xodr::build_map(in, xodr::MapOptions{});
    BatchRecorder r;
    odd::tag_network({in, build}, n.taxonomy, r, batch);
    return r;
}

} // namespace railodd::test
