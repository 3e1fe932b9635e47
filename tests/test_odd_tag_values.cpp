// OSM tag value parsers: plain values, the odd ones seen in OSM data, and the
// reasons given for values that cannot be read.
#include "railodd/odd/tag_values.hpp"

#include <gtest/gtest.h>

using namespace railodd::odd;

namespace {

std::vector<double> numbers(const TagValue<std::vector<double>>& v) {
    EXPECT_TRUE(v.ok()) << v.problem;
    return v.value.value_or(std::vector<double>{});
}

} // namespace

TEST(OddTagValues, MaxspeedPlainAndWithUnits) {
    for (const auto* text : {"80", " 80 ", "80 km/h", "80km/h", "80 kmh", "80 kph"}) {
        const auto s = parse_maxspeed(text);
        ASSERT_TRUE(s.ok()) << text << ": " << s.problem;
        EXPECT_DOUBLE_EQ(*s.kmh, 80.0) << text;
        EXPECT_EQ(s.kind, SpeedLimitKind::posted);
        EXPECT_TRUE(s.note.empty()) << text;
    }
    EXPECT_DOUBLE_EQ(*parse_maxspeed("12.5").kmh, 12.5);
}

TEST(OddTagValues, MaxspeedConvertsMphAndKnotsWithANote) {
    const auto mph = parse_maxspeed("50 mph");
    ASSERT_TRUE(mph.ok());
    EXPECT_NEAR(*mph.kmh, 80.4672, 1e-9);
    EXPECT_NE(mph.note.find("mph"), std::string::npos);
    EXPECT_NEAR(*parse_maxspeed("10 knots").kmh, 18.52, 1e-9);
}

TEST(OddTagValues, MaxspeedListsAndRangesTakeTheLowest) {
    const auto list = parse_maxspeed("60;80");
    ASSERT_TRUE(list.ok());
    EXPECT_DOUBLE_EQ(*list.kmh, 60.0);
    EXPECT_NE(list.note.find("lowest"), std::string::npos);
    EXPECT_DOUBLE_EQ(*parse_maxspeed("100;40 mph").kmh, 40 * 1.609344);

    const auto range = parse_maxspeed("80-100");
    ASSERT_TRUE(range.ok());
    EXPECT_DOUBLE_EQ(*range.kmh, 80.0);
    EXPECT_NE(range.note.find("lower end"), std::string::npos);
    EXPECT_NEAR(*parse_maxspeed("30 - 50 mph").kmh, 30 * 1.609344, 1e-9);
}

TEST(OddTagValues, MaxspeedWithoutANumberGivesKindAndReason) {
    const auto signals = parse_maxspeed("signals");
    EXPECT_FALSE(signals.ok());
    EXPECT_EQ(signals.kind, SpeedLimitKind::signals);
    EXPECT_NE(signals.problem.find("signals"), std::string::npos);

    const auto none = parse_maxspeed("none");
    EXPECT_FALSE(none.ok());
    EXPECT_EQ(none.kind, SpeedLimitKind::none);

    const auto walk = parse_maxspeed("walk");
    EXPECT_FALSE(walk.ok());
    EXPECT_EQ(walk.kind, SpeedLimitKind::unknown);
    EXPECT_NE(walk.problem.find("walk"), std::string::npos);

    for (const auto* zone : {"DE:urban", "AT:rural", "GB:nsl_single", "RU:living_street"}) {
        const auto z = parse_maxspeed(zone);
        EXPECT_FALSE(z.ok()) << zone;
        EXPECT_NE(z.problem.find("zone"), std::string::npos) << z.problem;
    }
}

TEST(OddTagValues, MaxspeedOddValuesAreUnparsedWithAReason) {
    for (const auto* text : {"", "fast", "80,5", "0", "-20", "5000", "80 m/s", "80;signals", "1e2", "80."}) {
        const auto s = parse_maxspeed(text);
        EXPECT_FALSE(s.ok()) << "'" << text << "' gave " << s.kmh.value_or(-1);
        EXPECT_FALSE(s.problem.empty()) << text;
    }
    EXPECT_NE(parse_maxspeed("80,5").problem.find("ambiguous"), std::string::npos);
    EXPECT_NE(parse_maxspeed("80;signals").problem.find("part 'signals'"), std::string::npos);
}

TEST(OddTagValues, Voltage) {
    EXPECT_EQ(numbers(parse_voltage("15000")), (std::vector<double>{15000}));
    EXPECT_EQ(numbers(parse_voltage("15000;25000")), (std::vector<double>{15000, 25000}));
    EXPECT_EQ(numbers(parse_voltage("750 V")), (std::vector<double>{750}));
    EXPECT_EQ(numbers(parse_voltage("0")), (std::vector<double>{0}));
    const auto kv = parse_voltage("15 kV");
    EXPECT_EQ(numbers(kv), (std::vector<double>{15000}));
    EXPECT_NE(kv.note.find("volts"), std::string::npos);
    for (const auto* bad : {"", "15", "high", "15000;", "-750", "15000 A"}) {
        const auto v = parse_voltage(bad);
        EXPECT_FALSE(v.ok()) << bad;
        EXPECT_FALSE(v.problem.empty()) << bad;
    }
    EXPECT_NE(parse_voltage("15").problem.find("kV"), std::string::npos);
}

