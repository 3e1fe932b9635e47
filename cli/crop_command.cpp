#include "crop_command.hpp"
#include "option_checks.hpp"

#include "railodd/util/errors.hpp"
#include "railodd/util/output_stage.hpp"
#include "railodd/xodr_check/map_crop.hpp"

#include <cmath>
#include <filesystem>
#include <iostream>
#include <sstream>

namespace railodd::cli {

namespace fs = std::filesystem;

namespace {

// XMIN,YMIN,XMAX,YMAX, four finite numbers, min below max.
xodr_check::CropSpec::Box parse_box(const std::string& text) {
    std::istringstream in(text);
    double v[4];
    char comma = ',';
    for (int i = 0; i < 4; ++i) {
        if (!(in >> v[i]) || !std::isfinite(v[i]) || (i < 3 && !(in >> comma && comma == ','))) {
            throw UsageError("--box", "'" + text + "' is not XMIN,YMIN,XMAX,YMAX (four numbers, map metres)");
        }
    }
    if (!(in >> std::ws).eof() || !(v[0] < v[2]) || !(v[1] < v[3])) {
        throw UsageError("--box", "'" + text + "' is not XMIN,YMIN,XMAX,YMAX with XMIN < XMAX and YMIN < YMAX");
    }
    return {v[0], v[1], v[2], v[3]};
}

} // namespace

CLI::App* CropCommand::add(CLI::App& parent) {
    CLI::App* app = parent.add_subcommand(
        "crop", "Cut an OpenDRIVE map to named roads or a box plus a corridor around them (docs/validate.md, \"crop\")");
    app->add_option("MAP", opt_.map, "OpenDRIVE map (.xodr)")->required();
    app->add_option("-o,--output", opt_.out, "The cut map (.xodr)")->required()->check(non_empty_path);
    app->add_option("--roads", opt_.roads, "Road ids to keep (a route's roads), comma separated")->delimiter(',');
    app->add_option("--box", opt_.box, "Keep roads with a point in XMIN,YMIN,XMAX,YMAX (map coordinates, m)");
    app->add_option("--corridor", opt_.corridor_m, "Also keep every road within this many metres of those")
        ->capture_default_str()
        ->check(finite_range(0.0, 100000.0));
    return app;
}

void CropCommand::setup() {
    if (opt_.roads.empty() && opt_.box.empty()) {
        throw UsageError("crop", "name the roads to keep (--roads ID,...) or a box (--box XMIN,YMIN,XMAX,YMAX)");
    }
    if (!opt_.box.empty()) {
        parse_box(opt_.box); // refused before anything is read
    }
    if (fs::path(opt_.out).filename().empty()) {
        throw UsageError(opt_.out, "-o names a folder, not a file");
    }
}

int CropCommand::run() {
    finish_pending_commit(fs::absolute(opt_.map).parent_path());
    xodr_check::CropSpec spec;
    spec.roads = opt_.roads;
    if (!opt_.box.empty()) {
        spec.box = parse_box(opt_.box);
    }
    spec.corridor_m = opt_.corridor_m;
    const xodr_check::CropResult r = xodr_check::crop_map(opt_.map, spec);
    const fs::path out = fs::absolute(opt_.out);
    OutputStage stage(out.parent_path());
    stage.write_text(out.filename().string(), r.xml);
    for (const auto& p : stage.commit()) {
        std::cout << "  wrote " << p.string() << "\n";
    }
    std::cout << "  " << r.roads_kept << " of " << r.roads_in << " roads, " << r.junctions_kept << " junctions; "
              << r.links_dropped << " links and " << r.connections_dropped << " junction connections to removed roads dropped\n";
    return exit_ok;
}

} // namespace railodd::cli
