#pragma once
// A small hand-made ODD profile shared by the profile, spec-check and CLI
// tests: two roads of one track with a tight and a medium curve, a 30 and a
// 10 permille gradient, an open and a full-barrier level crossing, a speed
// limit and a station. Elements in profile order (track, chainage, path).
#include "railodd/odd/profile.hpp"
#include "railodd/odd/profile_files.hpp"

#include <atomic>
#include <filesystem>
#include <sstream>
#include <string>

#include <unistd.h> // getpid: one scratch file per test process

namespace railodd::test {

// odd_profile.json, .geojson and .csv of a whole profile, as convert writes
// them (odd::ProfileFiles, the one writer), fed as one batch.
struct ProfileTexts {
    std::string json, geojson, csv;
};

inline ProfileTexts profile_files_of(const odd::OddProfile& p) {
    static std::atomic<int> n{0};
    const auto scratch = std::filesystem::temp_directory_path() /
                         ("railodd-profile-rows-" + std::to_string(::getpid()) + "-" + std::to_string(n++));
    std::ostringstream json, geojson, csv;
    {
        odd::ProfileFiles files(json, geojson, csv, scratch);
        odd::OddProfile head = p;
        head.elements.clear();
        std::deque<odd::TaggedElement> batch = p.elements;
        files.begin(head);
        files.add(batch);
        files.end(head);
    }
    return {json.str(), geojson.str(), csv.str()};
}

inline odd::TaggedElement tagged(std::string path, std::string id, std::vector<odd::TaggedAttribute> attrs,
                                 std::string road, double s0, double s1, double ch0, double ch1,
                                 std::vector<std::string> osm) {
    odd::TaggedElement e;
    e.element = std::move(path);
    e.element_id = std::move(id);
    e.attributes = std::move(attrs);
    e.road_id = std::move(road);
    e.s_start = s0;
    e.s_end = s1;
    e.track = 0;
    e.chainage_start = ch0;
    e.chainage_end = ch1;
    e.point = s0 == s1;
    e.osm_ids = std::move(osm);
    e.source = e.point ? "osm" : "derived";
    e.lonlat = {{8.1 + ch0 * 1e-5, 50.1}};
    if (!e.point) {
        e.lonlat.push_back({8.1 + ch1 * 1e-5, 50.1 + 1e-4});
    }
    return e;
}

inline odd::OddProfile sample_profile() {
    using odd::TaggedAttribute;
    const std::string curve = "Scenery/Track geometry/Horizontal/Curve";
    const std::string gradient = "Scenery/Track geometry/Vertical/Gradient";
    const std::string crossing = "Scenery/Crossings/Level crossing";
    odd::OddProfile p;
    p.taxonomy_name = "railodd railway ODD";
    p.taxonomy_version = "1.0";
    p.route = "test route";
    p.length_m = 1600.0;
    p.tracks = 1;
    p.elements = {
        tagged(gradient, "sc.geo.vt.gradient", {{"gradient", 30.0}, {"direction", std::string{"rising"}}}, "12",
               0, 400, 0, 400, {"way:1"}),
        tagged("Operational Conditions/Speed/Speed limit", "op.speed.limit",
               {{"maxspeed", 120.0}, {"kind", std::string{"posted"}}}, "12", 0, 1000, 0, 1000, {"way:1"}),
        tagged(curve, "sc.geo.hz.curve", {{"radius", 250.0}, {"direction", std::string{"left"}}}, "12", 100, 350,
               100, 350, {"way:1"}),
        tagged(crossing, "sc.xing.level", {{"barrier", std::string{"no"}}}, "12", 450, 450, 450, 450, {"node:5"}),
        tagged(curve, "sc.geo.hz.curve", {{"radius", 800.0}, {"direction", std::string{"right"}}}, "12", 500, 900,
               500, 900, {"way:1"}),
        tagged(gradient, "sc.geo.vt.gradient", {{"gradient", 10.0}, {"direction", std::string{"falling"}}}, "13",
               0, 600, 1000, 1600, {"way:2"}),
        tagged(crossing, "sc.xing.level", {{"barrier", std::string{"full"}}, {"lights", true}}, "13", 200, 200,
               1200, 1200, {"node:6", "way:7"}),
        tagged("Scenery/Stations and stops/Station", "sc.stn.station", {{"platforms", 2.0}}, "13", 500, 500, 1500,
               1500, {"node:8"}),
    };
    p.unparsed.push_back({{"way:2"}, "maxspeed", "DE:urban", "zone code"});
    return p;
}

} // namespace railodd::test
