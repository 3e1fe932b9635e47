// `railodd batch` and `railodd merge` on the embedded sample route: three
// routes (the whole sample, a bbox part, a missing input), the failed one
// reported without stopping the others, outputs independent of --jobs,
// up-to-date routes skipped, shards that partition the routes and merge back
// into the unsharded result, and refusals naming the file and line.
#include "test_support.hpp"

#include <nlohmann/json.hpp>

#include <map>
#include <set>

#include <unistd.h>

using namespace railodd::test;
using json = nlohmann::json;

namespace {

CommandResult run_railodd(const std::string& args) { return run_command(std::string{RAILODD_BIN} + " " + args); }

json read_json(const fs::path& p) { return json::parse(read_file(p)); }

class CliBatch : public ::testing::Test {
protected:
    // One folder per process: CTest runs each test in its own process, in parallel.
    static fs::path root() {
        return fs::temp_directory_path() / "railodd-tests" / ("CliBatch-" + std::to_string(::getpid()));
    }
    static fs::path routes() { return root() / "routes.yaml"; }

    static void SetUpTestSuite() {
        fs::remove_all(root());
        fs::create_directories(root());
        const auto s = run_railodd("sample -o " + quoted(root() / "sample"));
        ASSERT_EQ(s.exit_code, 0) << s.output;
        // Paths relative to the routes file; the bbox cuts the western half.
        write_file(routes(), "defaults:\n"
                             "  estimate_cant: true\n"
                             "  scenarios: {strategy: pairwise, count: 4}\n"
                             "routes:\n"
                             "  - id: whole\n"
                             "    input: sample/sample_route.osm\n"
                             "  - id: west\n"
                             "    input: sample/sample_route.osm\n"
                             "    bbox: [10.14, 48.29, 10.20, 48.31]\n"
                             "  - id: lost\n"
                             "    input: sample/no_such_route.osm\n"
                             "    scenarios: false\n");
    }
    static void TearDownTestSuite() { fs::remove_all(root()); }

    static CommandResult batch(const fs::path& out, const std::string& extra = "") {
        return run_railodd("batch " + quoted(routes()) + " -o " + quoted(out) + " " + extra);
    }
};

std::map<std::string, json> by_id(const json& summary) {
    std::map<std::string, json> out;
    for (const auto& r : summary["routes"]) {
        out[r["id"].get<std::string>()] = r;
    }
    return out;
}

// Every file under dir except logs and timings, with its content.
std::map<std::string, std::string> tree(const fs::path& dir) {
    std::map<std::string, std::string> out;
    for (const auto& e : fs::recursive_directory_iterator(dir)) {
        const std::string name = e.path().filename().string();
        if (e.is_regular_file() && e.path().extension() != ".log" && name.rfind("batch_timings", 0) != 0) {
            out[fs::relative(e.path(), dir).string()] = read_file(e.path());
        }
    }
    return out;
}

} // namespace

