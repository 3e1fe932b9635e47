#pragma once
// A straight track through the whole pipeline (ingest, graph, fit, profiles,
// map build, tagger), for tagger tests that feed their own OSM input.
#include "railodd/geometry/crossings.hpp"
#include "railodd/geometry/feature_attachment.hpp"
#include "railodd/geometry/profiles.hpp"
#include "railodd/geometry/road_fit.hpp"
#include "railodd/ingest/osm_reader.hpp"
#include "railodd/odd/tagger.hpp"
#include "railodd/xodr/map_builder.hpp"
#include "test_support.hpp"

#include <string>
#include <vector>

namespace railodd::test {

// 21 nodes along 48.0 N, about 100 m apart, from 10.0 E eastwards.
inline std::string straight_track_opl() {
    std::string opl, refs;
    for (int i = 0; i <= 20; ++i) {
        // append(), not "n" + ...: GCC 12 warns (-Wrestrict) on those temporaries
        opl.append("n").append(std::to_string(i + 1)).append(" v1 x").append(std::to_string(10.0 + 0.0013443 * i));
        opl.append(" y48.0\n");
        refs.append(i ? ",n" : "n").append(std::to_string(i + 1));
    }
    return opl + "w1 v1 Trailway=rail N" + refs + "\n";
}

struct Pipeline {
    ingest::IngestResult ingest;
    geometry::TrackGraph tracks, roads;
    geometry::FittedNetwork fitted, fitted_roads;
    std::vector<geometry::VerticalProfile> profiles;
    std::vector<std::vector<geometry::CantStretch>> cants;
    geometry::Attachment attachment;
    geometry::Crossings crossings;
    odd::Taxonomy taxonomy;

    explicit Pipeline(const fs::path& osm) {
        ingest = ingest::read_osm(osm, {});
        tracks = geometry::build_track_graph(ingest.tracks, ingest.features);
        fitted = geometry::fit_track_graph(tracks, geometry::FitOptions{});
        profiles = geometry::fit_profiles(tracks, fitted, ingest.tracks, ingest.projection, nullptr);
        cants = geometry::fit_cants(tracks, fitted, ingest.tracks, geometry::CantOptions{});
        roads = geometry::build_track_graph(ingest.roads, {});
        fitted_roads = geometry::fit_road_graph(roads, geometry::RoadFitOptions{});
        taxonomy = odd::load_taxonomy(fs::path{RAILODD_SOURCE_DIR} / "data/odd/railway_odd.yaml");
    }

    odd::OddProfile tag() const {
        const geometry::FittedMap g{tracks, fitted, profiles, cants, attachment, crossings, roads, fitted_roads, {}};
        const xodr::MapInput in{ingest, g};
        const xodr::MapBuild build = xodr::build_map(in, xodr::MapOptions{});
        return odd::tag_route({in, build}, taxonomy);
    }
};

} // namespace railodd::test
