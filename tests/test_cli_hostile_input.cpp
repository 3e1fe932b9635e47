// Hostile input, as a user can pass it, through the real executable: each row
// is a file or option that once crashed railodd, escaped the output folder,
// ran without bound or reported bad input as an internal error (exit 4). The
// rule each row checks: exit 1 (usage) or 2 (input) with a message naming the
// file and the problem, and nothing written where it must not be.
#include "pbf_test_support.hpp"
#include "test_support.hpp"

#include <nlohmann/json.hpp>

#include <chrono>
#include <functional>
#include <string_view>
#include <vector>

#include <unistd.h>

using namespace railodd::test;
using namespace std::string_literals;

namespace {

CommandResult run_railodd(const std::string& args) { return run_command(std::string{RAILODD_BIN} + " " + args); }

const fs::path data_dir = fs::path{RAILODD_SOURCE_DIR} / "data";

class CliHostileInput : public ::testing::Test {
protected:
    // One folder per process: CTest runs each test in its own process.
    static fs::path root() {
        return fs::temp_directory_path() / "railodd-tests" / ("CliHostileInput-" + std::to_string(::getpid()));
    }
    static fs::path map() { return root() / "map"; }

    static void SetUpTestSuite() {
        fs::remove_all(root());
        fs::create_directories(root());
        const auto s = run_railodd("sample -o " + quoted(root() / "sample"));
        ASSERT_EQ(s.exit_code, 0) << s.output;
        const auto c = run_railodd("convert " + quoted(root() / "sample" / "sample_route.osm") + " -o " + quoted(map()));
        ASSERT_EQ(c.exit_code, 0) << c.output;
    }
    static void TearDownTestSuite() { fs::remove_all(root()); }

    // The shipped templates with the first id replaced.
    static std::string templates_with_id(const std::string& id) {
        std::string t = read_file(data_dir / "scenario" / "templates.yaml");
        const std::string first = "- id: curve_crossing_street_vehicle";
        const auto at = t.find(first);
        EXPECT_NE(at, std::string::npos);
        return t.replace(at, first.size(), "- id: " + id);
    }
};

struct Expect {
    int exit_code;
    std::vector<std::string> says; // each in the output
};

void expect_refusal(const CommandResult& r, const Expect& e) {
    EXPECT_EQ(r.exit_code, e.exit_code) << r.output;
    for (const auto& s : e.says) {
        EXPECT_NE(r.output.find(s), std::string::npos) << "missing '" << s << "' in: " << r.output;
    }
    EXPECT_EQ(r.output.find("internal error"), std::string::npos) << r.output;
}

// Files of the folder, recursively, as relative paths.
std::vector<std::string> listing(const fs::path& dir) {
    std::vector<std::string> out;
    if (!fs::exists(dir)) {
        return out;
    }
    for (const auto& e : fs::recursive_directory_iterator(dir)) {
        out.push_back(fs::relative(e.path(), dir).string());
    }
    std::sort(out.begin(), out.end());
    return out;
}

} // namespace

// --- 1. bytes libosmium would walk past -----------------------------------

TEST_F(CliHostileInput, PbfWithNulInATagKeyIsRefusedNamingTheWay) {
    PbfBuilder b;
    b.nodes = {{1, 10.0, 48.0, {}}, {2, 10.002, 48.0, {}}, {3, 10.004, 48.0, {}}};
    b.ways = {{77, {{"railway", "rail"}, {"na\0me"s, "x"}}, {1, 2, 3}}};
    const auto dir = scratch_dir();
    b.write(dir / "nul.osm.pbf");
    const auto r = run_railodd("convert " + quoted(dir / "nul.osm.pbf") + " -o " + quoted(dir / "out"));
    expect_refusal(r, {2, {"nul.osm.pbf", "OSM way 77", "NUL byte"}});
    EXPECT_FALSE(fs::exists(dir / "out" / "map.xodr"));
}

