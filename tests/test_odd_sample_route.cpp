// ODD tags of the embedded ground-truth route (railodd sample): every designed
// main-line curve found with its radius (within 5 %) and direction on the right
// stretch, the level crossing within 5 m of its true place, the stations,
// tunnel and bridge where they were designed, the switches, and the tags in
// map.xodr's userData.
#include "railodd/geometry/alignment.hpp"
#include "railodd/ingest/projection.hpp"
#include "odd_profile_rows.hpp"
#include "test_support.hpp"

#include <nlohmann/json.hpp>

#include <cmath>
#include <limits>

using namespace railodd;
using namespace railodd::test;

namespace {

struct Converted {
    nlohmann::json truth, profile, geojson, report;
    std::string xodr;
};

const Converted& run() {
    static const Converted r = [] {
        Converted x;
        const fs::path dir = scratch_dir();
        const auto s = run_command(std::string{RAILODD_BIN} + " sample -o " + quoted(dir / "in"));
        const auto c = run_command(std::string{RAILODD_BIN} + " convert " + quoted(dir / "in" / "sample_route.osm") +
                                   " --dem " + quoted(dir / "in" / "sample_route_dem.tif") + " -o " + quoted(dir / "out") +
                                   " --no-timings --estimate-cant");
        if (s.exit_code != 0 || c.exit_code != 0) {
            throw std::runtime_error("sample/convert failed: " + s.output + c.output);
        }
        x.truth = nlohmann::json::parse(read_file(dir / "in" / "sample_route_truth.json"));
        x.report = nlohmann::json::parse(read_file(dir / "out" / "report.json"));
        x.profile = with_element_objects(nlohmann::json::parse(read_file(dir / "out" / "odd_profile.json")));
        x.geojson = nlohmann::json::parse(read_file(dir / "out" / "odd_profile.geojson"));
        x.xodr = read_file(dir / "out" / "map.xodr");
        return x;
    }();
    return r;
}

geometry::Alignment truth_track(const nlohmann::json& truth, const std::string& name) {
    for (const auto& t : truth["tracks"]) {
        if (t["name"] == name) {
            geometry::Alignment a;
            a.start = {t["start"]["x"], t["start"]["y"], t["start"]["hdg"], 0.0};
            for (const auto& p : t["primitives"]) {
                const std::string k = p["kind"];
                a.primitives.push_back({k == "line" ? geometry::PrimitiveKind::line
                                        : k == "arc" ? geometry::PrimitiveKind::arc
                                                     : geometry::PrimitiveKind::spiral,
                                        p["length"], p["curv_start"], p["curv_end"]});
            }
            return a;
        }
    }
    throw std::runtime_error("no truth track " + name);
}

// Distance (m, in the truth frame) from a truth point to a GeoJSON feature.
double distance_to(const ingest::LocalProjection& frame, const nlohmann::json& element, double x, double y) {
    double best = std::numeric_limits<double>::infinity();
    const auto& g = element["geometry"];
    const nlohmann::json coords = g["type"] == "Point" ? nlohmann::json::array({g["coordinates"]}) : g["coordinates"];
    for (const auto& ll : coords) {
        const ingest::XY p = frame.forward({ll[0].get<double>(), ll[1].get<double>()});
        best = std::min(best, std::hypot(p.x - x, p.y - y));
    }
    return best;
}

// The element of a kind nearest to a truth point, with its distance.
std::pair<const nlohmann::json*, double> nearest(const Converted& r, const std::string& path, double x, double y) {
    const ingest::LocalProjection frame({r.truth["frame"]["origin_lon"], r.truth["frame"]["origin_lat"]});
    const nlohmann::json* hit = nullptr;
    double best = std::numeric_limits<double>::infinity();
    for (const auto& f : r.geojson["features"]) {
        if (f["properties"]["odd_element"] != path) {
            continue;
        }
        const double d = distance_to(frame, f, x, y);
        if (d < best) {
            best = d;
            hit = &f["properties"];
        }
    }
    return {hit, best};
}

geometry::Pose truth_at(const Converted& r, const std::string& track, double s) {
    return geometry::evaluate(truth_track(r.truth, track), s);
}

} // namespace

TEST(OddSampleRoute, NodeNoiseIsEstimatedFromTheNodes) {
    // No --node-noise: each chain's scatter is read from its nodes (the
    // sample draws them with the truth's sigma). The main line's chain has
    // the most nodes; the short loop and spur chains have too few closely
    // spaced nodes to tell and take the default (0.1 m).
    const auto& n = run().report["geometry"]["summary"]["node_noise"];
    const double truth = run().truth["noise_sigma_m"].get<double>();
    const nlohmann::json* main_track = nullptr;
    for (const auto& t : run().report["geometry"]["tracks"]) {
        if (!main_track || t["nodes"].get<int>() > (*main_track)["nodes"].get<int>()) {
            main_track = &t;
        }
    }
    ASSERT_NE(main_track, nullptr);
    EXPECT_NEAR((*main_track)["noise_sigma_m"].get<double>(), truth, 0.25 * truth);
    EXPECT_EQ(n["outlier_nodes"], 0);
    EXPECT_LT(n["node_distance_p95_sigmas"].get<double>(), 2.5);
}

TEST(OddSampleRoute, GeoJsonHasOneFeaturePerElement) {
    EXPECT_EQ(run().geojson["features"].size(), run().profile["elements"].size());
}

