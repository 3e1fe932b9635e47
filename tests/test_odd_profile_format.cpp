// odd_profile.json format 2: element kinds listed once, elements as rows,
// chainage null where it equals s, flags only where set, positions to the
// millimetre; format 1 (one object per element) still read; malformed rows
// refused naming the element and the column.
#include "railodd/odd/profile.hpp"
#include "railodd/util/errors.hpp"

#include "odd_profile_support.hpp"
#include "test_support.hpp"

#include <gtest/gtest.h>

using namespace railodd::odd;
using namespace railodd::test;
using ojson = nlohmann::ordered_json;

namespace {

// Format 1 as earlier versions wrote it: every key of every element.
ojson format_one(const OddProfile& p) {
    ojson j = to_json(p);
    j["railodd"]["format_version"] = 1;
    j.erase("element_kinds");
    j.erase("element_columns");
    ojson elements = ojson::array();
    for (const auto& e : p.elements) {
        ojson attrs = ojson::object();
        for (const auto& a : e.attributes) {
            attrs[a.name] = std::visit([](const auto& v) { return ojson(v); }, a.value);
        }
        elements.push_back({{"odd_element", e.element}, {"id", e.element_id}, {"attributes", attrs},
                            {"road_id", e.road_id}, {"s_start", e.s_start}, {"s_end", e.s_end},
                            {"track", e.track}, {"chainage_start", e.chainage_start},
                            {"chainage_end", e.chainage_end}, {"point", e.point}, {"osm_ids", e.osm_ids},
                            {"source", e.source}});
        if (e.reversed) {
            elements.back()["reversed"] = true;
        }
    }
    j["elements"] = std::move(elements);
    return j;
}

std::string refusal(const ojson& j) {
    try {
        profile_from_json(j);
    } catch (const std::invalid_argument& e) {
        return e.what();
    }
    return "accepted";
}

} // namespace

TEST(OddProfileFormat, KindsOnceRowsAndDerivableValuesLeftOut) {
    OddProfile p = sample_profile();
    p.elements[2].reversed = true;
    p.elements[5].s_start = 0.0004; // rounds to 0, not -0 or 0.0004
    const ojson j = ojson::parse(to_json_text(p));
    // Five kinds for eight elements, in order of first use.
    ASSERT_EQ(j["element_kinds"].size(), 5u);
    EXPECT_EQ(j["element_kinds"][0], ojson::array({"Scenery/Track geometry/Vertical/Gradient", "sc.geo.vt.gradient"}));
    EXPECT_EQ(j["element_kinds"][2][1], "sc.geo.hz.curve");
    EXPECT_EQ(j["elements"][4][0], 2) << "the second curve names the kind of the first";
    // Chainage equal to s is null; the second road's is not.
    EXPECT_TRUE(j["elements"][0][5].is_null());
    EXPECT_TRUE(j["elements"][0][6].is_null());
    EXPECT_EQ(j["elements"][5][5], 1000.0);
    EXPECT_EQ(j["elements"][5][3].dump(), "0.0");
    // Flags only where one is set.
    EXPECT_EQ(j["elements"][0].size(), 10u);
    EXPECT_EQ(j["elements"][2][10], ojson::array({"reversed"}));
    EXPECT_EQ(j["elements"][3][10], ojson::array({"point"}));
    // Read back: every value restored.
    const OddProfile q = profile_from_json(j);
    ASSERT_EQ(q.elements.size(), 8u);
    EXPECT_EQ(q.elements[4].element, "Scenery/Track geometry/Horizontal/Curve");
    EXPECT_EQ(q.elements[0].chainage_end, 400.0);
    EXPECT_EQ(q.elements[5].chainage_start, 1000.0);
    EXPECT_EQ(q.elements[5].s_start, 0.0);
    EXPECT_TRUE(q.elements[2].reversed);
    EXPECT_FALSE(q.elements[2].point);
    EXPECT_TRUE(q.elements[3].point);
    EXPECT_EQ(q.elements[6].osm_ids, (std::vector<std::string>{"node:6", "way:7"}));
    EXPECT_EQ(std::get<bool>(*q.elements[6].find("lights")), true);
}

TEST(OddProfileFormat, PositionsToTheMillimetre) {
    OddProfile p = sample_profile();
    p.elements[1].s_end = 999.99951;         // rounds up across a metre
    p.elements[1].chainage_end = 999.99951;  // still equal to s: null
    p.elements[5].chainage_end = 1600.0004;  // differs from s (600.0) by the road's offset
    const ojson j = ojson::parse(to_json_text(p));
    EXPECT_EQ(j["elements"][1][4].dump(), "1000.0");
    EXPECT_TRUE(j["elements"][1][6].is_null());
    EXPECT_EQ(j["elements"][5][6].dump(), "1600.0");
    const std::string text = to_json_text(p);
    EXPECT_EQ(text.find("999.9995"), std::string::npos);
}