TEST_F(CliHostileInput, PbfWithNulInADenseNodeValueIsRefusedNamingTheNode) {
    PbfBuilder b;
    b.nodes = {{1, 10.0, 48.0, {}}, {2, 10.002, 48.0, {{"railway", "sig\0nal"s}}}, {3, 10.004, 48.0, {}}};
    b.ways = {{77, {{"railway", "rail"}}, {1, 2, 3}}};
    const auto dir = scratch_dir();
    b.write(dir / "nul.osm.pbf");
    const auto r = run_railodd("convert " + quoted(dir / "nul.osm.pbf") + " -o " + quoted(dir / "out"));
    expect_refusal(r, {2, {"nul.osm.pbf", "OSM node 2", "tag value holds a NUL byte"}});
}

// --- 2. names that become file names ---------------------------------------

TEST_F(CliHostileInput, TemplateIdThatIsAnAbsolutePathIsRefused) {
    const auto dir = scratch_dir();
    const fs::path target = dir / "elsewhere" / "pwned";
    const auto templates = write_file(dir / "t.yaml", templates_with_id(target.string()));
    const auto r = run_railodd("scenarios --map " + quoted(map()) + " -o " + quoted(dir / "scen") + " --templates " +
                               quoted(templates));
    expect_refusal(r, {2, {templates.string() + ":", "template id", "cannot be used in a file name"}});
    EXPECT_TRUE(listing(dir / "elsewhere").empty());
    EXPECT_FALSE(fs::exists(dir / "scen" / "manifest.json"));
}

TEST_F(CliHostileInput, TemplateIdWithDotDotIsRefused) {
    const auto dir = scratch_dir();
    for (const std::string& id : std::vector<std::string>{"../dotdot", "..", ".", ".hidden", "a/b", "-option", std::string(101, 'x')}) {
        const auto templates = write_file(dir / "t.yaml", templates_with_id("'" + id + "'"));
        const auto r = run_railodd("scenarios --map " + quoted(map()) + " -o " + quoted(dir / "scen" / "inner") +
                                   " --templates " + quoted(templates));
        SCOPED_TRACE(id);
        expect_refusal(r, {2, {"t.yaml:", "cannot be used in a file name"}});
    }
    EXPECT_EQ(listing(dir), (std::vector<std::string>{"t.yaml"})) << "refused before any output folder is made";
}

TEST_F(CliHostileInput, AssetIdWithSlashIsRefused) {
    const auto dir = scratch_dir();
    std::string assets = read_file(data_dir / "scenario" / "assets.yaml");
    assets.replace(assets.find("- id: regional_emu"), 18, "- id: ../regional_emu");
    const auto catalog = write_file(dir / "assets.yaml", assets);
    const auto r =
        run_railodd("scenarios --map " + quoted(map()) + " -o " + quoted(dir / "scen") + " --catalog " + quoted(catalog));
    expect_refusal(r, {2, {catalog.string() + ":", "asset id '../regional_emu'"}});
}

TEST_F(CliHostileInput, MergedRouteIdThatLeavesTheFolderIsRefused) {
    const auto dir = scratch_dir();
    write_file(dir / "batch_summary.json",
               R"({"railodd": {"format": "batch_summary", "format_version": 1}, "routes_file": "r.yaml",
                   "routes_file_hash": "0", "routes_total": 1, "shard": {"index": 0, "count": 1},
                   "routes": [{"id": "../../etc", "status": "ok", "scenarios": false}]})");
    expect_refusal(run_railodd("merge " + quoted(dir)), {2, {"batch_summary.json", "route id '../../etc'"}});
}

// --- 3. unbounded runs -------------------------------------------------------

TEST_F(CliHostileInput, RandomCountAboveTheLimitIsAUsageError) {
    const auto dir = scratch_dir();
    const auto r = run_railodd("scenarios --map " + quoted(map()) + " -o " + quoted(dir / "scen") +
                               " --strategy random --count 2147483647");
    expect_refusal(r, {1, {"--count", "100000"}});
    EXPECT_FALSE(fs::exists(dir / "scen"));
}