TEST_F(CliBatch, ConvertsRoutesReportsTheFailedOneAndSkipsUpToDateOnes) {
    const fs::path out = root() / "out";
    const auto r = batch(out, "--jobs 1");
    EXPECT_EQ(r.exit_code, 2) << r.output; // the missing input: the largest failed exit code
    for (const char* id : {"whole", "west"}) {
        EXPECT_TRUE(fs::is_regular_file(out / id / "map.xodr")) << id;
        EXPECT_TRUE(fs::is_regular_file(out / id / "odd_profile.json")) << id;
        EXPECT_TRUE(fs::is_regular_file(out / id / "scenarios" / "coverage.json")) << id;
        EXPECT_TRUE(fs::is_regular_file(out / id / ".railodd-batch-stamp.json")) << id;
    }
    // The part is smaller than the whole.
    EXPECT_LT(fs::file_size(out / "west" / "map.xodr"), fs::file_size(out / "whole" / "map.xodr"));
    const json s = read_json(out / "batch_summary.json");
    ASSERT_EQ(s["routes"].size(), 3u);
    EXPECT_EQ(s["routes"][0]["id"], "whole"); // file order
    EXPECT_EQ(s["routes"][2]["id"], "lost");
    auto routes = by_id(s);
    EXPECT_EQ(routes["whole"]["status"], "ok");
    EXPECT_EQ(routes["west"]["status"], "ok");
    EXPECT_EQ(routes["lost"]["status"], "failed");
    EXPECT_EQ(routes["lost"]["exit_code"], 2);
    EXPECT_NE(routes["lost"]["error"].get<std::string>().find("no_such_route.osm"), std::string::npos);
    EXPECT_NE(r.output.find("failed lost"), std::string::npos) << r.output; // a plain log line off a terminal
    const json t = read_json(out / "batch_timings.json");
    EXPECT_GT(t["routes"][0]["peak_rss_kb"].get<long>(), 1000);

    // Re-run: both good routes up to date; the failed one runs again.
    const std::string map_before = read_file(out / "whole" / "map.xodr");
    const auto again = batch(out, "--jobs 2");
    EXPECT_EQ(again.exit_code, 2) << again.output;
    routes = by_id(read_json(out / "batch_summary.json"));
    EXPECT_EQ(routes["whole"]["status"], "skipped");
    EXPECT_EQ(routes["west"]["status"], "skipped");
    EXPECT_EQ(routes["lost"]["status"], "failed");

    // --force reruns the up-to-date routes, to the same bytes.
    const auto forced = batch(out, "--jobs 2 --force");
    EXPECT_EQ(forced.exit_code, 2) << forced.output;
    routes = by_id(read_json(out / "batch_summary.json"));
    EXPECT_EQ(routes["whole"]["status"], "ok");
    EXPECT_EQ(routes["west"]["status"], "ok");
    EXPECT_EQ(read_file(out / "whole" / "map.xodr"), map_before);
}

// A route that runs too long is killed and reported; the others finish; a
// re-run resumes with only the unfinished route, whose folder held nothing
// that looked finished. The limit is the slow route's own `timeout:`, so the
// sample route is never raced against a clock (a sanitized build on a loaded
// machine converts it in seconds, not milliseconds).
TEST_F(CliBatch, ARouteOverItsTimeIsKilledAndTheRerunResumesIt) {
    const fs::path dir = root() / "timeout";
    fs::create_directories(dir);
    // A 50,000-node zig-zag way: about 5 s to convert in a release build, far more sanitized.
    std::string osm = "<?xml version=\"1.0\"?>\n<osm version=\"0.6\">\n";
    std::string way = "<way id=\"10\" version=\"1\">";
    for (int i = 1; i <= 50000; ++i) {
        osm += "<node id=\"" + std::to_string(i) + "\" version=\"1\" lat=\"" + (i % 2 ? "48.000018" : "48.0") +
               "\" lon=\"" + std::to_string(10.0 + i * 2e-5) + "\"/>\n";
        way += "<nd ref=\"" + std::to_string(i) + "\"/>";
    }
    write_file(dir / "slow.osm", osm + way + "<tag k=\"railway\" v=\"rail\"/></way>\n</osm>\n");
    const std::string whole = "  - id: whole\n    input: " + (root() / "sample" / "sample_route.osm").string() + "\n";
    write_file(dir / "routes.yaml", "routes:\n  - id: slow\n    input: slow.osm\n    timeout: 1\n" + whole);
    const fs::path out = dir / "out";
    const auto r = run_railodd("batch " + quoted(dir / "routes.yaml") + " -o " + quoted(out) + " --jobs 2");
    EXPECT_NE(r.exit_code, 0) << r.output;
    auto routes = by_id(read_json(out / "batch_summary.json"));
    EXPECT_EQ(routes["whole"]["status"], "ok");
    EXPECT_EQ(routes["slow"]["status"], "failed");
    EXPECT_NE(routes["slow"]["error"].get<std::string>().find("timed out"), std::string::npos) << routes["slow"];
    EXPECT_NE(routes["slow"]["error"].get<std::string>().find("timeout"), std::string::npos);
    EXPECT_FALSE(fs::exists(out / "slow" / "map.xodr"));
    EXPECT_FALSE(fs::exists(out / "slow" / ".railodd-batch-stamp.json"));
    // Resumed with the limit lifted: the finished route is skipped (a limit
    // does not change outputs), the killed one runs to the end.
    write_file(dir / "routes.yaml", "routes:\n  - id: slow\n    input: slow.osm\n" + whole);
    const auto again = run_railodd("batch " + quoted(dir / "routes.yaml") + " -o " + quoted(out) + " --jobs 2");
    EXPECT_EQ(again.exit_code, 0) << again.output;
    routes = by_id(read_json(out / "batch_summary.json"));
    EXPECT_EQ(routes["whole"]["status"], "skipped");
    EXPECT_EQ(routes["slow"]["status"], "ok");
    EXPECT_TRUE(fs::is_regular_file(out / "slow" / "map.xodr"));
    const auto bad = run_railodd("batch " + quoted(dir / "routes.yaml") + " -o " + quoted(out) + " --route-timeout -1");
    EXPECT_EQ(bad.exit_code, 1) << bad.output;
    EXPECT_NE(bad.output.find("--route-timeout"), std::string::npos) << bad.output;
    write_file(dir / "negative.yaml", "routes:\n  - id: slow\n    input: slow.osm\n    timeout: -1\n");
    const auto bad_key = run_railodd("batch " + quoted(dir / "negative.yaml") + " -o " + quoted(out));
    EXPECT_EQ(bad_key.exit_code, 2) << bad_key.output;
    EXPECT_NE(bad_key.output.find("timeout must be"), std::string::npos) << bad_key.output;
}

