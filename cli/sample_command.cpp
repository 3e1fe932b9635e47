#include "sample_command.hpp"
#include "option_checks.hpp"

#include "railodd/sample/sample_route.hpp"
#include "railodd/util/errors.hpp"

#include <iostream>

namespace railodd::cli {

CLI::App* SampleCommand::add(CLI::App& parent) {
    CLI::App* app =
        parent.add_subcommand("sample", "Write the embedded sample route: OSM, DEM and ground truth");
    app->add_option("-o,--output", outdir_, "Output directory (created if needed)")->required()->check(non_empty_path);
    return app;
}

int SampleCommand::run() {
    const sample::SampleFiles files = sample::write_sample_route(outdir_);
    std::cout << files.osm.string() << '\n' << files.dem.string() << '\n' << files.truth.string() << '\n';
    return exit_ok;
}

} // namespace railodd::cli