// One anchor per template: the cap is on parameter rows, and every anchor
// of the sample route wrote 44,478 files (62 s, 330 s under the sanitizers).
TEST_F(CliHostileInput, RandomCountAboveTheFeasibleRowsIsCappedAndSaysSo) {
    const auto dir = scratch_dir();
    const auto r = run_railodd("scenarios --map " + quoted(map()) + " -o " + quoted(dir / "scen") +
                               " --strategy random --count 100000 --seed 3 --max-anchors 1 -q");
    ASSERT_EQ(r.exit_code, 0) << r.output;
    EXPECT_NE(r.output.find("distinct valid parameter rows exist, fewer than --count 100000"), std::string::npos)
        << r.output;
    const auto manifest = nlohmann::json::parse(read_file(dir / "scen" / "manifest.json"));
    std::size_t capped = 0;
    for (const auto& t : manifest["templates"]) {
        EXPECT_LT(t["scenarios"].get<std::size_t>(), 100000u);
        capped += t.value("all_valid_rows", false) ? 1 : 0;
    }
    EXPECT_GT(capped, 0u);
}

// --- 4. input errors, not internal ones --------------------------------------

TEST_F(CliHostileInput, DirectoryWhereAFileIsExpected) {
    const auto dir = scratch_dir();
    const fs::path d = dir / "a_folder";
    fs::create_directories(d);
    const std::string scen = "scenarios --map " + quoted(map()) + " -o " + quoted(dir / "scen");
    const std::vector<std::pair<std::string, std::string>> cases = {
        {scen + " --catalog " + quoted(d), "is a directory, not a file (asset catalog)"},
        {scen + " --templates " + quoted(d), "is a directory, not a file (template file)"},
        {scen + " --odd-spec " + quoted(d), "is a directory, not a file (ODD spec)"},
        {scen + " --taxonomy " + quoted(d), "is a directory, not a file (ODD taxonomy)"},
        {"profile " + quoted(map()) + " --odd-spec " + quoted(d), "is a directory, not a file (ODD spec)"},
        {"convert " + quoted(root() / "sample" / "sample_route.osm") + " -o " + quoted(dir / "out") + " --polygon " +
             quoted(d),
         "is a directory, not a file (polygon file)"},
        {"batch " + quoted(d) + " -o " + quoted(dir / "batch"), "is a directory, not a file (routes file)"},
        {"validate " + quoted(d), "is a directory, not a file (OpenDRIVE map)"},
    };
    for (const auto& [args, says] : cases) {
        SCOPED_TRACE(args);
        expect_refusal(run_railodd(args), {2, {d.string(), says}});
    }
    EXPECT_FALSE(fs::exists(dir / "out" / "map.xodr"));
}

// Hand-edited odd_profile.json: every reader of it says which file and
// where, whatever the values hold.
TEST_F(CliHostileInput, OddProfileWithWrongTypesOrHugeNumbers) {
    const std::string good = read_file(map() / "odd_profile.json");
    struct Edit {
        std::string from, to;
    };
    const std::vector<Edit> edits = {
        {R"("length_m":)", R"("length_m": "long", "x":)"},
        {R"("length_m":)", R"("length_m": 1e999, "x":)"},
        {R"("elements": [)", R"("elements": {"a": 1}, "y": [)"},
        {R"("element_kinds": [)", R"("element_kinds": 5, "k": [)"},
        {R"("element_columns": [)", R"("element_columns": ["kind"], "c": [)"},
        {"\"elements\": [\n  [0,", "\"elements\": [\n  [99999,"}, // no such kind
        {"\"elements\": [\n  [0,0,", "\"elements\": [\n  [0,\"one\","},     // the track
        {"\"elements\": [\n  [0,0,\"", "\"elements\": [\n  [0,0,12,\"x"}, // the road id
        {"\"elements\": [\n  [0,0,\"", "\"elements\": [\n  [0,0,\"1\",[],\""}, // s_start
        {R"("summary":)", R"("summary": [1, 2], "x":)"},
        {R"("taxonomy": {)", R"("taxonomy": 7, "t": {)"},
    };
    const auto dir = scratch_dir();
    fs::copy_file(map() / "map.xodr", dir / "map.xodr");
    for (const auto& e : edits) {
        SCOPED_TRACE(e.to);
        std::string text = good;
        const auto at = text.find(e.from);
        ASSERT_NE(at, std::string::npos);
        text.replace(at, e.from.size(), e.to);
        write_file(dir / "odd_profile.json", text);
        for (const std::string& cmd : {"profile " + quoted(dir), "profile --json " + quoted(dir),
                                      "scenarios --map " + quoted(dir) + " -o " + quoted(dir / "scen")}) {
            const auto r = run_railodd(cmd);
            SCOPED_TRACE(cmd);
            expect_refusal(r, {2, {"odd_profile.json"}});
        }
    }
}

