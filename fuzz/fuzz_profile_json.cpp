// odd_profile.json as `railodd profile`, `scenarios` and `report` read it:
// read_profile (rows turned into elements while parsing) and, where that
// succeeds, the same text through the whole tree (profile_from_json), which
// must give the same profile.
#include "fuzz_support.hpp"

#include "railodd/odd/profile.hpp"
#include "railodd/util/errors.hpp"

#include <cstdlib>
#include <string>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    const auto file = railodd::fuzz::as_file("odd_profile.json", data, size);
    railodd::odd::OddProfile streamed;
    try {
        streamed = railodd::odd::read_profile(file);
    } catch (const railodd::InputError&) { // the documented refusal
        return 0;
    }
    try {
        const auto tree = railodd::odd::profile_from_json(
            nlohmann::ordered_json::parse(std::string(reinterpret_cast<const char*>(data), size)));
        if (railodd::odd::to_json_text(streamed) == railodd::odd::to_json_text(tree)) {
            return 0;
        }
    } catch (const std::exception&) { // accepted by one reading, refused by the other
    }
    std::abort();
    return 0;
}