TEST(OddProfileFormat, FormatOneIsStillRead) {
    OddProfile p = sample_profile();
    p.elements[2].reversed = true;
    p.elements[0].s_end = 400.123456789; // format 1 kept full precision
    const OddProfile q = profile_from_json(ojson::parse(format_one(p).dump()));
    ASSERT_EQ(q.elements.size(), p.elements.size());
    for (std::size_t i = 0; i < p.elements.size(); ++i) {
        EXPECT_EQ(q.elements[i].element, p.elements[i].element);
        EXPECT_EQ(q.elements[i].chainage_start, p.elements[i].chainage_start);
        EXPECT_EQ(q.elements[i].point, p.elements[i].point);
        EXPECT_EQ(q.elements[i].reversed, p.elements[i].reversed);
    }
    EXPECT_EQ(q.elements[0].s_end, 400.123456789);
    // Written again, it is format 2, and the same profile once more.
    const OddProfile r = profile_from_json(ojson::parse(to_json_text(q)));
    EXPECT_EQ(r.elements[0].s_end, 400.123);
    EXPECT_EQ(r.elements[7].element_id, "sc.stn.station");
    auto missing = format_one(p);
    missing["elements"][2].erase("s_start");
    EXPECT_NE(refusal(missing).find("elements[2].s_start: missing"), std::string::npos) << refusal(missing);
}

TEST(OddProfileFormat, MalformedRowsAreRefusedNamingTheElementAndColumn) {
    const ojson good = to_json(sample_profile());
    auto expect_refused = [&](auto change, const std::string& message) {
        ojson j = good;
        change(j);
        const std::string what = refusal(j);
        EXPECT_NE(what.find(message), std::string::npos) << "got: " << what;
    };
    expect_refused([](ojson& j) { j["elements"][1][0] = 9u; }, "elements[1].kind: 9 is not an index of element_kinds (5 kinds)");
    expect_refused([](ojson& j) { j["elements"][1][0] = -1; }, "elements[1].kind: expected a count");
    expect_refused([](ojson& j) { j["elements"][4].erase(9); }, "elements[4]: expected a row of 10 or 11 values");
    expect_refused([](ojson& j) { j["elements"][3][10] = {"point", "sideways"}; },
                   "elements[3].flags: unknown flag sideways");
    expect_refused([](ojson& j) { j["elements"][0][9] = 5; }, "elements[0].attributes: expected an object");
    expect_refused([](ojson& j) { j["elements"][0][8] = "way:1"; }, "elements[0].osm_ids: wrong type (string)");
    expect_refused([](ojson& j) { j["element_kinds"][0] = {"only a path"}; }, "element_kinds[0]: expected [path, id]");
    expect_refused([](ojson& j) { j["element_columns"][3] = "start"; }, "element_columns[3]: expected \"s_start\"");
    expect_refused([](ojson& j) { j.erase("element_kinds"); }, "element_kinds: missing");
    expect_refused([](ojson& j) { j["railodd"]["format_version"] = 3; },
                   "railodd.format_version: 3 is not a format this railodd reads (1 to 2)");
    expect_refused([](ojson& j) { j["railodd"]["format"] = "scenario"; }, "railodd.format: expected \"odd_profile\"");
}

TEST(OddProfileFormat, ReadProfileNamesTheFile) {
    const auto dir = scratch_dir();
    auto j = to_json(sample_profile());
    j["elements"][6][7] = 3;
    const auto file = write_file(dir / "odd_profile.json", j.dump());
    try {
        read_profile(file);
        ADD_FAILURE() << "accepted";
    } catch (const railodd::InputError& e) {
        const std::string what = e.what();
        EXPECT_NE(what.find(file.string()), std::string::npos) << what;
        EXPECT_NE(what.find("elements[6].source: wrong type (number)"), std::string::npos) << what;
    }
}

// read_profile turns rows into elements while parsing; a file whose keys come
// in another order (elements before their kinds) is read from the whole tree.
// Both give what profile_from_json gives.
TEST(OddProfileFormat, StreamedReadingEqualsTheTreeInAnyKeyOrder) {
    OddProfile p = sample_profile();
    p.elements[2].reversed = true;
    p.summary = {{"length_km", 1.6}};
    const auto dir = scratch_dir();
    const std::string text = to_json_text(p);
    const OddProfile tree = profile_from_json(ojson::parse(text));
    ojson reordered = ojson::object();
    ojson doc = ojson::parse(text);
    for (const char* key : {"elements", "summary", "unparsed", "element_columns", "element_kinds", "route",
                            "taxonomy", "railodd"}) {
        reordered[key] = doc[key];
    }
    ojson v1 = format_one(p);
    for (const auto& [name, body] : {std::pair{"written.json", text}, std::pair{"reordered.json", reordered.dump()},
                                     std::pair{"format1.json", v1.dump(1)}}) {
        SCOPED_TRACE(name);
        const OddProfile q = read_profile(write_file(dir / name, body));
        EXPECT_EQ(to_json_text(q), to_json_text(tree));
    }
    // Kinds given again after the rows were read with the first ones: refused,
    // not read two ways (the tree would keep the last).
    std::string twice = text;
    twice.insert(twice.rfind('}'), R"(, "element_kinds": [["A/B", "a.b"]])");
    try {
        read_profile(write_file(dir / "twice.json", twice));
        ADD_FAILURE() << "accepted";
    } catch (const railodd::InputError& e) {
        EXPECT_NE(std::string{e.what()}.find("element_kinds: given again after the elements"), std::string::npos)
            << e.what();
    }
    // Errors in a streamed row still name the element, the column and the file.
    doc["elements"][5][4] = "far";
    const auto bad = write_file(dir / "bad.json", doc.dump());
    try {
        read_profile(bad);
        ADD_FAILURE() << "accepted";
    } catch (const railodd::InputError& e) {
        const std::string what = e.what();
        EXPECT_NE(what.find("bad.json"), std::string::npos) << what;
        EXPECT_NE(what.find("elements[5].s_end: wrong type (string)"), std::string::npos) << what;
    }
}
