// The HTML report's data document on the sample route, checked against the
// files it is made from and against independent readings of them: the map
// read back by xodr_check and projected by ingest's LocalProjection, the
// scenario coverage figures of `railodd scenarios`, the spec verdict of
// `railodd profile --json`. The page itself is checked in a real browser by
// tests/report/check_report.mjs.
#include "test_support.hpp"

#include "railodd/ingest/projection.hpp"
#include "railodd/odd/profile.hpp"
#include "railodd/report/report.hpp"
#include "railodd/xodr_check/map_lines.hpp"

#include <nlohmann/json.hpp>

#include <cmath>
#include <map>
#include <regex>
#include <set>

namespace {

using namespace railodd::test;
using ojson = nlohmann::ordered_json;

CommandResult run_railodd(const std::string& args) { return run_command(std::string{RAILODD_BIN} + " " + args); }

class ReportData : public ::testing::Test {
protected:
    static fs::path root() { return fs::temp_directory_path() / "railodd-tests" / ("ReportData-" + std::to_string(::getpid())); }
    static fs::path map_dir() { return root() / "map"; }
    static fs::path scen_dir() { return root() / "scen"; }
    static fs::path spec() { return fs::path{RAILODD_SOURCE_DIR} / "data" / "odd" / "example_odd_spec.yaml"; }
    static fs::path taxonomy() { return fs::path{RAILODD_SOURCE_DIR} / "data" / "odd" / "railway_odd.yaml"; }
    static void TearDownTestSuite() { fs::remove_all(root()); }
    static void SetUpTestSuite() {
        fs::remove_all(root());
        fs::create_directories(root());
        ASSERT_EQ(run_railodd("sample -o " + quoted(root() / "sample")).exit_code, 0);
        auto c = run_railodd("convert " + quoted(root() / "sample" / "sample_route.osm") + " -o " + quoted(map_dir()) +
                             " --dem " + quoted(root() / "sample" / "sample_route_dem.tif") +
                             " --node-noise 0.3 --estimate-cant --no-timings --debug-outputs");
        ASSERT_EQ(c.exit_code, 0) << c.output;
        c = run_railodd("scenarios --map " + quoted(map_dir()) + " -o " + quoted(scen_dir()) + " --odd-spec " +
                        quoted(spec()) + " --quiet");
        ASSERT_EQ(c.exit_code, 0) << c.output;
    }
    static ojson data() {
        railodd::report::ReportOptions o;
        o.map_dir = map_dir();
        o.scenario_dir = scen_dir();
        o.odd_spec = spec();
        o.taxonomy = taxonomy();
        return railodd::report::report_data(o);
    }
    static ojson read_json(const fs::path& p) { return ojson::parse(read_file(p)); }
};

// Delta-decoded integers: "pts" interleave lon and lat (stride 2), "z" is one series.
std::vector<long long> undelta(const ojson& a, std::size_t stride) {
    std::vector<long long> out;
    std::vector<long long> prev(stride, 0);
    for (std::size_t i = 0; i < a.size(); ++i) {
        prev[i % stride] += a[i].get<long long>();
        out.push_back(prev[i % stride]);
    }
    return out;
}

TEST_F(ReportData, RoadsAreTheMapsReferenceLinesOnTheEarth) {
    const ojson d = data();
    const auto map = railodd::xodr_check::read_map_lines(map_dir() / "map.xodr");
    const ojson report = read_json(map_dir() / "report.json");
    const auto& origin = report["projection"]["origin"];
    const railodd::ingest::LocalProjection proj({origin["lon"].get<double>(), origin["lat"].get<double>()});
    ASSERT_EQ(d["roads"].size(), map.roads.size());
    std::size_t rail = 0;
    for (std::size_t i = 0; i < map.roads.size(); ++i) {
        const auto& r = d["roads"][i];
        const auto& m = map.roads[i];
        EXPECT_EQ(r["id"], m.id);
        rail += r["rail"].get<bool>() ? 1 : 0;
        const auto pts = undelta(r["pts"], 2);
        ASSERT_EQ(pts.size() % 2, 0u);
        const std::size_t n = pts.size() / 2;
        // A road a hair over a multiple of 10 m (rounding) takes no extra sample.
        EXPECT_EQ(n, std::max<std::size_t>(2, static_cast<std::size_t>(std::ceil(m.length / 10.0 - 1e-9)) + 1)) << m.id;
        for (std::size_t j : {std::size_t{0}, n / 2, n - 1}) {
            const auto pose = m.pose(m.length * static_cast<double>(j) / static_cast<double>(n - 1));
            const auto ll = proj.inverse({pose.x, pose.y});
            EXPECT_NEAR(pts[2 * j] * 1e-6, ll.lon, 1.1e-6) << "road " << m.id << " vertex " << j;
            EXPECT_NEAR(pts[2 * j + 1] * 1e-6, ll.lat, 1.1e-6) << "road " << m.id << " vertex " << j;
        }
        // Elevation at both ends, in cm (none where the map has no profile).
        if (m.elevations.empty()) {
            EXPECT_TRUE(r["z"].is_null()) << m.id;
            continue;
        }
        const auto z = undelta(r["z"], 1);
        ASSERT_EQ(z.size(), n);
        EXPECT_NEAR(z.front() / 100.0, m.elevation(0.0), 0.006);
        EXPECT_NEAR(z.back() / 100.0, m.elevation(m.length), 0.006);
    }
    EXPECT_EQ(rail, report["opendrive"]["rail_roads"].get<std::size_t>());
}

TEST_F(ReportData, CurvatureDiagramHasEveryRecordsCurvatureAtItsJoints) {
    const ojson d = data();
    const auto map = railodd::xodr_check::read_map_lines(map_dir() / "map.xodr");
    std::size_t arcs = 0;
    for (std::size_t i = 0; i < map.roads.size(); ++i) {
        const auto& k = d["roads"][i]["k"];
        std::map<double, std::vector<double>> at; // s -> curvatures given there
        for (std::size_t j = 0; j + 1 < k.size(); j += 2) {
            at[k[j].get<double>()].push_back(k[j + 1].get<double>());
        }
        for (const auto& g : map.roads[i].geometries) {
            if (g.kind != railodd::xodr_check::GeometryKind::arc) {
                continue;
            }
            ++arcs;
            for (double s : {g.s, g.s + g.length}) {
                const auto it = at.find(std::round(s * 100) / 100);
                ASSERT_NE(it, at.end()) << "road " << map.roads[i].id << " s " << s;
                EXPECT_TRUE(std::any_of(it->second.begin(), it->second.end(),
                                        [&](double v) { return std::abs(v - g.curvature) < 1e-7; }))
                    << "road " << map.roads[i].id << " arc at s " << g.s << " curvature " << g.curvature;
            }
        }
    }
    EXPECT_GT(arcs, 5u);
}

TEST_F(ReportData, ElementsTracksAndChainsFollowTheProfile) {
    const ojson d = data();
    const auto profile = railodd::odd::read_profile(map_dir() / "odd_profile.json");
    ASSERT_EQ(d["elements"].size(), profile.elements.size());
    std::size_t crossings = 0, rows_crossings = 0;
    for (std::size_t i = 0; i < profile.elements.size(); ++i) {
        const auto& row = d["elements"][i];
        const auto& kind = d["kinds"][row[0].get<std::size_t>()];
        EXPECT_EQ(kind["id"], profile.elements[i].element_id);
        EXPECT_EQ(d["roads"][row[1].get<std::size_t>()]["id"], profile.elements[i].road_id);
        EXPECT_NEAR(row[2].get<double>(), profile.elements[i].s_start, 0.051);
        // The kind's attributes as known when the row was written: a prefix.
        EXPECT_LE(row[7].size(), kind["attrs"].size());
        for (std::size_t a = 0; a < row[7].size(); ++a) {
            const auto* v = profile.elements[i].find(kind["attrs"][a].get<std::string>());
            EXPECT_EQ(v == nullptr, row[7][a].is_null()) << "element " << i << " attribute " << kind["attrs"][a];
        }
        crossings += profile.elements[i].element_id == "sc.xing.level" ? 1 : 0;
        rows_crossings += kind["id"] == "sc.xing.level" ? 1 : 0;
    }
    EXPECT_EQ(rows_crossings, crossings);
    EXPECT_GE(crossings, 1u);
    // Every track is covered by its pieces, end to end.
    ASSERT_EQ(d["tracks"].size(), profile.tracks);
    for (const auto& t : d["tracks"]) {
        double covered = 0.0, last_end = 0.0;
        for (const auto& p : t["pieces"]) {
            EXPECT_NEAR(p[3].get<double>(), last_end, 0.02);
            EXPECT_NEAR(p[2].get<double>() - p[1].get<double>(), p[4].get<double>() - p[3].get<double>(), 0.05);
            covered += p[4].get<double>() - p[3].get<double>();
            last_end = p[4].get<double>();
        }
        EXPECT_NEAR(covered, t["length"].get<double>(), 0.05);
    }
    // The first chain is every track end to end: the route's length.
    EXPECT_NEAR(d["chains"][0]["length"].get<double>(), profile.length_m, 0.05);
    EXPECT_EQ(d["chains"][0]["parts"].size(), profile.tracks);
    // A joined chain runs through the switches: longer than any one track.
    ASSERT_GE(d["chains"].size(), 2u);
    double longest_track = 0.0;
    for (const auto& t : d["tracks"]) longest_track = std::max(longest_track, t["length"].get<double>());
    EXPECT_GT(d["chains"][1]["length"].get<double>(), longest_track + 1000.0);
}

TEST_F(ReportData, FitMeasuresTheMappedNodesAgainstTheFittedLine) {
    const ojson d = data();
    const auto& fit = d["fit"];
    ASSERT_TRUE(fit["available"].get<bool>());
    const ojson report = read_json(map_dir() / "report.json");
    // Every mapped track node (shared way-end nodes once) is measured.
    EXPECT_EQ(fit["nodes"].get<std::size_t>() + fit["nodes_far"].get<std::size_t>(),
              report["input"]["track_nodes"].get<std::size_t>());
    std::size_t hist = 0;
    for (const auto& c : fit["histogram"]["counts"]) hist += c.get<std::size_t>();
    EXPECT_EQ(hist, fit["nodes"].get<std::size_t>());
    EXPECT_EQ(fit["node_res"].size(), fit["nodes"].get<std::size_t>());
    // The sample's nodes scatter with sigma 0.3 m across the track: the
    // median distance of a normal scatter is 0.67 sigma.
    EXPECT_NEAR(fit["residual_p50_m"].get<double>(), 0.2, 0.07);
    EXPECT_LT(fit["residual_max_m"].get<double>(), 1.5);
    EXPECT_EQ(fit["tracks"].size(), report["geometry"]["tracks"].size());
    // Node curvature on the fitted roads, within the roads.
    const auto& nk = d["node_curvature"];
    ASSERT_GT(nk.size(), 30u);
    for (std::size_t i = 0; i + 2 < nk.size(); i += 3) {
        const auto& road = d["roads"][nk[i].get<std::size_t>()];
        EXPECT_TRUE(road["rail"].get<bool>());
        EXPECT_LE(nk[i + 1].get<double>(), road["length"].get<double>() + 0.01);
    }
}

TEST_F(ReportData, SpecAndScenarioFiguresAgreeWithTheirCommands) {
    const ojson d = data();
    const auto p = run_railodd("profile " + quoted(map_dir()) + " --odd-spec " + quoted(spec()) + " --json");
    ASSERT_EQ(p.exit_code, 5) << p.output; // the sample's industrial spur is outside
    const ojson verdict = ojson::parse(p.output)["odd_spec"];
    EXPECT_EQ(d["spec"]["passed"], false);
    EXPECT_EQ(d["spec"]["violations_total"].get<std::size_t>(), verdict["violations"].size());
    EXPECT_EQ(d["spec"]["elements_outside"], verdict["elements_outside"]);

    const ojson coverage = read_json(scen_dir() / "coverage.json");
    const ojson manifest = read_json(scen_dir() / "manifest.json");
    const auto& sc = d["scenarios"];
    EXPECT_EQ(sc["count"].get<std::size_t>(), manifest["scenarios"].size());
    EXPECT_EQ(sc["list"].size(), manifest["scenarios"].size());
    // The matrix's row sums are coverage.json's scenario counts per item.
    std::map<std::string, std::size_t> expected;
    for (const auto& e : coverage["route"]["elements"]) {
        expected[e["element"].get<std::string>() + "|" + e["attribute"].get<std::string>() + "|" +
                 e["class"].get<std::string>()] = e["scenarios"].get<std::size_t>();
    }
    const auto& m = sc["matrix"];
    ASSERT_EQ(m["counts"].size(), m["items"].size());
    std::size_t checked = 0;
    for (std::size_t i = 0; i < m["items"].size(); ++i) {
        const auto& it = m["items"][i];
        const auto key = it["element"].get<std::string>() + "|" + it["attribute"].get<std::string>() + "|" +
                         it["class"].get<std::string>();
        if (!expected.count(key)) {
            continue;
        }
        std::size_t sum = 0;
        for (const auto& c : m["counts"][i]) sum += c.get<std::size_t>();
        EXPECT_EQ(sum, expected[key]) << key;
        ++checked;
    }
    EXPECT_EQ(checked, expected.size());
    // Anchors are on roads of the map.
    for (const auto& s : sc["list"]) {
        EXPECT_GE(s["road"].get<long>(), 0) << s["id"];
    }
}

TEST_F(ReportData, PageInlinesEverythingAndEscapesTheData) {
    ojson d = data();
    d["meta"]["title"] = "</script><script>alert(1)</script> & <b>";
    const std::string page = railodd::report::render_html(d);
    EXPECT_EQ(page.find("@DATA@"), std::string::npos);
    EXPECT_EQ(page.find("@LEAFLET_JS@"), std::string::npos);
    EXPECT_EQ(page.find("alert(1)</script>"), std::string::npos); // neither in <title> nor in the data
    EXPECT_NE(page.find("<title>&lt;/script&gt;"), std::string::npos);
    // No reference to anything outside the page.
    EXPECT_EQ(page.find("sourceMappingURL=leaflet"), std::string::npos);
    EXPECT_FALSE(std::regex_search(page, std::regex(R"(<(script|link|img)[^>]+(src|href)=["']?https?:)")));
    // The data reads back as it was given.
    const std::string open = R"(<script type="application/json" id="railodd-data">)";
    const auto a = page.find(open) + open.size();
    const auto b = page.find("</script>", a);
    EXPECT_EQ(ojson::parse(page.substr(a, b - a)), d);
}

// The page convert writes from what it holds in memory (the map model, the
// ingested ways) says what `railodd report` reads back from the files.
TEST_F(ReportData, ConvertsPageFromMemoryAgreesWithTheFiles) {
    const std::string page = read_file(map_dir() / "report.html");
    const std::string open = R"(<script type="application/json" id="railodd-data">)";
    const auto a = page.find(open) + open.size();
    const ojson mem = ojson::parse(page.substr(a, page.find("</script>", a) - a));
    railodd::report::ReportOptions o;
    o.map_dir = map_dir();
    const ojson files = railodd::report::report_data(o);
    ASSERT_EQ(mem["roads"].size(), files["roads"].size());
    for (std::size_t i = 0; i < files["roads"].size(); ++i) {
        const auto& m = mem["roads"][i];
        const auto& f = files["roads"][i];
        EXPECT_EQ(m["id"], f["id"]);
        EXPECT_EQ(m["rail"], f["rail"]);
        EXPECT_EQ(m["osm"], f["osm"]);
        ASSERT_EQ(m["pts"].size(), f["pts"].size()) << f["id"];
        const auto mp = undelta(m["pts"], 2), fp = undelta(f["pts"], 2);
        for (std::size_t j = 0; j < mp.size(); ++j) {
            EXPECT_LE(std::abs(mp[j] - fp[j]), 1) << "road " << f["id"] << " value " << j; // 1e-6 degree
        }
        EXPECT_EQ(m["k"].size(), f["k"].size()) << f["id"];
    }
    EXPECT_EQ(mem["elements"], files["elements"]);
    EXPECT_EQ(mem["fit"]["nodes"], files["fit"]["nodes"]);
    EXPECT_EQ(mem["fit"]["histogram"], files["fit"]["histogram"]);
    EXPECT_EQ(mem["node_curvature"].size(), files["node_curvature"].size());
}

TEST_F(ReportData, CommandWritesTheSamePageTwiceAndRefusesBadInput) {
    const fs::path out = root() / "pages";
    const std::string args = "report " + quoted(map_dir()) + " --scenarios " + quoted(scen_dir()) + " -o ";
    ASSERT_EQ(run_railodd(args + quoted(out / "a.html")).exit_code, 0);
    ASSERT_EQ(run_railodd(args + quoted(out / "b.html")).exit_code, 0);
    EXPECT_EQ(read_file(out / "a.html"), read_file(out / "b.html"));
    // convert wrote the page too, from the same data (no scenarios).
    const std::string by_convert = read_file(map_dir() / "report.html");
    EXPECT_NE(by_convert.find(R"("format":"railodd_report_data")"), std::string::npos);

    const fs::path empty = root() / "empty";
    fs::create_directories(empty);
    auto r = run_railodd("report " + quoted(empty) + " -o " + quoted(out / "c.html"));
    EXPECT_EQ(r.exit_code, 2) << r.output;
    EXPECT_NE(r.output.find("odd_profile.json"), std::string::npos) << r.output;
    EXPECT_FALSE(fs::exists(out / "c.html"));
    r = run_railodd("report " + quoted(map_dir()) + " --tiles ftp://x -o " + quoted(out / "c.html"));
    EXPECT_EQ(r.exit_code, 1) << r.output;
    EXPECT_NE(r.output.find("--tiles"), std::string::npos) << r.output;
    r = run_railodd("report " + quoted(map_dir()) + " --scenarios " + quoted(empty) + " -o " + quoted(out / "c.html"));
    EXPECT_EQ(r.exit_code, 2) << r.output;
    EXPECT_NE(r.output.find("coverage.json"), std::string::npos) << r.output;
    EXPECT_FALSE(fs::exists(out / "c.html"));
}

} // namespace
