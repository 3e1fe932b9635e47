// The GeoJSON polygon reader behind --polygon.
#include "fuzz_support.hpp"

#include "railodd/ingest/selection.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    const auto file = railodd::fuzz::as_file("in.geojson", data, size);
    railodd::fuzz::expect_clean([&] { (void)railodd::ingest::load_polygon_geojson(file); });
    return 0;
}
