// odd_profile.json / .geojson / .csv and the summary: round trip, geometry
// types and lon/lat order, RFC 4180 quoting, km per class.
#include "railodd/odd/profile.hpp"
#include "railodd/odd/profile_summary.hpp"
#include "railodd/util/errors.hpp"

#include "odd_profile_support.hpp"
#include "test_support.hpp"

#include <gtest/gtest.h>

using namespace railodd::odd;
using namespace railodd::test;

namespace {

std::string to_geojson(const OddProfile& p) { return profile_files_of(p).geojson; }
std::string to_csv(const OddProfile& p) { return profile_files_of(p).csv; }

} // namespace

namespace {

const Taxonomy& taxonomy() {
    static const Taxonomy t = load_taxonomy(fs::path{RAILODD_SOURCE_DIR} / "data/odd/railway_odd.yaml");
    return t;
}

void expect_same(const TaggedElement& a, const TaggedElement& b) {
    EXPECT_EQ(a.element, b.element);
    EXPECT_EQ(a.element_id, b.element_id);
    ASSERT_EQ(a.attributes.size(), b.attributes.size()) << a.element;
    for (std::size_t i = 0; i < a.attributes.size(); ++i) {
        EXPECT_EQ(a.attributes[i].name, b.attributes[i].name);
        EXPECT_EQ(a.attributes[i].value, b.attributes[i].value) << a.attributes[i].name;
    }
    EXPECT_EQ(a.road_id, b.road_id);
    EXPECT_EQ(a.s_start, b.s_start);
    EXPECT_EQ(a.s_end, b.s_end);
    EXPECT_EQ(a.track, b.track);
    EXPECT_EQ(a.chainage_start, b.chainage_start);
    EXPECT_EQ(a.chainage_end, b.chainage_end);
    EXPECT_EQ(a.point, b.point);
    EXPECT_EQ(a.osm_ids, b.osm_ids);
    EXPECT_EQ(a.source, b.source);
}

// Escapes, UTF-8, number forms and a repeated attribute name (first place,
// last value): what a directly printed line must still get right.
void make_awkward(TaggedElement& e) {
    e.attributes = {{"name", std::string{"K\xc3\xb6ln \"Hbf\"\\ \t\x01"}}, {"radius", 1e-5}, {"big", 1.5e300},
                    {"name", std::string{"Deutz"}}, {"flag", true}, {"zero", -0.0}};
    e.osm_ids = {"way:1", "node:\xe2\x82\xac"};
    e.s_end = 123456789.125;
    e.track = 18446744073709551615ULL;
}

} // namespace

TEST(OddProfileIo, JsonRoundTripKeepsEverythingButGeometry) {
    OddProfile p = sample_profile();
    p.elements[0].s_end = 400.123456789; // written to the millimetre
    p.summary = {{"length_km", 1.6}, {"note", "kept"}};
    const auto text = to_json(p).dump(1);
    const OddProfile q = profile_from_json(nlohmann::ordered_json::parse(text));
    EXPECT_EQ(q.taxonomy_name, p.taxonomy_name);
    EXPECT_EQ(q.taxonomy_version, p.taxonomy_version);
    EXPECT_EQ(q.route, p.route);
    EXPECT_EQ(q.length_m, p.length_m);
    EXPECT_EQ(q.tracks, p.tracks);
    ASSERT_EQ(q.elements.size(), p.elements.size());
    EXPECT_EQ(q.elements[0].s_end, 400.123);
    p.elements[0].s_end = 400.123;
    for (std::size_t i = 0; i < p.elements.size(); ++i) {
        expect_same(q.elements[i], p.elements[i]);
    }
    ASSERT_EQ(q.unparsed.size(), 1u);
    EXPECT_EQ(q.unparsed[0].value, "DE:urban");
    EXPECT_EQ(q.summary["note"], "kept");
    // Attribute values keep their JSON type; key order is fixed.
    const auto j = nlohmann::ordered_json::parse(text);
    EXPECT_TRUE(j["elements"][0][9]["gradient"].is_number());
    EXPECT_TRUE(j["elements"][6][9]["lights"].is_boolean());
    EXPECT_EQ(j.begin().key(), "railodd");
    EXPECT_EQ(j["railodd"]["format_version"], 2);
    EXPECT_EQ(to_json(q).dump(1), text); // byte-identical when written again
}

TEST(OddProfileIo, StreamedTextIsTheSameDocumentAsTheTree) {
    OddProfile p = sample_profile();
    p.unparsed.push_back({{"way:7"}, "maxspeed", "walk", "not a number"});
    p.summary = {{"length_km", 1.5}};
    EXPECT_EQ(nlohmann::ordered_json::parse(to_json_text(p)), to_json(p));
    p.elements.clear();
    p.unparsed.clear();
    EXPECT_EQ(nlohmann::ordered_json::parse(to_json_text(p)), to_json(p)) << "empty lists stay valid JSON";
}

