// The OSM reader on tiny inline OPL inputs: what is a track, which features and
// roads are kept, clipped ways, and the accounting invariant.
#include "railodd/ingest/osm_reader.hpp"
#include "railodd/util/errors.hpp"
#include "test_support.hpp"

#include <algorithm>

using namespace railodd::ingest;
using railodd::test::scratch_dir;
using railodd::test::write_file;

namespace {

// Track w100 runs east along 48.0 N from 10.000 to 10.004 E (about 300 m).
// 1e-4 degrees of latitude are 11.1 m, of longitude 7.4 m here.
const char* const route_opl = R"(n1 v1 x10.0000 y48.0000
n2 v1 x10.0010 y48.0000
n3 v1 x10.0020 y48.0000 Trailway=level_crossing,crossing:barrier=full
n4 v1 x10.0030 y48.0000
n5 v1 x10.0040 y48.0000
n6 v1 x10.0000 y48.0010
n7 v1 x10.0040 y48.0010
n10 v1 x10.0000 y48.0030
n11 v1 x10.0010 y48.0030
n12 v1 x10.0030 y48.0030
n13 v1 x10.0040 y48.0030
n20 v1 x10.0025 y48.00018 Trailway=signal,railway:signal:main=DE-ESO:hp
n21 v1 x10.0025 y48.0100 Trailway=signal
n22 v1 x10.0020 y47.9973 Trailway=station,name=Testdorf
n23 v1 x10.0020 y48.0400 Trailway=switch
n30 v1 x10.0010 y48.00005
n31 v1 x10.0030 y48.00005
n40 v1 x10.0020 y48.0020
n41 v1 x10.0020 y47.9950
n42 v1 x10.0500 y48.0500
n43 v1 x10.0510 y48.0500
w100 v1 Trailway=rail,maxspeed=120,electrified=contact_line Nn1,n2,n3,n4,n5
w101 v1 Trailway=disused Nn6,n7
w102 v1 Trailway=monorail Nn6,n7
w103 v1 Trailway=rail,service=siding Nn10,n11,n99,n12,n13
w104 v1 Trailway=rail Nn98,n97
w105 v1 Trailway=tram Nn5,n5,n4
w200 v1 Trailway=platform,ref=1 Nn30,n31
w300 v1 Thighway=secondary,lanes=2 Nn40,n3,n41
w301 v1 Thighway=residential Nn42,n43
w302 v1 Thighway=construction Nn40,n2
)";

IngestResult read(const std::string& opl, IngestOptions options = {}) {
    const auto dir = scratch_dir();
    return read_osm(write_file(dir / "input.opl", opl), options);
}

const Way* track(const IngestResult& r, std::int64_t id) {
    auto it = std::find_if(r.tracks.begin(), r.tracks.end(), [&](const Way& w) { return w.id == id; });
    return it == r.tracks.end() ? nullptr : &*it;
}

const Feature* feature(const IngestResult& r, std::int64_t id) {
    auto it = std::find_if(r.features.begin(), r.features.end(), [&](const Feature& f) { return f.id == id; });
    return it == r.features.end() ? nullptr : &*it;
}

std::size_t dropped_tracks(const IngestResult& r) {
    return std::count_if(r.dropped.begin(), r.dropped.end(), [](const Dropped& d) { return d.kind == "track"; });
}

} // namespace

TEST(IngestOsmReader, TracksAreRailwayValuesWithoutLifecycle) {
    const IngestResult r = read(route_opl);
    EXPECT_NE(track(r, 100), nullptr);
    EXPECT_EQ(track(r, 101), nullptr) << "railway=disused is not a track";
    EXPECT_NE(track(r, 102), nullptr) << "monorail is a track";
    EXPECT_EQ(r.counts.input_track_ways, 5u); // 100, 102, 103, 104, 105
    ASSERT_NE(track(r, 100), nullptr);
    EXPECT_EQ(track(r, 100)->tags.at("maxspeed"), "120");
    EXPECT_EQ(track(r, 100)->tags.at("electrified"), "contact_line");
    ASSERT_EQ(track(r, 100)->parts.size(), 1u);
    EXPECT_EQ(track(r, 100)->parts[0].size(), 5u);
}