TEST_F(CliHostileInput, BatchSummaryWithWrongTypesIsAnInputError) {
    const std::string head = R"({"railodd": {"format": "batch_summary", "format_version": 1}, "routes_file": "r.yaml",
                                 "routes_file_hash": "0", "routes_total": 1, )";
    const std::vector<std::pair<std::string, std::string>> bodies = {
        {R"("shard": 3, "routes": [])", "/shard"},
        {R"("shard": {"index": "0", "count": 1}, "routes": [])", "/shard/index"},
        {R"("shard": {"index": 0, "count": 1e999}, "routes": [])", "not valid JSON"},
        {R"("shard": {"index": 0, "count": 4294967295}, "routes": [])", "not a shard of a batch run"},
        {R"("shard": {"index": 0, "count": 1}, "routes": 5)", "/routes"},
        {R"("shard": {"index": 0, "count": 1}, "routes": [{"id": 5}])", "/routes/0/id"},
        {R"("shard": {"index": 0, "count": 1}, "routes": [{"id": "a", "status": 1}])", "/routes/0/status"},
    };
    const auto dir = scratch_dir();
    for (const auto& [body, says] : bodies) {
        SCOPED_TRACE(body);
        write_file(dir / "batch_summary.json", head + body + "}");
        expect_refusal(run_railodd("merge " + quoted(dir) + " -o " + quoted(dir / "merged.json")),
                       {2, {"batch_summary.json", says}});
    }
}

TEST_F(CliHostileInput, StaleManifestWithWrongTypesDoesNotStopAScenarioRun) {
    const auto dir = scratch_dir();
    fs::create_directories(dir / "scen");
    write_file(dir / "scen" / "keep.txt", "mine");
    write_file(dir / "scen" / "manifest.json",
               R"({"scenarios": [{"file": 5}, {"file": ".."}, {"file": "keep.txt"}, 7, {"behavior": ["x"]}]})");
    const auto r = run_railodd("scenarios --map " + quoted(map()) + " -o " + quoted(dir / "scen") + " -q");
    EXPECT_EQ(r.exit_code, 0) << r.output;
    EXPECT_TRUE(fs::exists(dir / "scen" / "keep.txt")) << "only .xosc / .behavior.yaml files are railodd's to remove";
    EXPECT_TRUE(fs::exists(dir)) << r.output;
}

// --- 5. text that XML cannot carry -----------------------------------------

// Invalid UTF-8 (PBF) and control characters or lone surrogates (OPL escapes)
// in tags: the map stays XML that strict readers open; the repair is reported.
TEST_F(CliHostileInput, TagTextThatIsNotXmlIsRepairedAndReported) {
    const auto dir = scratch_dir();
    PbfBuilder b;
    b.nodes = {{1, 10.0, 48.0, {}}, {2, 10.002, 48.0, {}}, {3, 10.004, 48.0, {}}};
    b.ways = {{77, {{"railway", "rail"}, {"name", "K\xC3\xB6ln \xFF\xFE \x01 \xED\xA0\x80 end"}}, {1, 2, 3}}};
    b.write(dir / "bad.osm.pbf");
    write_file(dir / "bad.opl", "n1 v1 x10.0 y48.0\nn2 v1 x10.002 y48.0\nn3 v1 x10.004 y48.0\n"
                                "w78 v1 Trailway=rail,name=a%1%b%d800%c%7f%d Nn1,n2,n3\n");
    for (const std::string& input : std::vector<std::string>{"bad.osm.pbf", "bad.opl"}) {
        SCOPED_TRACE(input);
        const fs::path out = dir / (input + ".out");
        const auto r = run_railodd("convert " + quoted(dir / input) + " -o " + quoted(out));
        ASSERT_EQ(r.exit_code, 0) << r.output;
        for (const char* file : {"map.xodr"}) {
            const auto x = run_command("xmllint --noout " + quoted(out / file));
            EXPECT_EQ(x.exit_code, 0) << file << ": " << x.output;
        }
        const auto v = run_railodd("validate " + quoted(out / "map.xodr"));
        EXPECT_EQ(v.exit_code, 0) << v.output;
        const auto report = nlohmann::json::parse(read_file(out / "report.json"));
        bool reported = false;
        for (const auto& rep : report["repairs"]) {
            reported = reported || rep["action"].get<std::string>().find("U+FFFD") != std::string::npos;
        }
        EXPECT_TRUE(reported) << report["repairs"].dump();
    }
}