TEST(OddProfileIo, JsonElementLinesAreCompactJsonDumps) {
    // The elements are printed directly, not through json objects: every
    // line must still be the tree's compact dump, escapes, repeated
    // attribute names, number formats and optional keys included.
    OddProfile p = sample_profile();
    p.elements.resize(3);
    TaggedElement& e = p.elements[1];
    make_awkward(e);
    e.point = true;
    e.reversed = true;
    p.elements[2].osm_ids.clear();
    const std::string text = to_json_text(p);
    const nlohmann::ordered_json tree = to_json(p);
    for (std::size_t i = 0; i < p.elements.size(); ++i) {
        const std::string line = "\n  " + tree["elements"][i].dump() + (i + 1 < p.elements.size() ? ",\n" : "\n");
        EXPECT_NE(text.find(line), std::string::npos) << line << text;
    }
    EXPECT_NE(text.find(R"(,["point","reversed"]])"), std::string::npos);
    e.element_id = std::string{"sc.\xff"}; // not UTF-8: refused as dump() refuses it
    EXPECT_THROW(to_json_text(p), nlohmann::json::type_error);
}

TEST(OddProfileIo, ReadingNamesTheFileAndTheMissingKey) {
    const auto dir = scratch_dir();
    auto j = nlohmann::json::parse(to_json(sample_profile()).dump());
    j["elements"][2][3] = "a hundred";
    const auto file = write_file(dir / "odd_profile.json", j.dump());
    try {
        read_profile(file);
        ADD_FAILURE() << "accepted";
    } catch (const railodd::InputError& e) {
        EXPECT_NE(std::string{e.what()}.find(file.string()), std::string::npos) << e.what();
        EXPECT_NE(std::string{e.what()}.find("elements[2].s_start: wrong type (string)"), std::string::npos)
            << e.what();
    }
    EXPECT_THROW(read_profile(write_file(dir / "bad.json", "{\"elements\": [")), railodd::InputError);
    EXPECT_THROW(read_profile(dir / "absent.json"), railodd::InputError);
    const auto good = write_file(dir / "good.json", to_json(sample_profile()).dump());
    EXPECT_EQ(read_profile(good).elements.size(), 8u);
}

TEST(OddProfileIo, GeoJsonHasPointsLinesAndLonLatOrder) {
    OddProfile p = sample_profile();
    p.elements[3].lonlat = {{8.12345678912, 50.98765432101}};
    const auto j = nlohmann::json::parse(to_geojson(p));
    EXPECT_EQ(j["type"], "FeatureCollection");
    ASSERT_EQ(j["features"].size(), p.elements.size());
    const auto& crossing = j["features"][3];
    EXPECT_EQ(crossing["geometry"]["type"], "Point");
    EXPECT_DOUBLE_EQ(crossing["geometry"]["coordinates"][0].get<double>(), 8.1234568); // lon first, 7 decimals
    EXPECT_DOUBLE_EQ(crossing["geometry"]["coordinates"][1].get<double>(), 50.9876543);
    EXPECT_EQ(crossing["properties"]["odd_element"], "Scenery/Crossings/Level crossing");
    EXPECT_EQ(crossing["properties"]["attributes"]["barrier"], "no");
    EXPECT_EQ(crossing["properties"]["osm_ids"][0], "node:5");
    const auto& curve = j["features"][2];
    EXPECT_EQ(curve["geometry"]["type"], "LineString");
    EXPECT_EQ(curve["geometry"]["coordinates"].size(), 2u);
    EXPECT_EQ(curve["properties"]["attributes"]["radius"], 250.0);
    EXPECT_EQ(curve["properties"]["road_id"], "12");
    EXPECT_EQ(curve["properties"]["chainage_end"], 350.0);
    p.elements[0].lonlat.clear();
    EXPECT_TRUE(nlohmann::json::parse(to_geojson(p))["features"][0]["geometry"].is_null());
}