TEST(IngestOsmReader, AccountingInvariantHolds) {
    const IngestResult r = read(route_opl);
    EXPECT_EQ(r.counts.output_track_ways, r.tracks.size());
    EXPECT_EQ(r.counts.output_track_ways + dropped_tracks(r), r.counts.input_track_ways);
    EXPECT_EQ(r.counts.output_track_ways, 4u);
    ASSERT_EQ(dropped_tracks(r), 1u);
    const auto d = std::find_if(r.dropped.begin(), r.dropped.end(), [](const Dropped& x) { return x.kind == "track"; });
    EXPECT_EQ(d->id, 104);
    EXPECT_EQ(d->reason, "none of its 2 nodes is in the input");
}

// A closed way with railway=* and an area's key outlines an area (a station's
// landuse, a shed): dropped with the reason. A closed way without one is a
// loop of track and stays.
TEST(IngestOsmReader, AnAreaOutlineTaggedAsTrackIsDroppedWithItsReason) {
    const IngestResult r = read(R"(n1 v1 x10.0000 y48.0000
n2 v1 x10.0010 y48.0000
n3 v1 x10.0010 y48.0010
n4 v1 x10.0000 y48.0010
n5 v1 x10.0020 y48.0000
n6 v1 x10.0030 y48.0000
n7 v1 x10.0030 y48.0010
w1 v1 Tlanduse=railway,railway=light_rail Nn1,n2,n3,n4,n1
w2 v1 Tbuilding=yes,railway=rail Nn2,n5,n6,n2
w3 v1 Trailway=rail Nn5,n6,n7,n5
w4 v1 Trailway=rail,area=yes Nn1,n2,n3,n1
w5 v1 Trailway=rail,landuse=railway Nn1,n2,n3
)");
    EXPECT_EQ(r.counts.input_track_ways, 5u);
    EXPECT_EQ(track(r, 1), nullptr);
    EXPECT_EQ(track(r, 2), nullptr);
    EXPECT_NE(track(r, 3), nullptr) << "a closed loop of track";
    EXPECT_EQ(track(r, 4), nullptr);
    EXPECT_NE(track(r, 5), nullptr) << "an open way is a track, whatever else it is tagged";
    ASSERT_EQ(dropped_tracks(r), 3u);
    const auto reason = [&](std::int64_t id) {
        const auto d = std::find_if(r.dropped.begin(), r.dropped.end(), [&](const Dropped& x) { return x.id == id; });
        return d == r.dropped.end() ? std::string{} : d->reason;
    };
    EXPECT_EQ(reason(1), "closed way tagged landuse=railway: an area's outline, not a track");
    EXPECT_EQ(reason(2), "closed way tagged building=yes: an area's outline, not a track");
    EXPECT_EQ(reason(4), "closed way tagged area=yes: an area's outline, not a track");
}

TEST(IngestOsmReader, ClippedWayKeepsContiguousPartsAndRecordsRepair) {
    const IngestResult r = read(route_opl);
    const Way* w = track(r, 103);
    ASSERT_NE(w, nullptr);
    EXPECT_TRUE(w->clipped());
    EXPECT_EQ(w->missing_nodes, 1u);
    ASSERT_EQ(w->parts.size(), 2u);
    EXPECT_EQ(w->parts[0].front().id, 10);
    EXPECT_EQ(w->parts[0].back().id, 11);
    EXPECT_EQ(w->parts[1].front().id, 12);
    EXPECT_EQ(w->parts[1].back().id, 13);
    const auto repair = std::find_if(r.repairs.begin(), r.repairs.end(), [](const Repair& x) { return x.id == 103; });
    ASSERT_NE(repair, r.repairs.end());
    EXPECT_NE(repair->action.find("clipped: 1 of 5 nodes missing"), std::string::npos) << repair->action;
    EXPECT_EQ(r.counts.missing_track_nodes, 3u); // n99, and n98, n97 of the dropped way
}