TEST_F(CliHostileInput, ValidateRefusesMapsStrictReadersCannotOpen) {
    const auto dir = scratch_dir();
    const std::string good = read_file(map() / "map.xodr");
    std::string ctl = good;
    const auto name = ctl.find("name=\"", ctl.find("<header"));
    ASSERT_NE(name, std::string::npos);
    ctl.insert(name + 6, "\x01"); // a control character inside the header's name
    write_file(dir / "ctl.xodr", ctl);
    std::string rev = good;
    const auto at = rev.find("revMinor=\"");
    rev.replace(at, 12, "revMinor=\"99\"");
    write_file(dir / "rev.xodr", rev);
    const auto c = run_railodd("validate " + quoted(dir / "ctl.xodr"));
    EXPECT_EQ(c.exit_code, 5) << c.output;
    EXPECT_NE(c.output.find("not UTF-8 XML 1.0 text"), std::string::npos) << c.output;
    const auto r = run_railodd("validate " + quoted(dir / "rev.xodr"));
    EXPECT_EQ(r.exit_code, 5) << r.output;
    EXPECT_NE(r.output.find("1.99 does not exist"), std::string::npos) << r.output;
}

TEST_F(CliHostileInput, TemplateTextWithAControlCharacterIsRefused) {
    const auto dir = scratch_dir();
    std::string t = read_file(data_dir / "scenario" / "templates.yaml");
    // The first template's text (the degraded modes before it have texts in flow maps).
    const auto at = t.find("text: ", t.find("\ntemplates:"));
    ASSERT_NE(at, std::string::npos);
    t.insert(at + 6, "\"bell \\x07 here\" # ");
    const auto templates = write_file(dir / "t.yaml", t);
    const auto r = run_railodd("scenarios --map " + quoted(map()) + " -o " + quoted(dir / "scen") + " --templates " +
                               quoted(templates));
    expect_refusal(r, {2, {templates.string() + ":", "not UTF-8 XML text"}});
    EXPECT_FALSE(fs::exists(dir / "scen"));
}

// --- 6. values that pass a naive range check ----------------------------------

TEST_F(CliHostileInput, NonFiniteOrOutOfRangeOptionsAreUsageErrors) {
    const auto dir = scratch_dir();
    const std::string convert = "convert " + quoted(root() / "sample" / "sample_route.osm") + " -o " + quoted(dir / "o");
    const std::string scen = "scenarios --map " + quoted(map()) + " -o " + quoted(dir / "s");
    const std::vector<std::pair<std::string, std::string>> cases = {
        {convert + " --node-noise nan", "--node-noise"},
        {convert + " --feature-distance nan", "--feature-distance"},
        {convert + " --station-distance inf", "--station-distance"},
        {convert + " --road-corridor 1e50", "--road-corridor"},
        {convert + " --threads -1", "--threads"},
        {convert + " --date yesterday", "--date"},
        {"convert " + quoted(root() / "sample" / "sample_route.osm") + " -o ''", "--output"},
        {scen + " --strategy random --count 5 --seed -1", "--seed"},
        {scen + " --count -1", "--count"},
        {scen + " --max-anchors -3", "--max-anchors"},
        {"scenarios --map " + quoted(map()) + " -o ''", "--output"},
    };
    for (const auto& [args, says] : cases) {
        SCOPED_TRACE(args);
        expect_refusal(run_railodd(args), {1, {says}});
    }
    EXPECT_FALSE(fs::exists(dir / "o"));
    EXPECT_FALSE(fs::exists(dir / "s"));
}

