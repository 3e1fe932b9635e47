// Track centerlines from GIS vector files through GDAL/OGR and a YAML field mapping.
#include "railodd/ingest/ogr_reader.hpp"
#include "railodd/util/errors.hpp"
#include "test_support.hpp"

#include <algorithm>

using namespace railodd::ingest;
using railodd::test::scratch_dir;
using railodd::test::write_file;

namespace {

// Three features in WGS84: two lines joined end to end, and one platform line
// that the mapping does not turn into a track.
const char* const tracks_geojson = R"({"type":"FeatureCollection","features":[
 {"type":"Feature","properties":{"gid":7,"kind":"main","vmax":120,"elek":"1","nm":"Nordbahn"},
  "geometry":{"type":"LineString","coordinates":[[10.000,48.000],[10.003,48.000]]}},
 {"type":"Feature","properties":{"gid":8,"kind":"main","vmax":null,"elek":"0","nm":"Nordbahn"},
  "geometry":{"type":"MultiLineString","coordinates":[[[10.003,48.000],[10.006,48.001]],[[10.007,48.001],[10.008,48.001]]]}},
 {"type":"Feature","properties":{"gid":9,"kind":"platform","vmax":null,"elek":"0","nm":null},
  "geometry":{"type":"LineString","coordinates":[[10.001,48.0001],[10.002,48.0001]]}}
]})";

const char* const mapping_yaml = R"(# national dataset -> OSM tags
id_field: gid
tags:
  railway:
    field: kind
    values: {main: rail, platform: platform}
  maxspeed: {field: vmax, default: "100"}
  electrified:
    field: elek
    values: {"1": contact_line, "0": "no"}
  name: {field: nm}
  gauge: "1435"
)";

} // namespace

TEST(IngestOgrReader, RecognisesVectorSuffixes) {
    EXPECT_TRUE(is_vector_source("a/tracks.GeoJSON"));
    EXPECT_TRUE(is_vector_source("tracks.gpkg"));
    EXPECT_TRUE(is_vector_source("tracks.shp"));
    EXPECT_FALSE(is_vector_source("x.osm.pbf"));
    EXPECT_FALSE(is_vector_source("x.osm"));
}

TEST(IngestOgrReader, MapsFieldsOntoTags) {
    const auto dir = scratch_dir();
    const auto r = read_vector(write_file(dir / "tracks.geojson", tracks_geojson),
                               write_file(dir / "mapping.yaml", mapping_yaml), {});
    ASSERT_EQ(r.tracks.size(), 2u);
    const Way& a = r.tracks[0];
    const Way& b = r.tracks[1];
    EXPECT_EQ(a.id, 7);
    EXPECT_EQ(a.origin, Origin::ogr);
    EXPECT_EQ(a.tags.at("railway"), "rail");
    EXPECT_EQ(a.tags.at("maxspeed"), "120");
    EXPECT_EQ(a.tags.at("electrified"), "contact_line");
    EXPECT_EQ(a.tags.at("gauge"), "1435");
    EXPECT_EQ(a.tags.at("name"), "Nordbahn");
    EXPECT_EQ(b.tags.at("maxspeed"), "100") << "null field takes the default";
    EXPECT_EQ(b.tags.at("electrified"), "no");
    ASSERT_EQ(b.parts.size(), 2u) << "a MultiLineString keeps its parts";
    // Lines meeting end to end share a vertex id, as OSM ways share a node.
    EXPECT_EQ(a.parts[0].back().id, b.parts[0].front().id);
    EXPECT_NEAR(a.parts[0].back().xy.x - a.parts[0].front().xy.x, 223.5, 0.5);
}

TEST(IngestOgrReader, NonTracksAreDroppedWithReason) {
    const auto dir = scratch_dir();
    const auto r = read_vector(write_file(dir / "tracks.geojson", tracks_geojson),
                               write_file(dir / "mapping.yaml", mapping_yaml), {});
    EXPECT_EQ(r.counts.input_track_ways, 3u);
    ASSERT_EQ(r.dropped.size(), 1u);
    EXPECT_EQ(r.dropped[0].id, 9);
    EXPECT_EQ(r.dropped[0].osm_type, "ogr_feature");
    EXPECT_EQ(r.dropped[0].reason, "mapped railway=platform is not a track value");
    EXPECT_EQ(r.counts.output_track_ways + r.dropped.size(), r.counts.input_track_ways);
}

