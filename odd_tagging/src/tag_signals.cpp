// railway:signal:* keys and values (OpenRailwayMap tagging scheme): the key
// names the signal's function, its value the national system.
#include "railodd/odd/tag_values.hpp"

#include "enum_table.hpp"

namespace railodd::odd {

using enums::Spelling;

namespace {

constexpr std::array<Spelling<SignalCategory>, 12> categories{{
    {"main", SignalCategory::main},
    {"distant", SignalCategory::distant},
    {"combined", SignalCategory::combined},
    {"speed_limit", SignalCategory::speed_limit},
    {"speed_limit_distant", SignalCategory::speed_limit_distant},
    {"minor", SignalCategory::minor},
    {"shunting", SignalCategory::shunting},
    {"crossing", SignalCategory::crossing},
    {"crossing_distant", SignalCategory::crossing_distant},
    {"route", SignalCategory::route},
    {"stop", SignalCategory::stop},
    {"train_protection", SignalCategory::train_protection},
}};

// Keys under railway:signal: that describe the signal post, not a function.
constexpr std::array<std::string_view, 5> post_keys{"direction", "position", "ref", "height", "catenary_mast"};

constexpr std::string_view prefix = "railway:signal:";

} // namespace

const char* to_string(SignalCategory c) {
    for (const auto& entry : categories) {
        if (entry.value == c) {
            return entry.osm.data(); // string literals: null-terminated
        }
    }
    return "other";
}

TagValue<SignalKey> parse_signal_key(std::string_view key) {
    TagValue<SignalKey> r;
    if (!key.starts_with(prefix) || key.size() == prefix.size()) {
        r.problem = text::quoted(key) + " is not a railway:signal:* key";
        return r;
    }
    auto rest = key.substr(prefix.size());
    const auto colon = rest.find(':');
    const auto name = rest.substr(0, colon);
    SignalKey k;
    if (colon != std::string_view::npos) {
        k.property = std::string(rest.substr(colon + 1));
    }
    for (const auto post : post_keys) {
        if (name == post) {
            r.problem = text::quoted(key) + " describes the signal post, not a signal category";
            return r;
        }
    }
    const auto category = enums::lookup(name, categories, "signal category");
    if (category.ok()) {
        k.category = *category.value;
    } else {
        // Many national categories (ring, whistle, snowplow, ...) have no
        // element of their own in the taxonomy; they are counted as `other`.
        k.category = SignalCategory::other;
        r.note = "signal category " + text::quoted(name) + " counted as other";
    }
    r.value = k;
    return r;
}

TagValue<SignalSystem> parse_signal_system(std::string_view raw) {
    TagValue<SignalSystem> r;
    const auto s = text::trim(raw);
    const auto colon = s.find(':');
    const auto dash = s.find('-');
    if (colon == std::string_view::npos || dash == std::string_view::npos || dash > colon || dash == 0 ||
        colon == dash + 1 || colon + 1 == s.size()) {
        r.problem = text::quoted(s) + " is not COUNTRY-BODY:NAME (e.g. DE-ESO:ks)";
        return r;
    }
    SignalSystem sys;
    sys.country = std::string(s.substr(0, dash));
    sys.body = std::string(s.substr(dash + 1, colon - dash - 1));
    sys.name = std::string(s.substr(colon + 1));
    r.value = std::move(sys);
    return r;
}

const char* to_string(SignalForm f) {
    switch (f) {
    case SignalForm::light: return "light";
    case SignalForm::semaphore: return "semaphore";
    case SignalForm::sign: return "sign";
    }
    return "sign";
}

TagValue<SignalForm> parse_signal_form(std::string_view raw) {
    static constexpr std::array<Spelling<SignalForm>, 3> table{{
        {"light", SignalForm::light}, {"semaphore", SignalForm::semaphore}, {"sign", SignalForm::sign},
    }};
    return enums::lookup(raw, table, "signal form");
}

} // namespace railodd::odd
