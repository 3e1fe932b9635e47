#include "report_command.hpp"
#include "option_checks.hpp"

#include "railodd/report/report.hpp"
#include "railodd/util/errors.hpp"
#include "railodd/util/output_stage.hpp"

#include <filesystem>
#include <iostream>
#include <regex>

namespace railodd::cli {

namespace fs = std::filesystem;

CLI::App* ReportCommand::add(CLI::App& parent) {
    CLI::App* app = parent.add_subcommand(
        "report", "Write one self-contained HTML page of a converted route: map, alignment, ODD, scenarios, fit");
    app->add_option("MAPDIR", opt_.map_dir, "Output folder of `railodd convert`")->required()->check(non_empty_path);
    app->add_option("--scenarios", opt_.scenario_dir, "Scenario set of `railodd scenarios` (coverage, anchors)")
        ->check(non_empty_path);
    app->add_option("--play", opt_.play, "play.json of `railodd play`, or its folder (default: SCENDIR/play.json)")
        ->check(non_empty_path);
    app->add_option("--odd-spec", opt_.odd_spec, "Declared ODD (YAML): violations listed and placed on the map")
        ->check(non_empty_path);
    app->add_option("--taxonomy", opt_.taxonomy, "Taxonomy for --odd-spec (default: the profile's, else the shipped one)");
    app->add_option("--tiles", opt_.tiles,
                    "Basemap tile URL template with {z}, {x}, {y} (default: none, the page needs no network)");
    app->add_option("--title", opt_.title, "Page title (default: from the route)");
    app->add_option("-o,--output", opt_.output, "The page (default: MAPDIR/report.html)")->check(non_empty_path);
    return app;
}

void ReportCommand::setup() {
    if (!fs::is_directory(opt_.map_dir)) {
        throw InputError(opt_.map_dir, "not a folder (MAPDIR is the output folder of `railodd convert`)");
    }
    if (!opt_.scenario_dir.empty() && !fs::is_directory(opt_.scenario_dir)) {
        throw InputError(opt_.scenario_dir, "not a folder (--scenarios is the output folder of `railodd scenarios`)");
    }
    if (!opt_.play.empty() && opt_.scenario_dir.empty()) {
        throw UsageError("--play", "play results belong to a scenario set: give --scenarios SCENDIR too");
    }
    static const std::regex tiles(R"(^https?://.*\{z\}.*\{x\}.*\{y\}.*$)");
    if (!opt_.tiles.empty() && !std::regex_match(opt_.tiles, tiles)) {
        throw UsageError("--tiles", "'" + opt_.tiles + "' is not an http(s) URL template with {z}, {x} and {y}");
    }
    if (opt_.output.empty()) {
        opt_.output = (fs::path{opt_.map_dir} / "report.html").string();
    }
    if (fs::is_directory(opt_.output)) {
        throw OutputError(opt_.output, "is a folder: -o names the page's file (e.g. " +
                                           (fs::path{opt_.output} / "report.html").string() + ")");
    }
}

int ReportCommand::run() {
    for (const std::string& dir : {opt_.map_dir, opt_.scenario_dir}) {
        if (!dir.empty()) {
            finish_pending_commit(dir);
        }
    }
    report::ReportOptions o;
    o.map_dir = opt_.map_dir;
    o.scenario_dir = opt_.scenario_dir;
    o.play_file = opt_.play;
    o.odd_spec = opt_.odd_spec;
    o.taxonomy = opt_.taxonomy;
    o.fallback_taxonomy = fs::path{RAILODD_DATA_DIR} / "odd" / "railway_odd.yaml";
    o.tiles = opt_.tiles;
    o.title = opt_.title;
    const report::PageData page = report::page_data(o);
    // Staged like every output: a failed run leaves no half-written page.
    const fs::path out = fs::absolute(opt_.output);
    OutputStage stage(out.parent_path());
    stage.write_with(out.filename().string(), [&](std::ostream& os) { report::write_html(page, os); });
    for (const auto& p : stage.commit()) {
        std::cout << "railodd report: wrote " << p.string() << " (" << fs::file_size(p) / 1024 << " KiB)\n";
    }
    return exit_ok;
}

} // namespace railodd::cli
