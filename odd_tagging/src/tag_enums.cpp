// Enumerated OSM tag values: electrified, usage, service,
// railway:preferred_direction, crossing:barrier, railway:radio.
#include "railodd/odd/tag_values.hpp"

#include "enum_table.hpp"

#include <algorithm>

namespace railodd::odd {

using enums::Spelling;

const char* to_string(Electrification e) {
    switch (e) {
    case Electrification::contact_line: return "contact_line";
    case Electrification::rail: return "rail";
    case Electrification::fourth_rail: return "fourth_rail";
    case Electrification::ground_level: return "ground_level";
    case Electrification::unspecified: return "unspecified";
    case Electrification::none: return "none";
    }
    return "unspecified";
}

TagValue<std::vector<Electrification>> parse_electrified(std::string_view raw) {
    static constexpr std::array<Spelling<Electrification>, 6> table{{
        {"contact_line", Electrification::contact_line},
        {"rail", Electrification::rail},
        {"4th_rail", Electrification::fourth_rail},
        {"ground-level_power_supply", Electrification::ground_level},
        {"yes", Electrification::unspecified},
        {"no", Electrification::none},
    }};
    TagValue<std::vector<Electrification>> r;
    std::vector<Electrification> out;
    // "contact_line;rail": both systems on one track (e.g. S-Bahn transitions).
    for (const auto part : text::split(raw, ';')) {
        auto one = enums::lookup(part, table, "electrified");
        if (!one.ok()) {
            r.problem = one.problem;
            return r;
        }
        if (!one.note.empty()) {
            r.note += (r.note.empty() ? "" : "; ") + one.note;
        }
        out.push_back(*one.value);
    }
    if (out.size() > 1 && std::find(out.begin(), out.end(), Electrification::none) != out.end()) {
        r.problem = text::quoted(raw) + " combines 'no' with a system";
        return r;
    }
    r.value = std::move(out);
    return r;
}

const char* to_string(Usage u) {
    switch (u) {
    case Usage::main: return "main";
    case Usage::branch: return "branch";
    case Usage::industrial: return "industrial";
    case Usage::military: return "military";
    case Usage::tourism: return "tourism";
    case Usage::scientific: return "scientific";
    case Usage::test: return "test";
    }
    return "main";
}

TagValue<Usage> parse_usage(std::string_view raw) {
    static constexpr std::array<Spelling<Usage>, 7> table{{
        {"main", Usage::main}, {"branch", Usage::branch}, {"industrial", Usage::industrial},
        {"military", Usage::military}, {"tourism", Usage::tourism}, {"scientific", Usage::scientific},
        {"test", Usage::test},
    }};
    return enums::lookup(raw, table, "usage");
}

const char* to_string(Service s) {
    switch (s) {
    case Service::siding: return "siding";
    case Service::yard: return "yard";
    case Service::spur: return "spur";
    case Service::crossover: return "crossover";
    }
    return "siding";
}

TagValue<Service> parse_service(std::string_view raw) {
    static constexpr std::array<Spelling<Service>, 4> table{{
        {"siding", Service::siding}, {"yard", Service::yard}, {"spur", Service::spur},
        {"crossover", Service::crossover},
    }};
    return enums::lookup(raw, table, "service");
}

const char* to_string(PreferredDirection d) {
    switch (d) {
    case PreferredDirection::forward: return "forward";
    case PreferredDirection::backward: return "backward";
    case PreferredDirection::both: return "both";
    }
    return "both";
}

TagValue<PreferredDirection> parse_preferred_direction(std::string_view raw) {
    static constexpr std::array<Spelling<PreferredDirection>, 3> table{{
        {"forward", PreferredDirection::forward}, {"backward", PreferredDirection::backward},
        {"both", PreferredDirection::both},
    }};
    return enums::lookup(raw, table, "railway:preferred_direction");
}

const char* to_string(Barrier b) {
    switch (b) {
    case Barrier::no: return "no";
    case Barrier::yes: return "yes";
    case Barrier::half: return "half";
    case Barrier::double_half: return "double_half";
    case Barrier::full: return "full";
    case Barrier::gate: return "gate";
    case Barrier::chain: return "chain";
    }
    return "yes";
}

TagValue<Barrier> parse_crossing_barrier(std::string_view raw) {
    static constexpr std::array<Spelling<Barrier>, 7> table{{
        {"no", Barrier::no}, {"yes", Barrier::yes}, {"half", Barrier::half},
        {"double_half", Barrier::double_half}, {"full", Barrier::full}, {"gate", Barrier::gate},
        {"chain", Barrier::chain},
    }};
    return enums::lookup(raw, table, "crossing:barrier");
}

const char* to_string(TrainRadio r) {
    switch (r) {
    case TrainRadio::gsm_r: return "gsm-r";
    case TrainRadio::frmcs: return "frmcs";
    case TrainRadio::analogue: return "analogue";
    case TrainRadio::none: return "none";
    }
    return "none";
}

TagValue<std::vector<TrainRadio>> parse_train_radio(std::string_view raw) {
    static constexpr std::array<Spelling<TrainRadio>, 5> table{{
        {"gsm-r", TrainRadio::gsm_r}, {"frmcs", TrainRadio::frmcs}, {"analogue", TrainRadio::analogue},
        {"no", TrainRadio::none}, {"none", TrainRadio::none},
    }};
    TagValue<std::vector<TrainRadio>> r;
    std::vector<TrainRadio> out;
    for (const auto part : text::split(raw, ';')) {
        // US spelling: the same system, read with a note rather than refused.
        const bool us = text::lower(text::trim(part)) == "analog";
        auto one = us ? TagValue<TrainRadio>{TrainRadio::analogue, "", "read 'analog' as 'analogue'"}
                      : enums::lookup(part, table, "railway:radio");
        if (!one.ok()) {
            r.problem = one.problem;
            return r;
        }
        if (!one.note.empty()) {
            r.note += (r.note.empty() ? "" : "; ") + one.note;
        }
        if (std::find(out.begin(), out.end(), *one.value) == out.end()) {
            out.push_back(*one.value);
        }
    }
    if (out.size() > 1 && std::find(out.begin(), out.end(), TrainRadio::none) != out.end()) {
        r.problem = text::quoted(raw) + " combines 'no' with a radio system";
        return r;
    }
    r.value = std::move(out);
    return r;
}

} // namespace railodd::odd
