// The OpenDRIVE reader and checks behind `railodd validate`, on bytes in memory.
#include "fuzz_support.hpp"

#include "railodd/xodr_check/check.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    const std::string xml(reinterpret_cast<const char*>(data), size);
    railodd::fuzz::expect_clean([&] { (void)railodd::xodr_check::check_text(xml, "fuzz.xodr"); });
    return 0;
}