TEST(IngestOsmReader, RepeatedNodeReferencesAreRemovedExplicitly) {
    const IngestResult r = read(route_opl);
    const Way* w = track(r, 105);
    ASSERT_NE(w, nullptr);
    ASSERT_EQ(w->parts.size(), 1u);
    EXPECT_EQ(w->parts[0].size(), 2u);
    const auto repair = std::find_if(r.repairs.begin(), r.repairs.end(), [](const Repair& x) { return x.id == 105; });
    ASSERT_NE(repair, r.repairs.end());
    EXPECT_NE(repair->action.find("repeated"), std::string::npos);
}

TEST(IngestOsmReader, FeaturesNearTracksAreKeptFarOnesDropped) {
    const IngestResult r = read(route_opl);
    ASSERT_NE(feature(r, 3), nullptr);
    EXPECT_TRUE(feature(r, 3)->on_track);
    EXPECT_EQ(feature(r, 3)->kind, "level_crossing");
    EXPECT_EQ(feature(r, 3)->tags.at("crossing:barrier"), "full");
    ASSERT_NE(feature(r, 20), nullptr) << "a signal 20 m beside the track";
    EXPECT_FALSE(feature(r, 20)->on_track);
    EXPECT_NE(feature(r, 22), nullptr) << "a station 300 m away (station distance 500 m)";
    EXPECT_EQ(feature(r, 21), nullptr);
    EXPECT_EQ(feature(r, 23), nullptr);
    const Feature* platform = feature(r, 200);
    ASSERT_NE(platform, nullptr);
    EXPECT_EQ(platform->kind, "platform");
    EXPECT_EQ(platform->osm_type, "way");
    EXPECT_EQ(platform->outline.size(), 2u);
    EXPECT_EQ(r.counts.input_features, 6u);
    EXPECT_EQ(r.counts.output_features, 4u);
    const auto far = std::count_if(r.dropped.begin(), r.dropped.end(), [](const Dropped& d) {
        return d.kind == "feature" && d.reason.find("farther than") != std::string::npos;
    });
    EXPECT_EQ(far, 2);
}

TEST(IngestOsmReader, RoadsInCorridorAreReadWhole) {
    const IngestResult r = read(route_opl);
    ASSERT_EQ(r.roads.size(), 1u) << "w301 is far away, w302 is highway=construction";
    EXPECT_EQ(r.roads[0].id, 300);
    ASSERT_EQ(r.roads[0].parts.size(), 1u);
    EXPECT_EQ(r.roads[0].parts[0].size(), 3u) << "n41 lies outside the corridor but belongs to the road";
    EXPECT_FALSE(r.roads[0].clipped());
    EXPECT_EQ(r.counts.input_road_ways, 1u);

    IngestOptions no_roads;
    no_roads.road_corridor_m = 0;
    EXPECT_TRUE(read(route_opl, no_roads).roads.empty());
}

TEST(IngestOsmReader, CorridorPassesFindTheSameRoadsAsPrefetch) {
    IngestOptions passes;
    passes.road_prefetch_refs = 0; // as for a file with too many roads to hold
    const IngestResult a = read(route_opl);
    const IngestResult b = read(route_opl, passes);
    ASSERT_EQ(a.roads.size(), b.roads.size());
    for (std::size_t i = 0; i < a.roads.size(); ++i) {
        EXPECT_EQ(a.roads[i].id, b.roads[i].id);
        ASSERT_EQ(a.roads[i].parts.size(), b.roads[i].parts.size());
        EXPECT_EQ(a.roads[i].parts[0].size(), b.roads[i].parts[0].size());
    }
    EXPECT_EQ(a.counts.input_road_ways, b.counts.input_road_ways);
}

TEST(IngestOsmReader, LocalFrameIsCentredOnTracks) {
    const IngestResult r = read(route_opl);
    EXPECT_NEAR(r.projection.origin().lon, 10.002, 1e-9);
    EXPECT_NEAR(r.projection.origin().lat, 48.0015, 1e-9);
    const Way* w = track(r, 100);
    ASSERT_NE(w, nullptr);
    // 0.004 degrees of longitude at 48 N on the WGS84 ellipsoid: 298.5 m.
    const double length = w->parts[0].back().xy.x - w->parts[0].front().xy.x;
    EXPECT_NEAR(length, 298.5, 0.1);
    EXPECT_NEAR(w->parts[0].front().xy.y, -166.8, 0.5);
}

