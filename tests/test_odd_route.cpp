// Routes between two stations on the embedded sample route: Sampleton (main
// line s 3290) to Brookside (s 6600) runs the main line through the tunnel and
// over the bridge, never into the passing loop or the spur; the reverse route
// mirrors it; unknown names are refused with the stations there are; and
// `railodd convert --from --to` writes the route and its profile.
#include "railodd/geometry/crossings.hpp"
#include "railodd/geometry/dump.hpp"
#include "railodd/geometry/feature_attachment.hpp"
#include "railodd/geometry/profiles.hpp"
#include "railodd/geometry/road_fit.hpp"
#include "railodd/ingest/osm_reader.hpp"
#include "railodd/odd/route.hpp"
#include "railodd/odd/tagger.hpp"
#include "railodd/sample/sample_route.hpp"
#include "railodd/util/errors.hpp"
#include "railodd/xodr/map_builder.hpp"
#include "railodd/xodr/xml_writer.hpp"
#include "odd_network_support.hpp"
#include "odd_profile_rows.hpp"
#include "test_support.hpp"

#include <nlohmann/json.hpp>

#include <set>

#include <unistd.h> // getpid: one folder per test process (CTest runs tests in parallel; a folder has one writer)

using namespace railodd;
using namespace railodd::test;

