// Degenerate geometry and data through the real executable (issue 22): each
// track converts, or is dropped with a reason in report.json, or the run is
// refused naming the file and the problem; the map then validates.
#include "test_support.hpp"

#include <nlohmann/json.hpp>

#include <cmath>
#include <map>
#include <sstream>
#include <vector>

using namespace railodd::test;

namespace {

CommandResult run_railodd(const std::string& args) { return run_command(std::string{RAILODD_BIN} + " " + args); }

struct Node {
    long long id;
    double lat, lon;
};

struct WaySpec {
    long long id;
    std::vector<long long> refs;
};

std::string osm_xml(const std::vector<Node>& nodes, const std::vector<WaySpec>& ways) {
    std::ostringstream s;
    s.precision(10);
    s << "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n<osm version=\"0.6\" generator=\"test\">\n";
    for (const auto& n : nodes) {
        s << "<node id=\"" << n.id << "\" version=\"1\" lat=\"" << n.lat << "\" lon=\"" << n.lon << "\"/>\n";
    }
    for (const auto& w : ways) {
        s << "<way id=\"" << w.id << "\" version=\"1\">";
        for (long long r : w.refs) s << "<nd ref=\"" << r << "\"/>";
        s << "<tag k=\"railway\" v=\"rail\"/></way>\n";
    }
    s << "</osm>\n";
    return s.str();
}

// A straight track of n nodes 50 m apart heading east from (lat, lon), ids from `first`.
std::vector<Node> straight(long long first, int n, double lat, double lon) {
    std::vector<Node> out;
    const double dlon = 50.0 / (111320.0 * std::cos(lat * M_PI / 180.0));
    for (int i = 0; i < n; ++i) {
        double l = lon + i * dlon;
        if (l > 180.0) l -= 360.0;
        out.push_back({first + i, lat, l});
    }
    return out;
}

std::vector<long long> ids(const std::vector<Node>& nodes) {
    std::vector<long long> out;
    for (const auto& n : nodes) out.push_back(n.id);
    return out;
}

struct Converted {
    CommandResult run;
    nlohmann::json report;
    CommandResult validate;
};

Converted convert(const fs::path& dir, const std::string& xml) {
    write_file(dir / "in.osm", xml);
    Converted c;
    c.run = run_railodd("convert " + quoted(dir / "in.osm") + " -o " + quoted(dir / "out") + " --no-timings --no-report");
    if (c.run.exit_code == 0) {
        c.report = nlohmann::json::parse(read_file(dir / "out" / "report.json"));
        c.validate = run_railodd("validate " + quoted(dir / "out" / "map.xodr"));
    }
    return c;
}

// Every input track is in the map or listed with a reason.
void expect_accounted(const nlohmann::json& report) {
    std::size_t dropped = 0;
    for (const auto& d : report["dropped"]) dropped += d["kind"] == "track" ? 1 : 0;
    EXPECT_EQ(report["output"]["track_ways"].get<std::size_t>() + dropped, report["input"]["track_ways"].get<std::size_t>());
}

TEST(CliDegenerateInput, AMillimetreTrackBesideARealOneIsDroppedWithAReason) {
    const fs::path dir = scratch_dir();
    auto nodes = straight(1, 20, 48.0, 10.0);
    nodes.push_back({100, 48.01, 10.0});
    nodes.push_back({101, 48.01, 10.0 + 1.4e-8}); // 1 mm east
    const auto c = convert(dir, osm_xml(nodes, {{10, ids(straight(1, 20, 48.0, 10.0))}, {11, {100, 101}}}));
    ASSERT_EQ(c.run.exit_code, 0) << c.run.output;
    expect_accounted(c.report);
    const std::string all = c.report["dropped"].dump() + c.report["opendrive"]["tracks_not_written"].dump();
    EXPECT_NE(all.find("11"), std::string::npos) << all; // way 11 is listed, with its reason
    EXPECT_EQ(c.validate.exit_code, 0) << c.validate.output;
}

TEST(CliDegenerateInput, OnlyAMillimetreTrackIsRefusedNamingTheProblem) {
    const fs::path dir = scratch_dir();
    const auto c = convert(dir, osm_xml({{1, 48.0, 10.0}, {2, 48.0, 10.0 + 1.4e-8}}, {{10, {1, 2}}}));
    EXPECT_EQ(c.run.exit_code, 2) << c.run.output;
    EXPECT_NE(c.run.output.find("in.osm"), std::string::npos) << c.run.output;
    EXPECT_NE(c.run.output.find("no track could be written"), std::string::npos) << c.run.output;
    EXPECT_FALSE(fs::exists(dir / "out" / "map.xodr"));
}

TEST(CliDegenerateInput, AWayMappedTwiceIsDroppedAsADuplicate) {
    const fs::path dir = scratch_dir();
    const auto nodes = straight(1, 20, 48.0, 10.0);
    auto reversed = ids(nodes);
    std::reverse(reversed.begin(), reversed.end());
    const auto c = convert(dir, osm_xml(nodes, {{10, ids(nodes)}, {11, ids(nodes)}, {12, reversed}}));
    ASSERT_EQ(c.run.exit_code, 0) << c.run.output;
    expect_accounted(c.report);
    std::map<long long, std::string> reasons;
    for (const auto& d : c.report["dropped"]) reasons[d["osm_id"].get<long long>()] = d["reason"];
    ASSERT_EQ(reasons.size(), 2u) << c.report["dropped"].dump();
    EXPECT_NE(reasons[11].find("way 10"), std::string::npos) << reasons[11];
    EXPECT_NE(reasons[12].find("way 10"), std::string::npos) << reasons[12];
    EXPECT_EQ(c.report["opendrive"]["rail_roads"], 1);
    EXPECT_EQ(c.validate.exit_code, 0) << c.validate.output;
}

TEST(CliDegenerateInput, ASelfIntersectingLoopConverts) {
    const fs::path dir = scratch_dir();
    std::vector<Node> nodes;
    for (int i = 0; i < 60; ++i) { // a figure eight, 1.5 km across
        const double t = 2 * M_PI * i / 60;
        nodes.push_back({i + 1, 48.0 + 0.005 * std::sin(2 * t), 10.0 + 0.01 * std::sin(t)});
    }
    auto refs = ids(nodes);
    refs.push_back(1);
    const auto c = convert(dir, osm_xml(nodes, {{10, refs}}));
    ASSERT_EQ(c.run.exit_code, 0) << c.run.output;
    expect_accounted(c.report);
    EXPECT_GE(c.report["opendrive"]["rail_roads"].get<int>(), 1);
    EXPECT_EQ(c.validate.exit_code, 0) << c.validate.output;
}

TEST(CliDegenerateInput, ATrackAcrossTheAntimeridianConverts) {
    const fs::path dir = scratch_dir();
    const auto nodes = straight(1, 40, 65.0, 179.98); // 2 km, across 180 degrees
    const auto c = convert(dir, osm_xml(nodes, {{10, ids(nodes)}}));
    ASSERT_EQ(c.run.exit_code, 0) << c.run.output;
    EXPECT_EQ(c.report["opendrive"]["rail_roads"], 1);
    EXPECT_NEAR(std::abs(c.report["projection"]["origin"]["lon"].get<double>()), 180.0, 0.05);
    EXPECT_EQ(c.validate.exit_code, 0) << c.validate.output;
}

TEST(CliDegenerateInput, ATrackNearThePoleConverts) {
    const fs::path dir = scratch_dir();
    const auto nodes = straight(1, 30, 89.9, 10.0);
    const auto c = convert(dir, osm_xml(nodes, {{10, ids(nodes)}}));
    ASSERT_EQ(c.run.exit_code, 0) << c.run.output;
    EXPECT_EQ(c.report["opendrive"]["rail_roads"], 1);
    EXPECT_EQ(c.validate.exit_code, 0) << c.validate.output;
}

TEST(CliDegenerateInput, ANodeIdMetTwiceKeepsTheFirstAndSaysSo) {
    const fs::path dir = scratch_dir();
    auto nodes = straight(1, 20, 48.0, 10.0);
    nodes.push_back({5, 48.1, 10.0}); // id 5 again, 11 km away
    std::vector<long long> refs;
    for (int i = 1; i <= 20; ++i) refs.push_back(i);
    const auto c = convert(dir, osm_xml(nodes, {{10, refs}}));
    ASSERT_EQ(c.run.exit_code, 0) << c.run.output;
    EXPECT_NE(c.report["repairs"].dump().find("first location kept"), std::string::npos) << c.report["repairs"].dump();
    EXPECT_EQ(c.report["input"]["duplicate_nodes"], 1);
    // Said on stderr too, the id named (issue 40).
    EXPECT_NE(c.run.output.find("warning: " + (dir / "in.osm").string() + ": 1 node id occurs again at another location (5)"),
              std::string::npos)
        << c.run.output;
    EXPECT_EQ(c.validate.exit_code, 0) << c.validate.output;
}

TEST(CliDegenerateInput, ANodeIdMetTwiceIsRefusedWithStrict) {
    const fs::path dir = scratch_dir();
    auto nodes = straight(1, 20, 48.0, 10.0);
    nodes.push_back({5, 48.1, 10.0});
    nodes.push_back({7, 48.2, 10.0});
    std::vector<long long> refs;
    for (int i = 1; i <= 20; ++i) refs.push_back(i);
    write_file(dir / "in.osm", osm_xml(nodes, {{10, refs}}));
    const auto r = run_railodd("convert " + quoted(dir / "in.osm") + " -o " + quoted(dir / "out") + " --strict");
    EXPECT_EQ(r.exit_code, 2) << r.output;
    EXPECT_NE(r.output.find((dir / "in.osm").string()), std::string::npos) << r.output;
    EXPECT_NE(r.output.find("2 node ids occur again at another location (5, 7)"), std::string::npos) << r.output;
    EXPECT_FALSE(fs::exists(dir / "out" / "map.xodr"));
}

TEST(CliDegenerateInput, AFiftyThousandNodeZigZagConverts) {
    const fs::path dir = scratch_dir();
    std::vector<Node> nodes;
    std::vector<long long> refs;
    for (int i = 0; i < 50000; ++i) { // 1.5 m steps, 2 m across
        nodes.push_back({i + 1, 48.0 + (i % 2 ? 1.8e-5 : 0.0), 10.0 + i * 2.0e-5});
        refs.push_back(i + 1);
    }
    const auto c = convert(dir, osm_xml(nodes, {{10, refs}}));
    ASSERT_EQ(c.run.exit_code, 0) << c.run.output;
    expect_accounted(c.report);
    EXPECT_EQ(c.validate.exit_code, 0) << c.validate.output;
}

} // namespace
