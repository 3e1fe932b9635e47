// Small OSM XML (first byte even) or OPL (odd) buffers through ingest: the
// reader, selection, local frame and accounting of `convert`.
#include "fuzz_support.hpp"

#include "railodd/ingest/osm_reader.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    if (size < 1 || size > 64 * 1024) {
        return 0;
    }
    const auto file = railodd::fuzz::as_file(data[0] % 2 ? "in.opl" : "in.osm", data + 1, size - 1);
    railodd::fuzz::expect_clean([&] {
        railodd::ingest::IngestOptions o;
        (void)railodd::ingest::read_osm(file, o);
    });
    return 0;
}