// Each feature line is printed directly, not through json objects: it must be
// the bytes nlohmann's dump() gives for the same feature, escapes, UTF-8,
// number forms and a repeated attribute name (first place, last value)
// included.
TEST(OddProfileIo, GeoJsonFeatureLinesAreCompactJsonDumps) {
    OddProfile p = sample_profile();
    p.elements.resize(2);
    TaggedElement& e = p.elements[1];
    make_awkward(e);
    e.lonlat = {{-0.000000049, 89.99999999}, {179.9999999, -12.5}};
    nlohmann::ordered_json attrs = nlohmann::ordered_json::object();
    for (const auto& a : e.attributes) {
        attrs[a.name] = std::visit([](const auto& v) { return nlohmann::ordered_json(v); }, a.value);
    }
    nlohmann::ordered_json props;
    props["odd_element"] = e.element;
    props["element_id"] = e.element_id;
    props["attributes"] = attrs;
    props["road_id"] = e.road_id;
    props["track"] = e.track;
    props["s_start"] = e.s_start;
    props["s_end"] = e.s_end;
    props["chainage_start"] = e.chainage_start;
    props["chainage_end"] = e.chainage_end;
    props["osm_ids"] = e.osm_ids;
    props["source"] = e.source;
    const nlohmann::ordered_json geometry = {
        {"type", "LineString"},
        {"coordinates", {{std::round(-0.000000049 * 1e7) / 1e7, std::round(89.99999999 * 1e7) / 1e7},
                         {std::round(179.9999999 * 1e7) / 1e7, -12.5}}}};
    const nlohmann::ordered_json feature = {{"type", "Feature"}, {"geometry", geometry}, {"properties", props}};
    const std::string text = to_geojson(p);
    const std::string expected = feature.dump();
    EXPECT_NE(text.find("\n" + expected + "\n]}"), std::string::npos) << text;
    EXPECT_NE(expected.find(R"("name":"Deutz")"), std::string::npos) << expected;
    e.osm_ids = {std::string{"way:\xff"}}; // not UTF-8: refused as dump() refuses it
    EXPECT_THROW(to_geojson(p), nlohmann::json::type_error);
}

TEST(OddProfileIo, CsvQuotesCommasAndQuotes) {
    OddProfile p = sample_profile();
    p.elements.resize(4);
    p.elements[3].attributes.push_back({"system", std::string{"DE-ESO:ks, \"hl\""}});
    const auto csv = to_csv(p);
    EXPECT_EQ(csv.substr(0, csv.find("\r\n")),
              "odd_element,element_id,road_id,s_start,s_end,chainage_start,chainage_end,track,point,attributes,"
              "osm_ids,source");
    EXPECT_NE(csv.find("Scenery/Track geometry/Horizontal/Curve,sc.geo.hz.curve,12,100.000,350.000,100.000,"
                       "350.000,0,false,radius=250;direction=left,way:1,derived\r\n"),
              std::string::npos)
        << csv;
    EXPECT_NE(csv.find(",true,\"barrier=no;system=DE-ESO:ks, \"\"hl\"\"\",node:5,osm\r\n"), std::string::npos) << csv;
    EXPECT_EQ(std::count(csv.begin(), csv.end(), '\n'), 5);
}

TEST(OddProfileSummary, KmPerClassAndCounts) {
    const auto s = summarize(sample_profile(), &taxonomy());
    EXPECT_DOUBLE_EQ(s["length_km"].get<double>(), 1.6);
    EXPECT_DOUBLE_EQ(s["curve_km_by_radius"]["tight"].get<double>(), 0.25);
    EXPECT_DOUBLE_EQ(s["curve_km_by_radius"]["medium"].get<double>(), 0.4);
    EXPECT_DOUBLE_EQ(s["curve_km_by_radius"]["wide"].get<double>(), 0.0);
    EXPECT_EQ(s["curve_km_by_radius"].begin().key(), "very tight"); // taxonomy bin order
    EXPECT_DOUBLE_EQ(s["gradient_km_by_class"]["very steep"].get<double>(), 0.4);
    EXPECT_DOUBLE_EQ(s["gradient_km_by_class"]["moderate"].get<double>(), 0.6);
    EXPECT_DOUBLE_EQ(s["speed_km_by_class"]["main line"].get<double>(), 1.0);
    EXPECT_EQ(s["level_crossings_by_barrier"]["no"], 1);
    EXPECT_EQ(s["level_crossings_by_barrier"]["full"], 1);
    EXPECT_EQ(s["stations"], 1);
    EXPECT_EQ(s["unparsed_values"], 1);

    const auto text = summary_text(sample_profile(), &taxonomy());
    EXPECT_NE(text.find("curves by radius class (km)"), std::string::npos) << text;
    EXPECT_NE(text.find("0.25\n"), std::string::npos) << text;
    EXPECT_NE(text.find("  tight "), std::string::npos) << text;
    // Without a taxonomy the stored summary is shown as it is.
    OddProfile stored = sample_profile();
    stored.summary = {{"curve_km_by_radius", {{"tight", 12.5}}}};
    const auto plain = summary_text(stored, nullptr);
    EXPECT_NE(plain.find("12.50"), std::string::npos) << plain;
}
