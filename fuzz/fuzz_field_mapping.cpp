// The YAML field mapping of GIS vector sources (--field-mapping).
#include "fuzz_support.hpp"

#include "field_mapping.hpp" // ingest's own reader: internal, not a public header

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    const auto file = railodd::fuzz::as_file("mapping.yaml", data, size);
    railodd::fuzz::expect_clean([&] { (void)railodd::ingest::load_field_mapping(file); });
    return 0;
}