TEST(OddTagValues, Frequency) {
    EXPECT_EQ(numbers(parse_frequency("16.7")), (std::vector<double>{16.7}));
    EXPECT_EQ(numbers(parse_frequency("0")), (std::vector<double>{0}));
    EXPECT_EQ(numbers(parse_frequency("50 Hz")), (std::vector<double>{50}));
    EXPECT_EQ(numbers(parse_frequency("16.7;50")), (std::vector<double>{16.7, 50}));
    const auto comma = parse_frequency("16,7");
    EXPECT_EQ(numbers(comma), (std::vector<double>{16.7}));
    EXPECT_NE(comma.note.find("comma"), std::string::npos);
    for (const auto* bad : {"", "ac", "16 2/3", "500", "-50"}) {
        EXPECT_FALSE(parse_frequency(bad).ok()) << bad;
    }
}

TEST(OddTagValues, Gauge) {
    EXPECT_EQ(numbers(parse_gauge("1435")), (std::vector<double>{1435}));
    EXPECT_EQ(numbers(parse_gauge("1435;1000")), (std::vector<double>{1435, 1000}));
    EXPECT_EQ(numbers(parse_gauge("1000 mm")), (std::vector<double>{1000}));
    const auto standard = parse_gauge("standard");
    EXPECT_EQ(numbers(standard), (std::vector<double>{1435}));
    EXPECT_NE(standard.note.find("standard"), std::string::npos);
    for (const auto* bad : {"", "narrow", "broad", "1,435", "14350", "1.435 m"}) {
        const auto g = parse_gauge(bad);
        EXPECT_FALSE(g.ok()) << bad;
        EXPECT_FALSE(g.problem.empty()) << bad;
    }
}

TEST(OddTagValues, RailwayPosition) {
    EXPECT_DOUBLE_EQ(*parse_railway_position("12.345").value, 12.345);
    EXPECT_DOUBLE_EQ(*parse_railway_position("-0.4").value, -0.4);
    const auto comma = parse_railway_position("12,345");
    EXPECT_DOUBLE_EQ(*comma.value, 12.345);
    EXPECT_NE(comma.note.find("comma"), std::string::npos);
    const auto overlength = parse_railway_position("12.3+45");
    ASSERT_TRUE(overlength.ok()) << overlength.problem;
    EXPECT_NEAR(*overlength.value, 12.345, 1e-12);
    EXPECT_NE(overlength.note.find("overlength"), std::string::npos);
    EXPECT_NEAR(*parse_railway_position("12,3+45").value, 12.345, 1e-12);
    EXPECT_DOUBLE_EQ(*parse_railway_position("km 12.3").value, 12.3);
    EXPECT_DOUBLE_EQ(*parse_railway_position("KM12.3").value, 12.3);
    EXPECT_NEAR(*parse_railway_position("mi:7.5").value, 7.5 * 1.609344, 1e-12);
    for (const auto* bad : {"", "km", "12.3.4", "12,3,4", "12.3+", "12.3+abc", "twelve", "12.3 km"}) {
        const auto p = parse_railway_position(bad);
        EXPECT_FALSE(p.ok()) << bad << " gave " << p.value.value_or(-1);
        EXPECT_FALSE(p.problem.empty()) << bad;
    }
}

TEST(OddTagValues, Booleans) {
    for (const auto* t : {"yes", "true", "1", "YES", " Yes "}) {
        EXPECT_EQ(parse_bool(t).value, true) << t;
    }
    for (const auto* f : {"no", "false", "0", "No"}) {
        EXPECT_EQ(parse_bool(f).value, false) << f;
    }
    for (const auto* bad : {"", "unknown", "2", "yes;no"}) {
        EXPECT_FALSE(parse_bool(bad).ok()) << bad;
    }
}

TEST(OddTagValues, Electrified) {
    EXPECT_EQ(parse_electrified("contact_line").value, (std::vector{Electrification::contact_line}));
    EXPECT_EQ(parse_electrified("4th_rail").value, (std::vector{Electrification::fourth_rail}));
    EXPECT_EQ(parse_electrified("ground-level_power_supply").value, (std::vector{Electrification::ground_level}));
    EXPECT_EQ(parse_electrified("yes").value, (std::vector{Electrification::unspecified}));
    EXPECT_EQ(parse_electrified("no").value, (std::vector{Electrification::none}));
    EXPECT_EQ(parse_electrified("contact_line;rail").value,
              (std::vector{Electrification::contact_line, Electrification::rail}));
    EXPECT_EQ(std::string(to_string(Electrification::fourth_rail)), "fourth_rail");
    for (const auto* bad : {"", "overhead", "no;rail", "contact_line;"}) {
        const auto e = parse_electrified(bad);
        EXPECT_FALSE(e.ok()) << bad;
        EXPECT_FALSE(e.problem.empty()) << bad;
    }
}