namespace {

struct Fixture : Network {
    xodr::MapBuild build;
    odd::OddProfile profile;
    nlohmann::json truth;
};

const Fixture& fixture() {
    static const Fixture f = [] {
        Fixture x;
        const auto dir = fs::temp_directory_path() / "railodd-tests" / ("odd-route-" + std::to_string(::getpid()));
        const sample::SampleFiles files = sample::write_sample_route(dir);
        x.truth = nlohmann::json::parse(read_file(files.truth));
        static_cast<Network&>(x) = network_of(files.osm);
        // The map and profile made without the indexes that placed the features.
        const geometry::FittedMap g = fitted_map(x, false);
        const xodr::MapInput in{x.ingest, g};
        x.build = xodr::build_map(in, xodr::MapOptions{});
        x.profile = odd::tag_route({in, x.build}, x.taxonomy);
        return x;
    }();
    return f;
}

odd::Route route(const std::string& from, const std::string& to) {
    const Fixture& f = fixture();
    return odd::find_route(f.tracks, f.fitted, f.attachment, f.ingest.features, from, to);
}

const odd::TaggedElement* find(const odd::OddProfile& p, const std::string& path) {
    for (const auto& e : p.elements) {
        if (e.element == path) {
            return &e;
        }
    }
    return nullptr;
}

// Graph edges holding a way of the passing loop or the spur.
std::set<std::size_t> off_main_edges(const Fixture& f) {
    std::set<std::int64_t> ways;
    for (const auto& w : f.truth["ways"]) {
        if (w.contains("track") && w["track"] != "main") {
            ways.insert(w["id"].get<std::int64_t>());
        }
    }
    std::set<std::size_t> edges;
    for (const auto& e : f.tracks.edges) {
        for (const auto& span : e.ways) {
            if (ways.contains(span.way_id)) {
                edges.insert(e.id);
            }
        }
    }
    return edges;
}

TEST(OddRoute, PrebuiltTrackIndexesChangeNoOutput) {
    // convert hands the indexes it made to place the features on to the map
    // builder, the tagger and the report; without them each indexes the
    // tracks itself.
    const Fixture& f = fixture();
    const geometry::FittedMap g = fitted_map(f, true);
    const xodr::MapInput in{f.ingest, g};
    const xodr::MapBuild build = xodr::build_map(in, xodr::MapOptions{});
    EXPECT_EQ(xodr::write_xodr(build.map, xodr::Revision::v1_7), xodr::write_xodr(f.build.map, xodr::Revision::v1_7));
    const odd::OddProfile profile = odd::tag_route({in, build}, f.taxonomy);
    ASSERT_GT(profile.elements.size(), 50u);
    EXPECT_EQ(odd::to_json_text(profile), odd::to_json_text(f.profile));
    EXPECT_EQ(geometry::report_section(f.tracks, f.fitted, &f.indexed), geometry::report_section(f.tracks, f.fitted));
}

TEST(OddRoute, SampletonToBrooksideRunsTheMainLine) {
    const odd::Route r = route("Sampleton", "Brookside");
    EXPECT_EQ(r.from, "Sampleton");
    EXPECT_EQ(r.to, "Brookside");
    EXPECT_NEAR(r.length_m, 6600.0 - 3290.0, 30.0);
    ASSERT_FALSE(r.pieces.empty());
    double chainage = 0.0;
    const auto off = off_main_edges(fixture());
    EXPECT_FALSE(off.empty());
    for (const auto& p : r.pieces) {
        EXPECT_NEAR(p.chainage_start, chainage, 1e-6);
        chainage += std::abs(p.s_to - p.s_from);
        EXPECT_FALSE(off.contains(p.edge)) << "edge " << p.edge;
    }
    EXPECT_NEAR(chainage, r.length_m, 1e-6);
}

TEST(OddRoute, ProfileAlongTheRouteHasTunnelAndBridgeAtRouteChainage) {
    const Fixture& f = fixture();
    const odd::Route r = route("Sampleton", "Brookside");
    const odd::OddProfile p = odd::along_route(f.profile, r, f.taxonomy);
    EXPECT_EQ(p.route, "Sampleton -> Brookside");
    EXPECT_DOUBLE_EQ(p.length_m, r.length_m);
    EXPECT_EQ(p.tracks, r.pieces.size());
    const auto* tunnel = find(p, "Scenery/Structures/Tunnel");
    const auto* bridge = find(p, "Scenery/Structures/Bridge");
    ASSERT_TRUE(tunnel && bridge);
    EXPECT_NEAR(tunnel->chainage_start, 4300.0 - 3290.0, 15.0);
    EXPECT_NEAR(tunnel->chainage_end, 4900.0 - 3290.0, 15.0);
    EXPECT_NEAR(bridge->chainage_start, 5350.0 - 3290.0, 15.0);
    EXPECT_NEAR(bridge->chainage_end, 5500.0 - 3290.0, 15.0);
    const auto off = off_main_edges(f);
    double last = 0.0;
    for (const auto& e : p.elements) {
        EXPECT_FALSE(off.contains(e.track)) << e.element << " on edge " << e.track;
        EXPECT_GE(e.chainage_start, -1e-6) << e.element;
        EXPECT_LE(e.chainage_end, r.length_m + 1e-6) << e.element;
        EXPECT_LE(e.chainage_start, e.chainage_end) << e.element;
        EXPECT_GE(e.chainage_start, last) << e.element;
        last = e.chainage_start;
    }
    EXPECT_EQ(p.summary["tunnels"]["count"], 1);
    EXPECT_EQ(p.summary["bridges"]["count"], 1);
    EXPECT_LT(p.elements.size(), f.profile.elements.size());
}

TEST(OddRoute, ReverseRouteMirrorsChainage) {
    const Fixture& f = fixture();
    const odd::Route there = route("Sampleton", "Brookside");
    const odd::Route back = route("brookside", "SAMPLETON"); // names match ignoring case too
    EXPECT_EQ(back.from, "Brookside");
    EXPECT_NEAR(back.length_m, there.length_m, 1e-6);
    const odd::OddProfile p = odd::along_route(f.profile, back, f.taxonomy);
    EXPECT_EQ(p.route, "Brookside -> Sampleton");
    const auto* tunnel = find(p, "Scenery/Structures/Tunnel");
    const auto* bridge = find(p, "Scenery/Structures/Bridge");
    ASSERT_TRUE(tunnel && bridge);
    EXPECT_NEAR(tunnel->chainage_start, back.length_m - (4900.0 - 3290.0), 15.0);
    EXPECT_NEAR(tunnel->chainage_end, back.length_m - (4300.0 - 3290.0), 15.0);
    EXPECT_NEAR(bridge->chainage_start, back.length_m - (5500.0 - 3290.0), 15.0);
    EXPECT_NEAR(bridge->chainage_end, back.length_m - (5350.0 - 3290.0), 15.0);
    for (const auto& piece : back.pieces) {
        EXPECT_TRUE(piece.reversed != (piece.s_to > piece.s_from));
    }
}

// The graph edge holding the truth way of `track` that starts at or after main-line s `from`.
std::size_t edge_of_way(const Fixture& f, const std::string& track, double from) {
    for (const auto& w : f.truth["ways"]) {
        if (w.value("track", "") == track && w.value("s_from", -1.0) >= from) {
            for (const auto& e : f.tracks.edges) {
                for (const auto& span : e.ways) {
                    if (span.way_id == w["id"].get<std::int64_t>()) {
                        return e.id;
                    }
                }
            }
        }
    }
    throw std::runtime_error("no " + track + " way from s " + std::to_string(from));
}

// Stops added on the spur and on the main line beyond the spur's switch: no
// train runs from one to the other without reversing at the switch, while the
// spur reaches Brookside through the switch's stem.
TEST(OddRoute, SwitchesAreOnlyPassedTowardsTheirStem) {
    const Fixture& f = fixture();
    std::vector<ingest::Feature> features = f.ingest.features;
    geometry::Attachment attachment = f.attachment;
    const std::size_t spur = edge_of_way(f, "spur", 0.0), beyond = edge_of_way(f, "main", 7700.0);
    for (const auto& [name, edge] : {std::pair{"Spur End", spur}, std::pair{"Line End", beyond}}) {
        ingest::Feature stop;
        stop.kind = "halt";
        stop.tags["name"] = name;
        features.push_back(stop);
        geometry::AttachedFeature a;
        a.feature = features.size() - 1;
        a.edge = edge;
        a.s = a.s_start = a.s_end = 100.0;
        attachment.attached.push_back(a);
    }
    EXPECT_THROW(odd::find_route(f.tracks, f.fitted, attachment, features, "Spur End", "Line End"), InputError);
    const odd::Route r = odd::find_route(f.tracks, f.fitted, attachment, features, "Spur End", "Brookside");
    ASSERT_GE(r.pieces.size(), 2U);
    EXPECT_EQ(r.pieces.front().edge, spur);
    // From the spur's switch (main s 7700) back to Brookside (6600), plus the spur's first metres.
    EXPECT_NEAR(r.length_m, 1100.0 + (f.fitted.edges[spur].reversed ? geometry::length(f.fitted.edges[spur].alignment) - 100.0 : 100.0), 30.0);
}

TEST(OddRoute, UnknownStationIsRefusedListingTheStations) {
    try {
        route("Nowhere", "Brookside");
        FAIL() << "no error";
    } catch (const InputError& e) {
        const std::string what = e.what();
        EXPECT_NE(what.find("'Nowhere'"), std::string::npos) << what;
        EXPECT_NE(what.find("stations are: Brookside, Sampleton"), std::string::npos) << what;
    }
}

TEST(OddRoute, ConvertFromToWritesTheRoute) {
    const fs::path dir = scratch_dir();
    const auto s = run_command(std::string{RAILODD_BIN} + " sample -o " + quoted(dir / "in"));
    ASSERT_EQ(s.exit_code, 0) << s.output;
    const std::string convert = std::string{RAILODD_BIN} + " convert " + quoted(dir / "in" / "sample_route.osm") +
                                " --no-timings --odd-user-data -o ";
    const auto c = run_command(convert + quoted(dir / "out") + " --from Sampleton --to Brookside");
    ASSERT_EQ(c.exit_code, 0) << c.output;
    const auto report = nlohmann::json::parse(read_file(dir / "out" / "report.json"));
    ASSERT_TRUE(report.contains("route"));
    const auto& r = report["route"];
    EXPECT_EQ(r["from"], "Sampleton");
    EXPECT_EQ(r["to"], "Brookside");
    const double length = r["length_m"];
    EXPECT_NEAR(length, 3310.0, 30.0);
    ASSERT_FALSE(r["pieces"].empty());
    for (const auto& p : r["pieces"]) {
        for (const char* key : {"edge", "reversed", "s_from", "s_to", "chainage_start"}) {
            EXPECT_TRUE(p.contains(key)) << key;
        }
    }
    const auto profile = with_element_objects(nlohmann::json::parse(read_file(dir / "out" / "odd_profile.json")));
    EXPECT_EQ(profile["route"]["description"], "Sampleton -> Brookside");
    EXPECT_FALSE(profile["elements"].empty());
    for (const auto& e : profile["elements"]) {
        EXPECT_GE(e["chainage_start"].get<double>(), -1e-6) << e.dump();
        EXPECT_LE(e["chainage_end"].get<double>(), length + 0.0005) << e.dump(); // written to the mm
    }
    // The map is the whole selection, and so are the ODD tags on its roads:
    // the route narrows only the profile.
    const auto whole = run_command(convert + quoted(dir / "whole"));
    ASSERT_EQ(whole.exit_code, 0) << whole.output;
    auto odd_entries = [](const std::string& xodr) {
        std::size_t n = 0;
        for (auto at = xodr.find("code=\"odd\""); at != std::string::npos; at = xodr.find("code=\"odd\"", at + 1)) {
            ++n;
        }
        return n;
    };
    const std::string route_map = read_file(dir / "out" / "map.xodr");
    EXPECT_GT(odd_entries(route_map), profile["elements"].size());
    EXPECT_EQ(route_map, read_file(dir / "whole" / "map.xodr"));
    const auto half = run_command(convert + quoted(dir / "half") + " --from Sampleton");
    EXPECT_EQ(half.exit_code, exit_usage) << half.output;
    const auto unknown = run_command(convert + quoted(dir / "unknown") + " --from Sampleton --to Atlantis");
    EXPECT_EQ(unknown.exit_code, exit_input) << unknown.output;
    EXPECT_NE(unknown.output.find("stations are: Brookside, Sampleton"), std::string::npos) << unknown.output;
}

} // namespace
