// The maps of every shared real extract, through the three checks of the
// OpenDRIVE issue: the ASAM XSD of the map's revision, SUMO netconvert's import
// (its rail edges one for one with our rail roads outside junctions) and the
// independent geometry / link check of `railodd validate`; and the map carries
// the switches, stations and level crossings the data maps.
#include "test_support.hpp"

#include <nlohmann/json.hpp>

#include <iostream>

using namespace railodd::test;

namespace {

struct Case {
    const char* file;
    const char* revision;
};

class XodrSharedMaps : public ::testing::TestWithParam<Case> {};

CommandResult run_railodd(const std::string& args) { return run_command(std::string{RAILODD_BIN} + " " + args); }

bool have(const char* tool) { return run_command(std::string{"command -v "} + tool).exit_code == 0; }

} // namespace

TEST_P(XodrSharedMaps, ValidatesImportsAndCarriesTheMappedFeatures) {
    RAILODD_REQUIRE_SHARED_DATA();
    if (!have("xmllint") || !have("netconvert")) {
        GTEST_SKIP() << "xmllint or netconvert missing (scripts/install-deps.sh installs them)";
    }
    const Case c = GetParam();
    const fs::path out = scratch_dir() / (std::string{c.file} + "-" + c.revision);
    const auto conv = run_railodd("convert " + quoted(shared_data() / "osm" / c.file) + " -o " + quoted(out) +
                              " --no-timings --debug-outputs --odr-version " + c.revision);
    ASSERT_EQ(conv.exit_code, 0) << conv.output;
    const auto val = run_railodd("validate " + quoted(out / "map.xodr") + " --xsd-dir " +
                             quoted(fs::canonical(shared_data() / "schemas")) + " --netconvert --json");
    const auto v = nlohmann::json::parse(val.output.substr(val.output.find('{')));
    EXPECT_EQ(val.exit_code, 0) << v["findings"].dump(1).substr(0, 3000);
    EXPECT_TRUE(v["schema"]["valid"].get<bool>()) << v["schema"].dump(1);
    EXPECT_TRUE(v["netconvert"]["passed"].get<bool>()) << v["netconvert"].dump(1);
    // No plan-view record under 1 cm (readers divide by its length).
    EXPECT_EQ(v["summary"]["short_records"].get<int>(), 0) << v["summary"]["shortest_record"].dump();

    const auto report = nlohmann::json::parse(read_file(out / "report.json"));
    // Every branch leaves its switch G2, as the network's fit built it (the
    // map's links above check the roads; a branch's first road can follow
    // its own fit into the junction).
    const auto& links = report["geometry"]["summary"]["links"];
    EXPECT_LT(links["max_gap_m"].get<double>(), 1e-3);
    EXPECT_LT(links["max_heading_jump_rad"].get<double>(), 1e-4);
    EXPECT_LT(links["max_curvature_jump"].get<double>(), 1e-6);
    const auto& odr = report["opendrive"];
    const auto& topo = report["topology"];
    // netconvert makes one normal edge per road outside junctions (connecting
    // roads become its internal lanes).
    const int rail_outside = odr["rail_roads"].get<int>() - odr["rail_connecting_roads"].get<int>();
    EXPECT_EQ(v["netconvert"]["rail_edges"].get<int>(), rail_outside);
    // What the data maps is on the map.
    EXPECT_EQ(odr["level_crossings"], topo["road_rail_crossings"]["at_grade"]);
    const auto& attached = topo["features_attached"];
    const int mapped_stations = attached.value("station", 0) + attached.value("halt", 0);
    EXPECT_GE(odr["stations"].get<int>(), mapped_stations);
    EXPECT_EQ(odr["tracks_not_written"].size(), 0u);
    const int switches = odr["rail"]["switches"], vertices = odr["rail"]["switch_vertices"];
    EXPECT_GE(switches * 10, vertices * 9) << "at least 90 % of the switch vertices become <switch>";
    // The ODD profile tags what the data maps: every switch vertex, every
    // crossing at grade, every attached station and halt, every tunnel and
    // bridge way of the tracks.
    const auto profile = nlohmann::json::parse(read_file(out / "odd_profile.json"));
    const auto& summary = profile["summary"];
    EXPECT_EQ(summary["switches"].get<int>(), vertices);
    int level_crossings = summary["footpath_crossings"].get<int>();
    for (const auto& [barrier, n] : summary["level_crossings_by_barrier"].items()) {
        level_crossings += n.get<int>();
    }
    EXPECT_EQ(level_crossings, topo["road_rail_crossings"]["at_grade"].get<int>());
    EXPECT_EQ(summary["stations"].get<int>() + summary["halts"].get<int>(), mapped_stations);
    std::size_t tunnels = 0, bridges = 0;
    const auto ingest = nlohmann::json::parse(read_file(out / "ingest.geojson"));
    for (const auto& f : ingest["features"]) {
        const auto& p = f["properties"];
        if (p["layer"] != "track") {
            continue;
        }
        const std::string tunnel = p["tags"].value("tunnel", "no"), bridge = p["tags"].value("bridge", "no");
        tunnels += tunnel != "no" ? 1 : 0;
        bridges += tunnel == "no" && bridge != "no" ? 1 : 0;
    }
    EXPECT_EQ(profile["summary"]["tunnels"]["count"].get<std::size_t>(), tunnels);
    EXPECT_EQ(profile["summary"]["bridges"]["count"].get<std::size_t>(), bridges);
    std::cout << c.file << " (" << c.revision << "): " << odr["rail_roads"] << " rail roads, " << switches << " of "
              << vertices << " switches, " << odr["stations"] << " stations, " << odr["level_crossings"]
              << " level crossings, " << odr["track_ends_not_linked"].size() << " unlinked track ends; netconvert "
              << v["netconvert"]["rail_edges"] << " rail edges\n";
}