TEST_F(CliHostileInput, DuplicateYamlKeysAreRefusedWithTheirLine) {
    const auto dir = scratch_dir();
    std::string t = read_file(data_dir / "scenario" / "templates.yaml");
    const auto at = t.find("    text: ");
    ASSERT_NE(at, std::string::npos);
    t.insert(at, "    text: first\n");
    const auto templates = write_file(dir / "t.yaml", t);
    expect_refusal(run_railodd("scenarios --map " + quoted(map()) + " -o " + quoted(dir / "s") + " --templates " +
                               quoted(templates)),
                   {2, {templates.string() + ":", "duplicate key 'text'"}});
    const auto spec = write_file(dir / "spec.yaml", "odd_spec: twice\nodd_spec: again\nelements: []\n");
    expect_refusal(run_railodd("profile " + quoted(map()) + " --odd-spec " + quoted(spec)),
                   {2, {spec.string() + ":2", "duplicate key 'odd_spec'"}});
    const auto bomb = write_file(dir / "bomb.yaml", "a: &a [x, x, x, x, x, x, x, x, x, x]\n"
                                                     "b: &b [*a, *a, *a, *a, *a, *a, *a, *a, *a, *a]\n"
                                                     "c: &c [*b, *b, *b, *b, *b, *b, *b, *b, *b, *b]\n"
                                                     "d: &d [*c, *c, *c, *c, *c, *c, *c, *c, *c, *c]\n"
                                                     "e: &e [*d, *d, *d, *d, *d, *d, *d, *d, *d, *d]\n"
                                                     "f: &f [*e, *e, *e, *e, *e, *e, *e, *e, *e, *e]\n"
                                                     "g: &g [*f, *f, *f, *f, *f, *f, *f, *f, *f, *f]\n");
    expect_refusal(run_railodd("profile " + quoted(map()) + " --odd-spec " + quoted(bomb)),
                   {2, {bomb.string(), "YAML nodes (aliases expanded)"}});
}

TEST_F(CliHostileInput, ScenariosRefuseAMapThatIsNotOpenDrive) {
    const auto dir = scratch_dir();
    fs::copy_file(map() / "odd_profile.json", dir / "odd_profile.json");
    for (const std::string& text : std::vector<std::string>{"this is not xml", read_file(map() / "map.xodr").substr(0, 5000)}) {
        write_file(dir / "map.xodr", text);
        expect_refusal(run_railodd("scenarios --map " + quoted(dir) + " -o " + quoted(dir / "s")),
                       {2, {"map.xodr", "not an OpenDRIVE map"}});
    }
}

// --- 7. degenerate data ----------------------------------------------------------

TEST_F(CliHostileInput, TrackOfZeroLengthIsRefusedNotAnEmptyMap) {
    const auto dir = scratch_dir();
    write_file(dir / "zero.opl", "n1 v1 x10.0 y48.0\nn2 v1 x10.0 y48.0\nw1 v1 Trailway=rail Nn1,n2\n");
    const auto r = run_railodd("convert " + quoted(dir / "zero.opl") + " -o " + quoted(dir / "o"));
    expect_refusal(r, {2, {"zero.opl", "no track could be written to the map", "zero length"}});
    EXPECT_FALSE(fs::exists(dir / "o" / "map.xodr"));
}

TEST_F(CliHostileInput, DuplicateNodeIdsKeepTheFirstAndAreReported) {
    const auto dir = scratch_dir();
    write_file(dir / "dup.opl", "n1 v1 x10.0 y48.0\nn2 v1 x10.001 y48.0\nn3 v1 x10.002 y48.0\n"
                                "n2 v1 x11.0 y48.0\nw1 v1 Trailway=rail Nn1,n2,n3\n");
    const auto r = run_railodd("convert " + quoted(dir / "dup.opl") + " -o " + quoted(dir / "o"));
    ASSERT_EQ(r.exit_code, 0) << r.output;
    const auto report = nlohmann::json::parse(read_file(dir / "o" / "report.json"));
    ASSERT_EQ(report["repairs"].size(), 1u) << report["repairs"].dump();
    EXPECT_EQ(report["repairs"][0]["osm_id"], 2);
    EXPECT_NE(report["repairs"][0]["action"].get<std::string>().find("first location kept"), std::string::npos);
    EXPECT_LT(report["geometry"]["summary"]["length_km"].get<double>(), 0.2) << "not the 75 km detour to 11 E";
}

