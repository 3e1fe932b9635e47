// The hostile-input table (issue 22): one row per way a user can get a
// command wrong, across convert, scenarios, validate, profile, batch, report,
// play and merge. Each row states the exit code, the words the message must
// hold (the file or option, and the problem), and what the output folder
// holds afterwards. No row may end as an internal error (exit 4) or a crash.
// test_cli_hostile_input holds the cases that once broke railodd, one test
// each; this table is the breadth.
#include "test_support.hpp"

#include <functional>
#include <vector>

using namespace railodd::test;

namespace {

CommandResult run_railodd(const std::string& args) { return run_command(std::string{RAILODD_BIN} + " " + args); }

const fs::path data_dir = fs::path{RAILODD_SOURCE_DIR} / "data";

enum class After {
    absent,    // the output path does not exist
    untouched, // the output path holds what it held before
};

struct Row {
    std::string name;
    std::function<void(const fs::path& dir)> setup; // files the row needs, in its folder
    std::string args;                               // "$D" is the row's folder, "$M" the sample map, "$S" its scenarios
    int exit_code;
    std::vector<std::string> says;
    After after;
    std::string output = "$D/out"; // the path After is checked on
};

class CliHostileTable : public ::testing::Test {
protected:
    static fs::path root() {
        return fs::temp_directory_path() / "railodd-tests" / ("CliHostileTable-" + std::to_string(::getpid()));
    }
    static void SetUpTestSuite() {
        fs::remove_all(root());
        fs::create_directories(root());
        ASSERT_EQ(run_railodd("sample -o " + quoted(root() / "sample")).exit_code, 0);
        auto c = run_railodd("convert " + quoted(root() / "sample" / "sample_route.osm") + " -o " + quoted(root() / "map") +
                             " --no-timings --no-report");
        ASSERT_EQ(c.exit_code, 0) << c.output;
        c = run_railodd("scenarios --map " + quoted(root() / "map") + " -o " + quoted(root() / "scen") +
                        " --strategy random --count 1 --quiet");
        ASSERT_EQ(c.exit_code, 0) << c.output;
    }
    static void TearDownTestSuite() { fs::remove_all(root()); }
};

std::string expand(std::string s, const fs::path& dir, const fs::path& root) {
    const std::vector<std::pair<std::string, std::string>> vars = {
        {"$D", dir.string()}, {"$M", (root / "map").string()}, {"$S", (root / "scen").string()},
        {"$O", (root / "sample" / "sample_route.osm").string()}, {"$T", (data_dir / "scenario").string()}};
    for (const auto& [k, v] : vars) {
        for (auto at = s.find(k); at != std::string::npos; at = s.find(k, at + v.size())) {
            s.replace(at, k.size(), v);
        }
    }
    return s;
}

void write(const fs::path& p, const std::string& text) { write_file(p, text); }

const auto none = [](const fs::path&) {};

std::vector<Row> convert_rows() {
    const std::string conv = "convert ";
    return {
        {"convert: missing input", none, conv + "$D/nope.osm -o $D/out", 2, {"nope.osm", "no such file"}, After::absent},
        {"convert: empty .osm", [](const fs::path& d) { write(d / "e.osm", ""); }, conv + "$D/e.osm -o $D/out", 2,
         {"e.osm"}, After::absent},
        {"convert: truncated XML", [](const fs::path& d) { write(d / "t.osm", "<?xml version=\"1.0\"?><osm><node id=\"1\" lat="); },
         conv + "$D/t.osm -o $D/out", 2, {"t.osm"}, After::absent},
        {"convert: a latitude of 1e20 (libosmium would overflow)",
         [](const fs::path& d) {
             write(d / "x.osm", "<osm version=\"0.6\"><node id=\"1\" lat=\"1e20\" lon=\"1\"/></osm>");
         },
         conv + "$D/x.osm -o $D/out", 2, {"x.osm", "line 1", "lat=\"1e20\"", "exponent"}, After::absent},
        {"convert: no railway in the file",
         [](const fs::path& d) { write(d / "n.osm", "<osm version=\"0.6\"><node id=\"1\" lat=\"1\" lon=\"1\"/></osm>"); },
         conv + "$D/n.osm -o $D/out", 2, {"n.osm", "no usable railway track"}, After::absent},
        {"convert: --bbox west of east swapped", none, conv + "$O -o $D/out --bbox 11,48,10,49", 1, {"bbox"}, After::absent},
        {"convert: --bbox with three numbers", none, conv + "$O -o $D/out --bbox 10,48,11", 1, {"bbox"}, After::absent},
        {"convert: --polygon not GeoJSON", [](const fs::path& d) { write(d / "p.geojson", "not json"); },
         conv + "$O -o $D/out --polygon $D/p.geojson", 2, {"p.geojson"}, After::absent},
        {"convert: --polygon a LineString",
         [](const fs::path& d) {
             write(d / "l.geojson", R"({"type":"LineString","coordinates":[[10,48],[11,49]]})");
         },
         conv + "$O -o $D/out --polygon $D/l.geojson", 2, {"l.geojson"}, After::absent},
        {"convert: --relation not in the file", none, conv + "$O -o $D/out --relation 999999", 2, {"999999"}, After::absent},
        {"convert: --dem not a raster", [](const fs::path& d) { write(d / "dem.tif", "no raster"); },
         conv + "$O -o $D/out --dem $D/dem.tif", 2, {"dem.tif"}, After::absent},
        {"convert: --from without --to", none, conv + "$O -o $D/out --from Sampleton", 1, {"--to"}, After::absent},
        {"convert: --from an unknown station", none, conv + "$O -o $D/out --from Nowhere --to Sampleton", 2,
         {"Nowhere"}, After::absent},
        {"convert: --odr-version 2.0", none, conv + "$O -o $D/out --odr-version 2.0", 1, {"--odr-version"}, After::absent},
        {"convert: --taxonomy not YAML", [](const fs::path& d) { write(d / "tax.yaml", "a: [b\n"); },
         conv + "$O -o $D/out --taxonomy $D/tax.yaml", 2, {"tax.yaml"}, After::absent},
        {"convert: --field-mapping with an OSM file", [](const fs::path& d) { write(d / "m.yaml", "layer: x\n"); },
         conv + "$O -o $D/out --field-mapping $D/m.yaml", 1, {"--field-mapping"}, After::absent},
        {"convert: -o is a file", [](const fs::path& d) { write(d / "out", "a file"); }, conv + "$O -o $D/out", 3,
         {"out"}, After::untouched},
        {"convert: --road-corridor NaN", none, conv + "$O -o $D/out --road-corridor nan", 1, {"--road-corridor"},
         After::absent},
    };
}

std::vector<Row> scenario_and_check_rows() {
    return {
        {"scenarios: map folder without a profile", [](const fs::path& d) { fs::create_directories(d / "m"); },
         "scenarios --map $D/m -o $D/out", 2, {"odd_profile.json"}, After::absent},
        {"scenarios: unknown --strategy", none, "scenarios --map $M -o $D/out --strategy all", 1, {"--strategy"},
         After::absent},
        {"scenarios: --count -1", none, "scenarios --map $M -o $D/out --strategy random --count -1", 1, {"--count"},
         After::absent},
        {"scenarios: empty templates file", [](const fs::path& d) { write(d / "t.yaml", ""); },
         "scenarios --map $M -o $D/out --templates $D/t.yaml", 2, {"t.yaml"}, After::absent},
        {"scenarios: catalog is a list", [](const fs::path& d) { write(d / "c.yaml", "- a\n- b\n"); },
         "scenarios --map $M -o $D/out --catalog $D/c.yaml", 2, {"c.yaml"}, After::absent},
        {"scenarios: --osc-version 9", none, "scenarios --map $M -o $D/out --osc-version 9", 1, {"--osc-version"},
         After::absent},
        // --- validate ----------------------------------------------------
        {"validate: empty file", [](const fs::path& d) { write(d / "e.xodr", ""); }, "validate $D/e.xodr", 2,
         {"e.xodr"}, After::absent},
        {"validate: not XML", [](const fs::path& d) { write(d / "x.xodr", "road road road"); }, "validate $D/x.xodr", 2,
         {"x.xodr", "not well-formed"}, After::absent},
        {"validate: XML that is not OpenDRIVE", [](const fs::path& d) { write(d / "o.xodr", "<osm/>"); },
         "validate $D/o.xodr", 2, {"o.xodr", "OpenDRIVE"}, After::absent},
        {"validate: --xsd-dir missing", none, "validate $M/map.xodr --xsd-dir $D/nothing", 1, {"nothing", "--xsd-dir"}, After::absent},
        // --- profile -----------------------------------------------------
        {"profile: missing folder", none, "profile $D/nothing", 2, {"nothing"}, After::absent},
        {"profile: truncated profile", [](const fs::path& d) { write(d / "odd_profile.json", "{\"elements\": ["); },
         "profile $D/odd_profile.json", 2, {"odd_profile.json"}, After::absent},
        {"profile: spec naming an unknown element",
         [](const fs::path& d) { write(d / "spec.yaml", "odd_spec: x\nelements:\n  - path: Scenery/Nothing\n    allowed: true\n"); },
         "profile $M --odd-spec $D/spec.yaml", 2, {"spec.yaml", "Scenery/Nothing"}, After::absent},
    };
}

std::vector<Row> batch_report_play_rows() {
    return {
        {"batch: routes file without routes", [](const fs::path& d) { write(d / "r.yaml", "routes: []\n"); },
         "batch $D/r.yaml -o $D/out", 2, {"r.yaml"}, After::absent},
        {"batch: duplicate route ids",
         [](const fs::path& d) {
             write(d / "r.yaml", "routes:\n  - id: a\n    input: x.osm\n  - id: a\n    input: y.osm\n");
         },
         "batch $D/r.yaml -o $D/out", 2, {"r.yaml", "a"}, After::absent},
        {"batch: --shard 3/2", [](const fs::path& d) { write(d / "r.yaml", "routes:\n  - id: a\n    input: x.osm\n"); },
         "batch $D/r.yaml -o $D/out --shard 3/2", 1, {"--shard"}, After::absent},
        // --- report ------------------------------------------------------
        {"report: missing folder", none, "report $D/nothing -o $D/out/r.html", 2, {"nothing"}, After::absent},
        {"report: folder without map.xodr",
         [](const fs::path& d) {
             fs::create_directories(d / "m");
             fs::copy_file(d.parent_path() / "map" / "odd_profile.json", d / "m" / "odd_profile.json");
         },
         "report $D/m -o $D/out/r.html", 2, {"map.xodr"}, After::absent},
        {"report: --play without --scenarios", none, "report $M --play $S/play.json -o $D/out/r.html", 1, {"--play"},
         After::absent},
        {"report: --tiles without {z}", none, "report $M --tiles https://tiles.example/a.png -o $D/out/r.html", 1,
         {"--tiles"}, After::absent},
        {"report: scenario folder without a manifest", [](const fs::path& d) { fs::create_directories(d / "s"); },
         "report $M --scenarios $D/s -o $D/out/r.html", 2, {"coverage.json"}, After::absent},
        {"report: map without a geoReference",
         [](const fs::path& d) {
             fs::create_directories(d / "m");
             for (const char* f : {"odd_profile.json", "report.json"}) {
                 fs::copy_file(d.parent_path() / "map" / f, d / "m" / f);
             }
             std::string x = read_file(d.parent_path() / "map" / "map.xodr");
             const auto a = x.find("<geoReference>"), b = x.find("</geoReference>");
             write(d / "m" / "map.xodr", x.erase(a, b + 15 - a));
         },
         "report $D/m -o $D/out/r.html", 2, {"map.xodr", "geoReference"}, After::absent},
        // --- play and merge ----------------------------------------------
        {"play: missing folder", none, "play $D/nothing", 2, {"nothing"}, After::absent},
        {"play: --player that does not exist", none, "play $S --player $D/no-esmini --quiet", 2, {"no-esmini"},
         After::absent, "$S/play.json"},
        {"merge: missing batch folder", none, "merge $D/nothing -o $D/out/merged.json", 2, {"nothing"}, After::absent},
    };
}

std::vector<Row> rows() {
    std::vector<Row> all = convert_rows();
    for (auto part : {scenario_and_check_rows(), batch_report_play_rows()}) {
        all.insert(all.end(), part.begin(), part.end());
    }
    return all;
}

TEST_F(CliHostileTable, EveryRowExitsAsDocumentedAndLeavesNoOutput) {
    const auto table = rows();
    EXPECT_GE(table.size(), 40u);
    std::size_t i = 0;
    for (const auto& row : table) {
        SCOPED_TRACE(row.name);
        const fs::path dir = root() / ("row" + std::to_string(i++));
        fs::create_directories(dir);
        row.setup(dir);
        const fs::path out{expand(row.output, dir, root())};
        const std::string before = fs::is_regular_file(out) ? read_file(out) : "";
        const auto r = run_railodd(expand(row.args, dir, root()));
        EXPECT_EQ(r.exit_code, row.exit_code) << r.output;
        for (const auto& s : row.says) {
            EXPECT_NE(r.output.find(expand(s, dir, root())), std::string::npos) << "missing '" << s << "' in: " << r.output;
        }
        EXPECT_EQ(r.output.find("internal error"), std::string::npos) << r.output;
        switch (row.after) {
        case After::absent: EXPECT_FALSE(fs::exists(out)) << out; break;
        case After::untouched:
            EXPECT_TRUE(fs::exists(out));
            if (fs::is_regular_file(out)) {
                EXPECT_EQ(read_file(out), before);
            }
            break;
        }
    }
}

} // namespace
