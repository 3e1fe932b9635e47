#pragma once
// Parsers for the OSM tag values the ODD tagger reads (docs/odd.md "Tag
// values"). Each returns the parsed value or the reason it could not be parsed,
// so that the tagger can record every unparsed value in report.json instead of
// guessing. A `note` says how an unusual but accepted value was read (mph
// converted, several values reduced to one, a decimal comma) so that the
// interpretation is reported as a repair.
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace railodd::odd {

template <class T>
struct TagValue {
    std::optional<T> value;
    std::string problem; // why it could not be parsed; empty when parsed
    std::string note;    // how an accepted value was interpreted; often empty
    bool ok() const { return value.has_value(); }
};

// --- numbers ---------------------------------------------------------------

// The kind of a maxspeed value, named as the taxonomy's
// "Operational Conditions/Speed/Speed limit" `kind` values.
enum class SpeedLimitKind { posted, signals, none, unknown };
const char* to_string(SpeedLimitKind kind);

struct MaxSpeed {
    std::optional<double> kmh;
    SpeedLimitKind kind = SpeedLimitKind::unknown;
    std::string problem;
    std::string note;
    bool ok() const { return kmh.has_value(); }
};

// "80", "80 km/h", "50 mph" (converted), "60;80" and "80-100" (the lowest, with
// a note); "signals", "none", "walk" and zone codes such as "DE:urban" carry no
// number and come back unparsed with their kind and reason.
MaxSpeed parse_maxspeed(std::string_view text);

// Volts: "15000", "15000;25000", "750 V"; "15 kV" is converted with a note.
TagValue<std::vector<double>> parse_voltage(std::string_view text);
// Hertz: "16.7", "50", "0" (DC), "16.7;50"; "16,7" read with a note.
TagValue<std::vector<double>> parse_frequency(std::string_view text);
// Millimetres: "1435", "1435;1000" (dual gauge), "standard" (1435, with a note).
TagValue<std::vector<double>> parse_gauge(std::string_view text);
// Kilometrage (railway:position) in km: "12.345", "12,345" (decimal comma),
// "12.3+45" (12.3 km plus 45 m of overlength), "km 12.3", "mi:7.5" (miles).
TagValue<double> parse_railway_position(std::string_view text);
// yes/no/true/false/1/0, any letter case.
TagValue<bool> parse_bool(std::string_view text);

// --- enumerations (to_string gives the taxonomy's enum value) ---------------

enum class Electrification { contact_line, rail, fourth_rail, ground_level, unspecified, none };
const char* to_string(Electrification e);
// "contact_line", "rail", "4th_rail", "ground-level_power_supply", "yes", "no",
// or several separated by ';'.
TagValue<std::vector<Electrification>> parse_electrified(std::string_view text);

enum class Usage { main, branch, industrial, military, tourism, scientific, test };
const char* to_string(Usage u);
TagValue<Usage> parse_usage(std::string_view text);

// A running line carries no service tag; the tagger records that as "running".
enum class Service { siding, yard, spur, crossover };
const char* to_string(Service s);
TagValue<Service> parse_service(std::string_view text);

enum class PreferredDirection { forward, backward, both };
const char* to_string(PreferredDirection d);
TagValue<PreferredDirection> parse_preferred_direction(std::string_view text);

enum class Barrier { no, yes, half, double_half, full, gate, chain };
const char* to_string(Barrier b);
TagValue<Barrier> parse_crossing_barrier(std::string_view text);

// Train radio (railway:radio): "gsm-r", "frmcs", "analogue" ("analog" with a
// note), "no"/"none"; several separated by ';' ("gsm-r;analogue" during a
// changeover). "no" combined with a system is a contradiction, not a value.
enum class TrainRadio { gsm_r, frmcs, analogue, none };
const char* to_string(TrainRadio r);
TagValue<std::vector<TrainRadio>> parse_train_radio(std::string_view text);

// --- signals (railway:signal:*) ---------------------------------------------

enum class SignalCategory {
    main, distant, combined, speed_limit, speed_limit_distant, minor, shunting,
    crossing, crossing_distant, route, stop, train_protection, other
};
const char* to_string(SignalCategory c);

struct SignalKey {
    SignalCategory category = SignalCategory::other;
    std::string property; // "" for the category key itself, else "form", "states", ...
};
// "railway:signal:main" -> {main, ""}; "railway:signal:main:form" -> {main, "form"}.
// Keys describing the signal as a whole (direction, position, ref) are not
// categories and come back unparsed; unknown categories become `other` with a note.
TagValue<SignalKey> parse_signal_key(std::string_view key);

struct SignalSystem {
    std::string country; // "DE"
    std::string body;    // "ESO" (operator or rule book)
    std::string name;    // "ks"
};
// The value of a category key: "DE-ESO:ks", "AT-ÖBB:hauptsignal".
TagValue<SignalSystem> parse_signal_system(std::string_view text);

enum class SignalForm { light, semaphore, sign };
const char* to_string(SignalForm f);
TagValue<SignalForm> parse_signal_form(std::string_view text);

} // namespace railodd::odd