TEST(IngestOsmReader, BboxSelectsWaysTouchingIt) {
    IngestOptions o;
    o.selection.bbox = parse_bbox("9.999,47.9995,10.0045,48.0005");
    const IngestResult r = read(route_opl, o);
    EXPECT_NE(track(r, 100), nullptr);
    EXPECT_NE(track(r, 105), nullptr);
    EXPECT_EQ(track(r, 103), nullptr);
    EXPECT_EQ(track(r, 102), nullptr);
    // w104 has no node in the input: it lies in no box (the whole file
    // accounts it as dropped, TracksAreRailwayValuesWithoutLifecycle).
    EXPECT_EQ(r.counts.input_track_ways, 2u);
    EXPECT_EQ(r.counts.output_track_ways + dropped_tracks(r), r.counts.input_track_ways);
}

TEST(IngestOsmReader, BboxHoldsOnlyWhatIsNearTheSelection) {
    // Ways are read only where they reach the nodes in and near the box, and
    // point features off them only near it: the switch n23, 4.4 km north, is
    // not even read (without a box it is read and dropped as too far from
    // every track).
    auto far_switch = [](const IngestResult& r) {
        return std::count_if(r.dropped.begin(), r.dropped.end(),
                             [](const Dropped& d) { return d.kind == "feature" && d.id == 23; });
    };
    EXPECT_EQ(far_switch(read(route_opl)), 1);
    IngestOptions o;
    o.selection.bbox = parse_bbox("9.999,47.9995,10.0045,48.0005");
    const IngestResult r = read(route_opl, o);
    EXPECT_EQ(far_switch(r), 0);
    EXPECT_EQ(r.counts.input_nodes, 21u) << "every node of the file is still counted";
    // n3 (a level crossing on w100) and the signal n20 beside it are kept.
    const auto has_feature = [&](std::int64_t id) {
        return std::any_of(r.features.begin(), r.features.end(), [&](const Feature& f) { return f.id == id; });
    };
    EXPECT_TRUE(has_feature(3));
    EXPECT_TRUE(has_feature(20));
}

TEST(IngestOsmReader, PolygonSelectionHonoursHoles) {
    const auto dir = scratch_dir();
    // An outer ring around all tracks with a hole around w100's western half.
    write_file(dir / "sel.geojson", R"({"type":"Feature","geometry":{"type":"Polygon","coordinates":[
        [[9.99,47.99],[10.01,47.99],[10.01,48.0025],[9.99,48.0025],[9.99,47.99]],
        [[9.995,47.999],[10.0045,47.999],[10.0045,48.0005],[9.995,48.0005],[9.995,47.999]]]}})");
    IngestOptions o;
    o.selection.polygon = load_polygon_geojson(dir / "sel.geojson");
    const IngestResult r = read(route_opl, o);
    EXPECT_EQ(track(r, 100), nullptr) << "all its nodes lie in the hole";
    EXPECT_NE(track(r, 102), nullptr);
    EXPECT_EQ(track(r, 103), nullptr);
}

TEST(IngestOsmReader, NoTrackInSelectionIsAnError) {
    IngestOptions o;
    o.selection.bbox = parse_bbox("11,49,12,50");
    EXPECT_THROW(read(route_opl, o), railodd::InputError);
}

namespace {

const char* const relation_opl = R"(n1 v1 x10.000 y48.000
n2 v1 x10.001 y48.000
n3 v1 x10.002 y48.000
n4 v1 x10.003 y48.000
n5 v1 x10.000 y48.010
n6 v1 x10.001 y48.010
w1 v1 Trailway=rail Nn1,n2
w2 v1 Trailway=rail Nn2,n3
w3 v1 Trailway=rail Nn3,n4
w4 v1 Trailway=rail Nn5,n6
w5 v1 Thighway=service Nn5,n6
r10 v1 Ttype=route,route=train,name=RB Mw1@,w2@,w5@,n2@stop
r11 v1 Ttype=route,route=train Mw3@
r12 v1 Ttype=route_master,route_master=train Mr10@,r11@,r99@
r13 v1 Ttype=route,route=bus Mw4@
)";

} // namespace