INSTANTIATE_TEST_SUITE_P(
    Extracts, XodrSharedMaps,
    ::testing::Values(Case{"gh_harsdorf.osm.pbf", "1.7"}, Case{"gh_harsdorf.osm.pbf", "1.6"},
                      Case{"gh_harsdorf.osm.pbf", "1.8"}, Case{"valhalla_liechtenstein-latest.osm.pbf", "1.7"},
                      Case{"valhalla_liechtenstein-latest.osm.pbf", "1.8"}, Case{"gh_north-bayreuth.osm.gz", "1.7"},
                      Case{"gh_lauf-200115.osm.pbf", "1.7"}, Case{"gh_krems.osm.gz", "1.7"},
                      Case{"most_monaco_network_ele.osm", "1.7"}, Case{"osrm_monaco.osm.pbf", "1.7"},
                      Case{"valhalla_munchen.osm.pbf", "1.7"}, Case{"orr_vde8.2-rail.osm.pbf", "1.7"},
                      Case{"orr_cologne-railway.osm.pbf", "1.7"}),
    [](const ::testing::TestParamInfo<Case>& info) {
        std::string n = std::string{info.param.file} + "_" + info.param.revision;
        for (char& ch : n) {
            ch = std::isalnum(static_cast<unsigned char>(ch)) ? ch : '_';
        }
        return n;
    });

// The embedded sample route (made by railodd itself) in every revision.
class XodrSampleRouteMap : public ::testing::TestWithParam<const char*> {};

TEST_P(XodrSampleRouteMap, ValidatesAndImports) {
    RAILODD_REQUIRE_SHARED_DATA(); // the ASAM schemas
    if (!have("xmllint") || !have("netconvert")) {
        GTEST_SKIP() << "xmllint or netconvert missing (scripts/install-deps.sh installs them)";
    }
    const fs::path dir = scratch_dir() / (std::string{"sample-"} + GetParam());
    ASSERT_EQ(run_railodd("sample -o " + quoted(dir / "in")).exit_code, 0);
    const auto conv = run_railodd("convert " + quoted(dir / "in" / "sample_route.osm") + " --dem " +
                                  quoted(dir / "in" / "sample_route_dem.tif") + " -o " + quoted(dir / "out") +
                                  " --no-timings --estimate-cant --odr-version " + GetParam());
    ASSERT_EQ(conv.exit_code, 0) << conv.output;
    const auto val = run_railodd("validate " + quoted(dir / "out" / "map.xodr") + " --xsd-dir " +
                                 quoted(fs::canonical(shared_data() / "schemas")) + " --netconvert --json");
    const auto v = nlohmann::json::parse(val.output.substr(val.output.find('{')));
    EXPECT_EQ(val.exit_code, 0) << val.output.substr(0, 3000);
    EXPECT_EQ(v["summary"]["switches"], 3);
    EXPECT_EQ(v["summary"]["short_records"].get<int>(), 0) << v["summary"]["shortest_record"].dump();
    EXPECT_EQ(v["summary"]["stations"], 2);
    const auto report = nlohmann::json::parse(read_file(dir / "out" / "report.json"));
    EXPECT_EQ(report["opendrive"]["level_crossings"], 1);
    EXPECT_EQ(report["opendrive"]["tunnels_and_bridges"], 2);
    EXPECT_EQ(v["netconvert"]["rail_edges"].get<int>(),
              report["opendrive"]["rail_roads"].get<int>() - report["opendrive"]["rail_connecting_roads"].get<int>());
}

INSTANTIATE_TEST_SUITE_P(Revisions, XodrSampleRouteMap, ::testing::Values("1.6", "1.7", "1.8"),
                         [](const ::testing::TestParamInfo<const char*>& info) {
                             return std::string{"v"} + (info.param[2] == '6' ? "16" : info.param[2] == '7' ? "17" : "18");
                         });
