// Small OSM XML or OPL buffers through the whole convert pipeline
// (convert::run, as `railodd convert` calls it): ingest, track graph, fit,
// vertical profile, cant, topology, OpenDRIVE, ODD tagging, the outputs and
// (when asked) report.html. The first byte chooses: bit 0 OPL or XML, bit 1
// the HTML report, bit 2 estimated cant, bit 3 a --from/--to route profile.
#include "fuzz_support.hpp"

#include "railodd/convert/convert.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    if (size < 1 || size > 32 * 1024) {
        return 0;
    }
    const std::uint8_t flags = data[0];
    const auto file = railodd::fuzz::as_file(flags & 1 ? "in.opl" : "in.osm", data + 1, size - 1);
    railodd::convert::Options o;
    o.input = file.string();
    o.outdir = railodd::fuzz::scratch("map").string();
    o.no_timings = true;
    o.threads = 1;
    o.no_report = !(flags & 2);
    o.estimate_cant = (flags & 4) != 0;
    if (flags & 8) {
        o.from = "A";
        o.to = "B";
    }
    railodd::fuzz::expect_exit_code([&] { (void)railodd::convert::run(o); });
    return 0;
}
