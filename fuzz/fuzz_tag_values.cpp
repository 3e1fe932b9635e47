// OSM tag value parsers (maxspeed, gauge, voltage, frequency, radio, ...):
// every one gets the same bytes; none may crash or throw.
#include "railodd/odd/tag_values.hpp"

#include <cstdint>
#include <string_view>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    const std::string_view s(reinterpret_cast<const char*>(data), size);
    using namespace railodd::odd;
    (void)parse_maxspeed(s);
    (void)parse_voltage(s);
    (void)parse_frequency(s);
    (void)parse_gauge(s);
    (void)parse_railway_position(s);
    (void)parse_bool(s);
    (void)parse_electrified(s);
    (void)parse_usage(s);
    (void)parse_service(s);
    (void)parse_preferred_direction(s);
    (void)parse_crossing_barrier(s);
    (void)parse_train_radio(s);
    (void)parse_signal_key(s);
    (void)parse_signal_system(s);
    (void)parse_signal_form(s);
    return 0;
}