// A 300-byte way from 80 S to 80 N once took 20 s and 519 MB: now dropped
// with its reason; tracks 3,300 km apart cannot share one local frame.
TEST_F(CliHostileInput, WaysALocalFrameCannotHoldAreRefusedAtOnce) {
    const auto dir = scratch_dir();
    write_file(dir / "pole.opl", "n1 v1 x10.0 y-80.0\nn2 v1 x10.0 y80.0\nw1 v1 Trailway=rail Nn1,n2\n");
    const auto p = run_railodd("convert " + quoted(dir / "pole.opl") + " -o " + quoted(dir / "o"));
    expect_refusal(p, {2, {"pole.opl", "way 1", "km apart"}});
    write_file(dir / "far.opl", "n1 v1 x10.0 y30.0\nn2 v1 x10.001 y30.0\nn3 v1 x10.0 y60.0\nn4 v1 x10.001 y60.0\n"
                                "w1 v1 Trailway=rail Nn1,n2\nw2 v1 Trailway=rail Nn3,n4\n");
    const auto f = run_railodd("convert " + quoted(dir / "far.opl") + " -o " + quoted(dir / "o"));
    expect_refusal(f, {2, {"far.opl", "covers at most 1000 km"}});
    EXPECT_FALSE(fs::exists(dir / "o"));
}

// --- 8. outputs ---------------------------------------------------------------

// The map's date is the data's (or --date), not the input file's mtime: a copy
// of the same data converts to the same bytes on every machine.
TEST_F(CliHostileInput, MapDateDoesNotFollowTheFileTime) {
    const auto dir = scratch_dir();
    const fs::path input = root() / "sample" / "sample_route.osm";
    const fs::path copy = dir / "copy" / "sample_route.osm"; // same name: the header carries it
    fs::create_directories(copy.parent_path());
    fs::copy_file(input, copy);
    fs::last_write_time(copy, fs::last_write_time(input) - std::chrono::hours(24 * 400));
    ASSERT_EQ(run_railodd("convert " + quoted(copy) + " -o " + quoted(dir / "a")).exit_code, 0);
    EXPECT_EQ(read_file(dir / "a" / "map.xodr"), read_file(map() / "map.xodr"));
    ASSERT_EQ(run_railodd("convert " + quoted(copy) + " -o " + quoted(dir / "b") +
                          " --date 2024-01-02T03:04:05")
                  .exit_code,
              0);
    EXPECT_NE(read_file(dir / "b" / "map.xodr").find("date=\"2024-01-02T03:04:05Z\""), std::string::npos);
}

// A rerun with fewer templates removes the earlier run's scenario, behaviour
// and distribution files of the others, in its commit.
TEST_F(CliHostileInput, RerunRemovesStaleDistributionsToo) {
    const auto dir = scratch_dir();
    const fs::path out = dir / "s";
    ASSERT_EQ(run_railodd("scenarios --map " + quoted(map()) + " -o " + quoted(out) + " -q").exit_code, 0);
    ASSERT_TRUE(fs::exists(out / "distributions" / "tunnel_exit_animal.xosc"));
    std::string t = read_file(data_dir / "scenario" / "templates.yaml");
    t.erase(t.find("  - id: level_crossing_person")); // the first template only
    const auto templates = write_file(dir / "one.yaml", t);
    const auto r = run_railodd("scenarios --map " + quoted(map()) + " -o " + quoted(out) + " -q --templates " +
                               quoted(templates));
    ASSERT_EQ(r.exit_code, 0) << r.output;
    for (const auto& f : listing(out)) {
        if (f.find(".xosc") != std::string::npos || f.find(".behavior.yaml") != std::string::npos) {
            EXPECT_TRUE(f.rfind("curve_crossing_street_vehicle", 0) == 0 ||
                        f.rfind("distributions/curve_crossing_street_vehicle", 0) == 0 || f.rfind("catalogs/", 0) == 0)
                << "stale: " << f;
        }
    }
    EXPECT_TRUE(fs::exists(out / "distributions" / "curve_crossing_street_vehicle.xosc"));
}
