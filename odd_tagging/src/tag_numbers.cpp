// Numeric OSM tag values: maxspeed, voltage, frequency, gauge, railway:position
// and booleans. Rules and their reasons: docs/odd.md "Tag values".
#include "railodd/odd/tag_values.hpp"

#include "text.hpp"

#include <algorithm>
#include <cctype>
#include <regex>

namespace railodd::odd {

using text::quoted;

namespace {

constexpr double km_per_mile = 1.609344; // also km/h per mph
constexpr double kmh_per_knot = 1.852;

// One maxspeed value without ';'.
MaxSpeed single_maxspeed(std::string_view s) {
    MaxSpeed r;
    const auto low = text::lower(s);
    if (low == "signals") {
        r.kind = SpeedLimitKind::signals;
        r.problem = "limit shown by signals (maxspeed=signals): no fixed number";
        return r;
    }
    if (low == "none") {
        r.kind = SpeedLimitKind::none;
        r.problem = "no limit posted (maxspeed=none)";
        return r;
    }
    if (low == "walk") {
        r.problem = "walking pace (maxspeed=walk) carries no number";
        return r;
    }
    // Country zone codes ("DE:urban", "AT:rural", "GB:nsl_single") are road
    // speed zones; they imply nothing about a track's line speed.
    static const std::regex zone{R"(^[A-Za-z]{2}(-[A-Za-z0-9]+)?:[A-Za-z0-9_]+$)"};
    if (std::regex_match(low, zone)) {
        r.problem = "country speed zone " + quoted(s) + " is a road zone code; no railway speed is derived from it";
        return r;
    }
    const auto [num, unit] = text::number_and_unit(s);
    if (num.find(',') != std::string_view::npos) {
        r.problem = quoted(s) + ": ',' is ambiguous (decimal comma or list); OSM uses '.' and ';'";
        return r;
    }
    auto value = text::strict_number(num);
    if (!value) {
        r.problem = quoted(s) + " is not a number with an optional unit (km/h, mph, knots)";
        return r;
    }
    const auto u = text::lower(unit);
    if (u == "mph") {
        r.note = "converted " + text::format(*value) + " mph to km/h";
        *value *= km_per_mile;
    } else if (u == "knots" || u == "kn") {
        r.note = "converted " + text::format(*value) + " knots to km/h";
        *value *= kmh_per_knot;
    } else if (!(u.empty() || u == "km/h" || u == "kmh" || u == "kph")) {
        r.problem = quoted(s) + ": unknown unit " + quoted(unit) + " (expected km/h, mph or knots)";
        return r;
    }
    if (*value <= 0.0 || *value > 1000.0) {
        r.problem = quoted(s) + " is not a plausible speed (0 < v <= 1000 km/h)";
        return r;
    }
    r.kmh = *value;
    r.kind = SpeedLimitKind::posted;
    return r;
}

// Applies `one` to every ';'-separated part; all must parse.
template <class One>
TagValue<std::vector<double>> list_of(std::string_view text, const char* what, One one) {
    TagValue<std::vector<double>> r;
    const auto t = text::trim(text);
    if (t.empty()) {
        r.problem = std::string("empty ") + what;
        return r;
    }
    std::vector<double> values;
    for (const auto part : text::split(t, ';')) {
        TagValue<double> v = one(part);
        if (!v.ok()) {
            r.problem = v.problem;
            return r;
        }
        if (!v.note.empty()) {
            r.note += (r.note.empty() ? "" : "; ") + v.note;
        }
        values.push_back(*v.value);
    }
    r.value = std::move(values);
    return r;
}

TagValue<double> fail(std::string problem) {
    TagValue<double> r;
    r.problem = std::move(problem);
    return r;
}

TagValue<double> pass(double v, std::string note = {}) {
    TagValue<double> r;
    r.value = v;
    r.note = std::move(note);
    return r;
}

} // namespace

const char* to_string(SpeedLimitKind kind) {
    switch (kind) {
    case SpeedLimitKind::posted: return "posted";
    case SpeedLimitKind::signals: return "signals";
    case SpeedLimitKind::none: return "none";
    case SpeedLimitKind::unknown: return "unknown";
    }
    return "unknown";
}

MaxSpeed parse_maxspeed(std::string_view raw) {
    const auto s = text::trim(raw);
    if (s.empty()) {
        MaxSpeed r;
        r.problem = "empty maxspeed";
        return r;
    }
    // "80-100": a range; the lower end is the safe reading for an ODD bound.
    static const std::regex range{R"(^(\d+(\.\d+)?)\s*-\s*(\d+(\.\d+)?)(\s*\S.*)?$)"};
    std::cmatch m;
    if (s.find(';') == std::string_view::npos && std::regex_match(s.begin(), s.end(), m, range)) {
        MaxSpeed low = single_maxspeed(m[1].str() + m[5].str());
        const MaxSpeed high = single_maxspeed(m[3].str() + m[5].str());
        if (low.ok() && high.ok()) {
            low.kmh = std::min(*low.kmh, *high.kmh);
            low.note = "range " + quoted(s) + ": took the lower end" + (low.note.empty() ? "" : "; " + low.note);
        }
        return low;
    }
    const auto parts = text::split(s, ';');
    if (parts.size() == 1) {
        return single_maxspeed(s);
    }
    // "60;80": per-direction or conditional values; the lowest is the one every
    // train may rely on, so the ODD is judged against it.
    MaxSpeed out;
    for (const auto part : parts) {
        MaxSpeed p = single_maxspeed(part);
        if (!p.ok()) {
            p.problem = "part " + quoted(part) + " of " + quoted(s) + ": " + p.problem;
            return p;
        }
        if (!out.kmh || *p.kmh < *out.kmh) {
            out.kmh = p.kmh;
        }
    }
    out.kind = SpeedLimitKind::posted;
    out.note = "several values " + quoted(s) + ": took the lowest";
    return out;
}

TagValue<std::vector<double>> parse_voltage(std::string_view raw) {
    return list_of(raw, "voltage", [](std::string_view s) {
        const auto [num, unit] = text::number_and_unit(s);
        const auto v = text::strict_number(num);
        const auto u = text::lower(unit);
        if (!v || *v < 0) {
            return fail(quoted(s) + " is not a voltage in volts");
        }
        if (u == "kv") {
            return pass(*v * 1000.0, "read " + quoted(s) + " as " + text::format(*v * 1000.0) + " V (OSM voltage is in volts)");
        }
        if (!(u.empty() || u == "v")) {
            return fail(quoted(s) + ": unknown unit " + quoted(unit) + " (expected V)");
        }
        // Traction voltages start at a few hundred volts; "15" is almost
        // certainly kV, but guessing would hide a tagging error.
        if (*v > 0 && *v < 100) {
            return fail(quoted(s) + " V is implausible for traction (kV written without unit?)");
        }
        return pass(*v);
    });
}

TagValue<std::vector<double>> parse_frequency(std::string_view raw) {
    return list_of(raw, "frequency", [](std::string_view s) {
        auto [num, unit] = text::number_and_unit(s);
        std::string n(num);
        std::string note;
        // A frequency has no thousands separator, so "16,7" can only mean 16.7.
        if (const auto comma = n.find(','); comma != std::string::npos) {
            n[comma] = '.';
            note = "read decimal comma in " + quoted(s);
        }
        const auto v = text::strict_number(n);
        const auto u = text::lower(unit);
        if (!v || !(u.empty() || u == "hz")) {
            return fail(quoted(s) + " is not a frequency in Hz");
        }
        if (*v < 0 || *v > 100) {
            return fail(quoted(s) + " Hz is implausible for traction (0 for DC, 16.7, 50 or 60)");
        }
        return pass(*v, note);
    });
}

TagValue<std::vector<double>> parse_gauge(std::string_view raw) {
    return list_of(raw, "gauge", [](std::string_view s) {
        const auto low = text::lower(s);
        if (low == "standard") {
            return pass(1435.0, "read 'standard' as 1435 mm");
        }
        const auto [num, unit] = text::number_and_unit(s);
        const auto v = text::strict_number(num);
        if (!v || !(unit.empty() || text::lower(unit) == "mm")) {
            return fail(quoted(s) + " is not a gauge in millimetres (words other than 'standard' name no width)");
        }
        if (*v < 300 || *v > 2000) {
            return fail(quoted(s) + " mm is implausible for a track gauge");
        }
        return pass(*v);
    });
}

TagValue<double> parse_railway_position(std::string_view raw) {
    auto s = text::trim(raw);
    std::string note;
    double scale = 1.0; // to km
    const auto low = text::lower(s);
    if (low.starts_with("mi:")) {
        scale = km_per_mile;
        s = text::trim(s.substr(3));
        note = "converted miles to km";
    } else if (low.starts_with("km")) {
        s = text::trim(s.substr(2));
        note = "dropped 'km' prefix";
    }
    std::string t(s);
    // German kilometrage writes a decimal comma; positions have no thousands separators.
    if (const auto comma = t.find(','); comma != std::string::npos && t.find(',', comma + 1) == std::string::npos) {
        t[comma] = '.';
        note += (note.empty() ? "" : "; ") + std::string("read decimal comma");
    }
    // "12.3+45": 12.3 km plus 45 m, where a section is longer than its nominal
    // length (overlength after a realignment).
    double extra_m = 0.0;
    if (const auto plus = t.find('+'); plus != std::string::npos && plus > 0) {
        const auto m = text::strict_number(std::string_view(t).substr(plus + 1));
        if (!m || *m < 0) {
            return fail(quoted(raw) + ": the part after '+' must be metres");
        }
        extra_m = *m;
        t.resize(plus);
        note += (note.empty() ? "" : "; ") + std::string("overlength notation: added ") + text::format(extra_m) + " m";
    }
    const auto km = text::strict_number(text::trim(t));
    if (!km) {
        return fail(quoted(raw) + " is not a kilometrage (e.g. 12.345, 12,345, 12.3+45, mi:7.5)");
    }
    return pass(*km * scale + extra_m / 1000.0, note);
}

TagValue<bool> parse_bool(std::string_view raw) {
    TagValue<bool> r;
    const auto low = text::lower(text::trim(raw));
    if (low == "yes" || low == "true" || low == "1") {
        r.value = true;
    } else if (low == "no" || low == "false" || low == "0") {
        r.value = false;
    } else {
        r.problem = quoted(raw) + " is not yes/no/true/false/1/0";
    }
    return r;
}

} // namespace railodd::odd
