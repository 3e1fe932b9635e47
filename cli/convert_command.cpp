#include "convert_command.hpp"
#include "option_table.hpp"

#include "railodd/convert/convert.hpp"
#include "railodd/util/errors.hpp"

#include <cstdlib>
#include <iostream>
#include <string>

namespace railodd::cli {

CLI::App* ConvertCommand::add(CLI::App& parent) {
    CLI::App* app = parent.add_subcommand("convert", "Convert an OSM extract (or GIS vector file) of a route");
    add_table_options(*app, opt_);
    return app;
}

void ConvertCommand::setup() {
    convert::check(opt_);
    if (opt_.threads > 0) {
        // libosmium sizes its decoding pool from this on first use.
        ::setenv("OSMIUM_POOL_THREADS", std::to_string(opt_.threads).c_str(), 1);
    }
}

int ConvertCommand::run() {
    const convert::Result r = convert::run(opt_);
    const auto& c = r.counts;
    std::cout << "railodd convert: " << r.source << " (" << r.selection << ")\n"
              << "  track ways: " << r.ways_in_map << " of " << c.input_track_ways << " in the map, "
              << (c.input_track_ways - c.output_track_ways) << " dropped at ingest, "
              << (c.output_track_ways - r.ways_in_map) << " not written (report.json)\n"
              << "  road ways:  " << c.output_road_ways << " of " << c.input_road_ways << "\n"
              << "  features:   " << c.output_features << " of " << c.input_features << "\n";
    for (const auto& p : r.written) {
        std::cout << "  wrote " << p.string() << '\n';
    }
    return exit_ok;
}

} // namespace railodd::cli
