// Small OSM XML or OPL buffers through the whole `railodd convert` pipeline,
// exactly as the command line runs it: ingest, track graph, fit, vertical
// profile, cant, topology, OpenDRIVE, ODD tagging, the outputs and (when
// asked) report.html. The first byte chooses: bit 0 OPL or XML, bit 1 the
// HTML report, bit 2 estimated cant, bit 3 a --from/--to route profile.
#include "fuzz_support.hpp"

#include "convert_command.hpp"

#include <CLI/CLI.hpp>

#include <vector>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    if (size < 1 || size > 32 * 1024) {
        return 0;
    }
    const std::uint8_t flags = data[0];
    const auto file = railodd::fuzz::as_file(flags & 1 ? "in.opl" : "in.osm", data + 1, size - 1);
    const auto out = railodd::fuzz::scratch("map");
    std::vector<std::string> args{"convert", file.string(), "-o", out.string(), "--no-timings", "--threads", "1"};
    if (!(flags & 2)) {
        args.push_back("--no-report");
    }
    if (flags & 4) {
        args.push_back("--estimate-cant");
    }
    if (flags & 8) {
        args.insert(args.end(), {"--from", "A", "--to", "B"});
    }
    CLI::App app{"fuzz"};
    railodd::cli::ConvertCommand convert;
    CLI::App* sub = convert.add(app);
    std::vector<std::string> reversed(args.rbegin(), args.rend()); // CLI11 parses a reversed vector
    try {
        app.parse(reversed);
    } catch (const CLI::ParseError&) {
        __builtin_trap(); // the arguments are fixed: a parse error is the harness's own bug
    }
    if (!sub->parsed()) {
        __builtin_trap();
    }
    railodd::fuzz::expect_exit_code([&] {
        convert.setup();
        (void)convert.run();
    });
    return 0;
}