TEST_F(CliBatch, OutputsAreByteIdenticalWhateverTheJobs) {
    const auto one = batch(root() / "jobs1", "--jobs 1");
    const auto two = batch(root() / "jobs2", "--jobs 2");
    ASSERT_EQ(one.exit_code, 2) << one.output;
    ASSERT_EQ(two.exit_code, 2) << two.output;
    const auto a = tree(root() / "jobs1");
    const auto b = tree(root() / "jobs2");
    ASSERT_GT(a.size(), 20u);
    ASSERT_EQ(a.size(), b.size());
    for (const auto& [name, content] : a) {
        ASSERT_TRUE(b.contains(name)) << name;
        EXPECT_TRUE(b.at(name) == content) << name << " differs between --jobs 1 and --jobs 2";
    }
    EXPECT_TRUE(a.contains("batch_summary.json"));
    EXPECT_TRUE(a.contains("whole/.railodd-batch-stamp.json"));
}

TEST_F(CliBatch, ShardsPartitionTheRoutesAndMergeIntoTheUnshardedRun) {
    const fs::path whole = root() / "unsharded";
    const fs::path sharded = root() / "sharded";
    ASSERT_EQ(batch(whole, "--jobs 2").exit_code, 2);
    const auto s0 = batch(sharded, "--shard 0/2 --jobs 2");
    const auto s1 = batch(sharded, "--shard 1/2 --jobs 2");
    std::set<std::string> seen;
    std::size_t listed = 0;
    for (const char* name : {"batch_summary.shard-0-of-2.json", "batch_summary.shard-1-of-2.json"}) {
        const json s = read_json(sharded / name);
        for (const auto& r : s["routes"]) {
            seen.insert(r["id"].get<std::string>());
            ++listed;
        }
    }
    EXPECT_EQ(listed, 3u); // no route in both shards
    EXPECT_EQ(seen, (std::set<std::string>{"whole", "west", "lost"}));
    EXPECT_EQ(s0.exit_code, 2) << s0.output; // routes 0 and 2: whole, lost
    EXPECT_EQ(s1.exit_code, 0) << s1.output; // route 1: west

    const auto m = run_railodd("merge " + quoted(sharded));
    ASSERT_EQ(m.exit_code, 0) << m.output;
    const auto mu = run_railodd("merge " + quoted(whole) + " -o " + quoted(root() / "unsharded.json"));
    ASSERT_EQ(mu.exit_code, 0) << mu.output;
    json merged = read_json(sharded / "batch_merged.json");
    json reference = read_json(root() / "unsharded.json");
    EXPECT_EQ(merged["shards"]["missing"].size(), 0u);
    for (const char* key : {"routes", "counts", "coverage", "odd_profile"}) {
        EXPECT_EQ(merged[key], reference[key]) << key;
    }
    EXPECT_EQ(merged["routes"][0]["id"], "lost"); // sorted by id

    // Coverage: route items summed per (element, attribute, class) over the routes.
    std::map<std::string, long> on_route, scenarios;
    long total = 0;
    for (const char* id : {"whole", "west"}) {
        const json c = read_json(sharded / id / "scenarios" / "coverage.json");
        total += c["scenarios"].get<long>();
        for (const auto& e : c["route"]["elements"]) {
            const std::string k = e["element"].get<std::string>() + "|" + e["attribute"].get<std::string>() + "|" +
                                  e["class"].get<std::string>();
            on_route[k] += e["on_route"].get<long>();
            scenarios[k] += e["scenarios"].get<long>();
        }
    }
    const json& cov = merged["coverage"];
    EXPECT_EQ(cov["scenarios"].get<long>(), total);
    ASSERT_EQ(cov["route"]["elements"].size(), on_route.size());
    std::size_t gaps = 0;
    for (const auto& e : cov["route"]["elements"]) {
        const std::string k = e["element"].get<std::string>() + "|" + e["attribute"].get<std::string>() + "|" +
                              e["class"].get<std::string>();
        EXPECT_EQ(e["on_route"].get<long>(), on_route[k]) << k;
        EXPECT_EQ(e["scenarios"].get<long>(), scenarios[k]) << k;
        gaps += scenarios[k] == 0 ? 1 : 0;
    }
    EXPECT_EQ(cov["gaps"].size(), gaps);
    // ODD summaries: numbers summed.
    const double km = read_json(sharded / "whole" / "odd_profile.json")["summary"]["length_km"].get<double>() +
                      read_json(sharded / "west" / "odd_profile.json")["summary"]["length_km"].get<double>();
    EXPECT_NEAR(merged["odd_profile"]["summary"]["length_km"].get<double>(), km, 1e-6);

    // A summary of another routes file in the same root is refused by name.
    json stray = read_json(sharded / "batch_summary.shard-1-of-2.json");
    stray["routes_file_hash"] = "0000000000000000";
    write_file(sharded / "batch_summary.shard-1-of-2.json", stray.dump());
    const auto bad = run_railodd("merge " + quoted(sharded));
    EXPECT_EQ(bad.exit_code, 2) << bad.output;
    EXPECT_NE(bad.output.find("batch_summary.shard-1-of-2.json"), std::string::npos) << bad.output;
}