TEST(IngestOsmReader, RelationSelectsItsTrackWays) {
    IngestOptions o;
    o.selection.relation = 10;
    const IngestResult r = read(relation_opl, o);
    ASSERT_EQ(r.tracks.size(), 2u);
    EXPECT_EQ(r.tracks[0].id, 1);
    EXPECT_EQ(r.tracks[1].id, 2);
    EXPECT_EQ(r.counts.input_track_ways, 2u) << "the highway member is no track";
}

TEST(IngestOsmReader, RouteMasterIncludesItsRoutes) {
    IngestOptions o;
    o.selection.relation = 12;
    const IngestResult r = read(relation_opl, o);
    ASSERT_EQ(r.tracks.size(), 3u);
    EXPECT_EQ(r.tracks[2].id, 3);
}

TEST(IngestOsmReader, RelationErrorsNameTheProblem) {
    IngestOptions o;
    o.selection.relation = 13;
    try {
        read(relation_opl, o);
        FAIL() << "a bus route was accepted";
    } catch (const railodd::InputError& e) {
        EXPECT_NE(std::string{e.what()}.find("relation 13 is not a rail route"), std::string::npos) << e.what();
    }
    o.selection.relation = 77;
    try {
        read(relation_opl, o);
        FAIL() << "a missing relation was accepted";
    } catch (const railodd::InputError& e) {
        EXPECT_NE(std::string{e.what()}.find("relation 77 is not in the file"), std::string::npos) << e.what();
    }
}

TEST(IngestOsmReader, UnreadableInputsFailWithTheFileName) {
    const auto dir = scratch_dir();
    const auto missing = dir / "missing.osm.pbf";
    try {
        read_osm(missing, {});
        FAIL();
    } catch (const railodd::InputError& e) {
        EXPECT_EQ(e.where(), missing.string());
        EXPECT_EQ(e.problem(), "no such file");
    }
    const auto garbage = write_file(dir / "garbage.osm.pbf", std::string(1000, 'x'));
    EXPECT_THROW(read_osm(garbage, {}), railodd::InputError);
    const auto bad_xml = write_file(dir / "bad.osm", "<osm version=\"0.6\"><node id=\"1\" lat=\"48\" lon=");
    EXPECT_THROW(read_osm(bad_xml, {}), railodd::InputError);
    const auto bad_gz = write_file(dir / "bad.osm.gz", "\x1f\x8b\x08\x00 not really gzip");
    EXPECT_THROW(read_osm(bad_gz, {}), railodd::InputError);
    const auto unknown = write_file(dir / "tracks.txt", "hello");
    EXPECT_THROW(read_osm(unknown, {}), railodd::InputError);
}

TEST(IngestOsmReader, EveryFormatGivesTheSameResult) {
    const auto dir = scratch_dir();
    const auto opl = write_file(dir / "route.opl", route_opl);
    const IngestResult reference = read_osm(opl, {});
    for (const char* name : {"route.osm", "route.osm.pbf", "route.osm.gz", "route.osm.bz2"}) {
        SCOPED_TRACE(name);
        // osmium-tool writes the other formats: an independent writer.
        const std::string cmd = "osmium cat -o '" + (dir / name).string() + "' '" + opl.string() + "' 2>&1";
        ASSERT_EQ(std::system(cmd.c_str()), 0);
        const IngestResult r = read_osm(dir / name, {});
        EXPECT_EQ(r.counts.input_track_ways, reference.counts.input_track_ways);
        ASSERT_EQ(r.tracks.size(), reference.tracks.size());
        for (std::size_t i = 0; i < r.tracks.size(); ++i) {
            EXPECT_EQ(r.tracks[i].id, reference.tracks[i].id);
            EXPECT_EQ(r.tracks[i].tags, reference.tracks[i].tags);
            EXPECT_EQ(r.tracks[i].parts.size(), reference.tracks[i].parts.size());
        }
        EXPECT_EQ(r.features.size(), reference.features.size());
        EXPECT_EQ(r.roads.size(), reference.roads.size());
    }
}