TEST(OddSampleRoute, EveryMainLineCurveWithItsRadiusOnTheRightStretch) {
    const Converted& r = run();
    for (const auto& c : r.truth["curves"]) {
        if (c["track"] != "main") {
            continue;
        }
        const double mid = (c["s_from"].get<double>() + c["s_to"].get<double>()) / 2.0;
        const geometry::Pose p = truth_at(r, "main", mid);
        const auto [e, d] = nearest(r, "Scenery/Track geometry/Horizontal/Curve", p.x, p.y);
        ASSERT_NE(e, nullptr);
        SCOPED_TRACE("curve R " + std::to_string(c["radius"].get<double>()) + " at s " + std::to_string(mid));
        EXPECT_LT(d, 25.0) << "a tagged curve covers the designed curve's middle";
        EXPECT_NEAR((*e)["attributes"]["radius"].get<double>(), c["radius"].get<double>(), 0.05 * c["radius"].get<double>());
        EXPECT_EQ((*e)["attributes"]["direction"], c["direction"]);
        EXPECT_TRUE((*e)["attributes"].contains("radius_class"));
    }
}

TEST(OddSampleRoute, LevelCrossingWithinFiveMetres) {
    const Converted& r = run();
    const auto& lc = r.truth["features"]["level_crossings"][0];
    const auto [e, d] = nearest(r, "Scenery/Crossings/Level crossing", lc["x"], lc["y"]);
    ASSERT_NE(e, nullptr);
    EXPECT_LT(d, 5.0);
    for (const auto& f : r.geojson["features"]) {
        if (f["properties"]["odd_element"] == "Scenery/Crossings/Level crossing") {
            EXPECT_EQ(f["geometry"]["type"], "Point");
        }
    }
}

TEST(OddSampleRoute, StationsTunnelAndBridgeOnTheRightStretch) {
    const Converted& r = run();
    for (const auto& st : r.truth["features"]["stations"]) {
        const std::string path = st["type"] == "halt" ? "Scenery/Stations and stops/Halt" : "Scenery/Stations and stops/Station";
        const geometry::Pose p = truth_at(r, "main", st["s"]);
        EXPECT_LT(nearest(r, path, p.x, p.y).second, 30.0) << st["name"];
    }
    for (const auto& [kind, path] : {std::pair{"tunnels", "Scenery/Structures/Tunnel"}, std::pair{"bridges", "Scenery/Structures/Bridge"}}) {
        const auto& t = r.truth["features"][kind][0];
        for (const char* end : {"s_from", "s_to"}) {
            const geometry::Pose p = truth_at(r, "main", t[end]);
            EXPECT_LT(nearest(r, path, p.x, p.y).second, 10.0) << kind << " " << end;
        }
        const auto [e, d] = nearest(r, path, truth_at(r, "main", t["s_from"]).x, truth_at(r, "main", t["s_from"]).y);
        EXPECT_NEAR((*e)["attributes"]["length"].get<double>(), t["s_to"].get<double>() - t["s_from"].get<double>(), 10.0);
    }
}

TEST(OddSampleRoute, SwitchesSignalsAndSummary) {
    const Converted& r = run();
    const auto& s = r.profile["summary"];
    EXPECT_EQ(s["switches"], r.truth["features"]["switches"].size());
    EXPECT_EQ(s["level_crossings_by_barrier"]["full"], 1);
    EXPECT_EQ(s["tunnels"]["count"], 1);
    EXPECT_EQ(s["bridges"]["count"], 1);
    int signals = 0;
    for (const auto& [category, n] : s["signals_by_category"].items()) {
        signals += n.get<int>();
    }
    EXPECT_EQ(signals, static_cast<int>(r.truth["features"]["signals"].size()));
    EXPECT_NEAR(s["length_km"].get<double>(), 10.19, 0.1);
    EXPECT_EQ(r.profile["unparsed"].size(), 0u);
}

// Only when asked for: otherwise odd_profile.json is where the elements are.
TEST(OddSampleRoute, TagsAreInTheMapUserDataWhenAskedFor) {
    EXPECT_EQ(run().xodr.find("code=\"odd\""), std::string::npos);
    const fs::path dir = scratch_dir();
    const auto c = run_command(std::string{RAILODD_BIN} + " sample -o " + quoted(dir / "in") + " && " +
                               std::string{RAILODD_BIN} + " convert " + quoted(dir / "in" / "sample_route.osm") +
                               " -o " + quoted(dir / "out") + " --no-timings --no-report --odd-user-data");
    ASSERT_EQ(c.exit_code, 0) << c.output;
    const std::string x = read_file(dir / "out" / "map.xodr");
    EXPECT_NE(x.find("<userData code=\"odd\" value=\"sc.geo.hz.curve s="), std::string::npos);
    EXPECT_NE(x.find("radius_class="), std::string::npos);
}

TEST(OddSampleRoute, RoadAlongsideTheStationIsAParallelRoad) {
    // The sample's village street (way 2000016) runs about 40 m from the main line.
    std::size_t found = 0;
    for (const auto& e : run().profile["elements"]) {
        if (e["odd_element"] != "Scenery/Surroundings/Parallel road") {
            continue;
        }
        const auto& ids = e["osm_ids"];
        if (std::find(ids.begin(), ids.end(), "way:2000016") != ids.end()) {
            ++found;
            EXPECT_NEAR(e["attributes"]["distance"].get<double>(), 40.0, 3.0);
            EXPECT_EQ(e["attributes"]["distance_class"], "nearby");
            EXPECT_EQ(e["attributes"]["road_class"], "residential");
        }
    }
    EXPECT_GT(found, 0u);
}