TEST(OddTagValues, UsageServiceAndDirection) {
    EXPECT_EQ(parse_usage("main").value, Usage::main);
    EXPECT_EQ(parse_usage("tourism").value, Usage::tourism);
    const auto cased = parse_usage("Branch");
    EXPECT_EQ(cased.value, Usage::branch);
    EXPECT_FALSE(cased.note.empty());
    EXPECT_FALSE(parse_usage("freight").ok());
    EXPECT_NE(parse_usage("freight").problem.find("main, branch"), std::string::npos);

    EXPECT_EQ(parse_service("siding").value, Service::siding);
    EXPECT_EQ(parse_service("crossover").value, Service::crossover);
    EXPECT_FALSE(parse_service("").ok());
    EXPECT_FALSE(parse_service("driveway").ok());

    EXPECT_EQ(parse_preferred_direction("forward").value, PreferredDirection::forward);
    EXPECT_EQ(parse_preferred_direction("both").value, PreferredDirection::both);
    EXPECT_FALSE(parse_preferred_direction("up").ok());
}

TEST(OddTagValues, TrainRadio) {
    EXPECT_EQ(parse_train_radio("gsm-r").value, (std::vector{TrainRadio::gsm_r}));
    EXPECT_EQ(parse_train_radio("analogue").value, (std::vector{TrainRadio::analogue}));
    EXPECT_EQ(parse_train_radio("no").value, (std::vector{TrainRadio::none}));
    EXPECT_EQ(parse_train_radio("gsm-r;analogue").value, (std::vector{TrainRadio::gsm_r, TrainRadio::analogue}));
    const auto us = parse_train_radio("analog");
    EXPECT_EQ(us.value, (std::vector{TrainRadio::analogue}));
    EXPECT_NE(us.note.find("analog"), std::string::npos);
    const auto cased = parse_train_radio("GSM-R");
    EXPECT_EQ(cased.value, (std::vector{TrainRadio::gsm_r}));
    EXPECT_FALSE(cased.note.empty());
    EXPECT_EQ(std::string(to_string(TrainRadio::gsm_r)), "gsm-r");
    for (const auto* bad : {"", "yes", "tetra", "gsm-r;", "no;gsm-r"}) {
        const auto r = parse_train_radio(bad);
        EXPECT_FALSE(r.ok()) << bad;
        EXPECT_FALSE(r.problem.empty()) << bad;
    }
}

TEST(OddTagValues, CrossingBarrier) {
    EXPECT_EQ(parse_crossing_barrier("full").value, Barrier::full);
    EXPECT_EQ(parse_crossing_barrier("double_half").value, Barrier::double_half);
    EXPECT_EQ(parse_crossing_barrier("no").value, Barrier::no);
    EXPECT_EQ(parse_crossing_barrier("gate").value, Barrier::gate);
    for (const auto* bad : {"", "gates", "half;full", "boom"}) {
        EXPECT_FALSE(parse_crossing_barrier(bad).ok()) << bad;
    }
}

TEST(OddTagValues, SignalKeys) {
    const auto main = parse_signal_key("railway:signal:main");
    ASSERT_TRUE(main.ok());
    EXPECT_EQ(main.value->category, SignalCategory::main);
    EXPECT_EQ(main.value->property, "");
    const auto form = parse_signal_key("railway:signal:speed_limit_distant:form");
    ASSERT_TRUE(form.ok());
    EXPECT_EQ(form.value->category, SignalCategory::speed_limit_distant);
    EXPECT_EQ(form.value->property, "form");
    const auto ring = parse_signal_key("railway:signal:ring");
    ASSERT_TRUE(ring.ok());
    EXPECT_EQ(ring.value->category, SignalCategory::other);
    EXPECT_NE(ring.note.find("ring"), std::string::npos);
    for (const auto* bad : {"railway:signal:direction", "railway:signal:position", "railway:signal:", "railway", "signal:main"}) {
        EXPECT_FALSE(parse_signal_key(bad).ok()) << bad;
    }
}

TEST(OddTagValues, SignalSystemAndForm) {
    const auto ks = parse_signal_system("DE-ESO:ks");
    ASSERT_TRUE(ks.ok());
    EXPECT_EQ(ks.value->country, "DE");
    EXPECT_EQ(ks.value->body, "ESO");
    EXPECT_EQ(ks.value->name, "ks");
    EXPECT_EQ(parse_signal_system("AT-ÖBB:hauptsignal").value->body, "ÖBB");
    for (const auto* bad : {"", "ks", "DE:ks", "-ESO:ks", "DE-:ks", "DE-ESO:"}) {
        EXPECT_FALSE(parse_signal_system(bad).ok()) << bad;
    }
    EXPECT_EQ(parse_signal_form("semaphore").value, SignalForm::semaphore);
    EXPECT_FALSE(parse_signal_form("led").ok());
}
