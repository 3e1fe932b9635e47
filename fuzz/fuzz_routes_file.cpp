// The routes file of `railodd batch` (cli/batch_routes.cpp, in railodd_cli).
#include "fuzz_support.hpp"

#include "batch_routes.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    const auto file = railodd::fuzz::as_file("routes.yaml", data, size);
    railodd::fuzz::expect_clean([&] { (void)railodd::cli::load_batch_file(file); });
    return 0;
}