TEST(IngestOgrReader, ProjectedSourcesAreTransformed) {
    const auto dir = scratch_dir();
    const auto src = write_file(dir / "utm.geojson", R"({"type":"FeatureCollection",
 "crs":{"type":"name","properties":{"name":"urn:ogc:def:crs:EPSG::25832"}},
 "features":[{"type":"Feature","properties":{"t":"rail"},
  "geometry":{"type":"LineString","coordinates":[[574595.11248671,5316784.00911336],[574818.895466883,5316786.91630222]]}}]})");
    const auto map = write_file(dir / "m.yaml", "tags:\n  railway: {field: t}\n");
    const auto r = read_vector(src, map, {});
    ASSERT_EQ(r.tracks.size(), 1u);
    const auto& p = r.tracks[0].parts[0];
    EXPECT_NEAR(p[0].lonlat.lon, 10.000, 1e-8);
    EXPECT_NEAR(p[0].lonlat.lat, 48.000, 1e-8);
    EXPECT_NEAR(p[1].lonlat.lon, 10.003, 1e-8);
}

TEST(IngestOgrReader, MappingErrorsNameFileAndLine) {
    const auto dir = scratch_dir();
    const auto src = write_file(dir / "tracks.geojson", tracks_geojson);
    const auto bad_field = write_file(dir / "bad_field.yaml", "tags:\n  railway: rail\n  maxspeed: {field: speed}\n");
    try {
        read_vector(src, bad_field, {});
        FAIL();
    } catch (const railodd::InputError& e) {
        EXPECT_EQ(e.where(), bad_field.string() + ":3");
        EXPECT_NE(e.problem().find("field 'speed' is not in layer"), std::string::npos) << e.what();
    }
    const auto bad_key = write_file(dir / "bad_key.yaml", "tags:\n  railway: rail\nlayr: x\n");
    try {
        read_vector(src, bad_key, {});
        FAIL();
    } catch (const railodd::InputError& e) {
        EXPECT_EQ(e.where(), bad_key.string() + ":3");
    }
    const auto no_railway = write_file(dir / "no_railway.yaml", "tags:\n  name: {field: nm}\n");
    EXPECT_THROW(read_vector(src, no_railway, {}), railodd::InputError);
    const auto not_yaml = write_file(dir / "not.yaml", "tags: [unclosed\n");
    EXPECT_THROW(read_vector(src, not_yaml, {}), railodd::InputError);
}

TEST(IngestOgrReader, RelationSelectionIsRefused) {
    const auto dir = scratch_dir();
    Selection sel;
    sel.relation = 1;
    EXPECT_THROW(read_vector(write_file(dir / "t.geojson", tracks_geojson), write_file(dir / "m.yaml", mapping_yaml), sel),
                 railodd::UsageError);
}

TEST(IngestOgrReader, GeoPackageAndShapefileReadLikeGeoJson) {
    const auto dir = scratch_dir();
    const auto src = write_file(dir / "tracks.geojson", tracks_geojson);
    const auto map = write_file(dir / "mapping.yaml", mapping_yaml);
    const auto reference = read_vector(src, map, {});
    for (const char* name : {"tracks.gpkg", "tracks.shp"}) {
        SCOPED_TRACE(name);
        // ogr2ogr (gdal-bin) converts; GeoPackage and Shapefile keep the gid field.
        const std::string cmd = "ogr2ogr '" + (dir / name).string() + "' '" + src.string() + "' 2>&1";
        ASSERT_EQ(std::system(cmd.c_str()), 0);
        const auto r = read_vector(dir / name, map, {});
        ASSERT_EQ(r.tracks.size(), reference.tracks.size());
        for (std::size_t i = 0; i < r.tracks.size(); ++i) {
            EXPECT_EQ(r.tracks[i].id, reference.tracks[i].id);
            EXPECT_EQ(r.tracks[i].tags, reference.tracks[i].tags);
            ASSERT_EQ(r.tracks[i].parts.size(), reference.tracks[i].parts.size());
            EXPECT_NEAR(r.tracks[i].parts[0][0].xy.x, reference.tracks[i].parts[0][0].xy.x, 1e-6);
        }
        EXPECT_EQ(r.dropped.size(), reference.dropped.size());
    }
}