TEST_F(CliBatch, RefusesMalformedRoutesFilesAndShards) {
    const fs::path bad = write_file(root() / "bad.yaml", "routes:\n"
                                                         "  - id: a\n"
                                                         "    input: sample/sample_route.osm\n"
                                                         "    node_nose: 0.2\n");
    const auto r = run_railodd("batch " + quoted(bad) + " -o " + quoted(root() / "bad"));
    EXPECT_EQ(r.exit_code, 2) << r.output;
    EXPECT_NE(r.output.find("bad.yaml:4"), std::string::npos) << r.output;
    EXPECT_NE(r.output.find("node_nose"), std::string::npos) << r.output;
    EXPECT_FALSE(fs::exists(root() / "bad"));

    const fs::path dup = write_file(root() / "dup.yaml", "routes:\n"
                                                         "  - {id: a, input: x.osm}\n"
                                                         "  - {id: a, input: y.osm}\n");
    const auto d = run_railodd("batch " + quoted(dup) + " -o " + quoted(root() / "dup"));
    EXPECT_EQ(d.exit_code, 2) << d.output;
    EXPECT_NE(d.output.find("dup.yaml:3"), std::string::npos) << d.output;

    for (const char* shard : {"2/2", "1/0", "x"}) {
        const auto s = batch(root() / "shard", std::string{"--shard "} + shard);
        EXPECT_EQ(s.exit_code, 1) << shard << ": " << s.output;
    }
    const auto m = run_railodd("merge " + quoted(root()));
    EXPECT_EQ(m.exit_code, 2) << m.output; // no batch summary there
}
