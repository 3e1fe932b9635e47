// ElevationModel on synthetic rasters: interpolation, voids, tiles, CRSs, errors.
#include "railodd/geometry/elevation_model.hpp"
#include "railodd/util/errors.hpp"

#include "test_dem_support.hpp"
#include "test_support.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

using namespace railodd;
using geometry::ElevationModel;
using test::DemSpec;

namespace {

constexpr double void_value = std::numeric_limits<double>::quiet_NaN();
constexpr double arcsec = 1.0 / 3600.0;

// 100 x 80 arc-second pixels from lon 10, lat 48.1 down.
DemSpec wgs84_spec() {
    DemSpec s;
    s.x0 = 10.0;
    s.y0 = 48.1;
    s.step = arcsec;
    s.cols = 100;
    s.rows = 80;
    return s;
}

// A plane: bilinear interpolation reproduces it exactly.
double plane(double lon, double lat) { return 300.0 + 20000.0 * (lon - 10.0) - 5000.0 * (lat - 48.0); }

std::string error_of(const std::filesystem::path& file) {
    try {
        ElevationModel dem(file);
    } catch (const InputError& e) {
        EXPECT_EQ(e.where(), file.string());
        return e.problem();
    }
    return "no error";
}

} // namespace

TEST(ElevationModel, BilinearOnAPlaneIsExact) {
    const auto dir = test::scratch_dir();
    test::write_dem(dir / "plane.tif", wgs84_spec(), plane);
    const ElevationModel dem(dir / "plane.tif");
    EXPECT_EQ(dem.tile_count(), 1u);
    for (const auto& p : {ingest::LonLat{10.0101, 48.0912}, {10.0002, 48.0998}, {10.02, 48.08}}) {
        const auto z = dem.sample(p);
        ASSERT_TRUE(z);
        EXPECT_NEAR(*z, plane(p.lon, p.lat), 1e-3);
    }
    // The outer half-pixel rim repeats the edge pixels.
    const auto rim = dem.sample({10.00005, 48.09});
    ASSERT_TRUE(rim);
    EXPECT_NEAR(*rim, plane(10.0 + 0.5 * arcsec, 48.09), 1e-3);
    // Outside the raster.
    EXPECT_FALSE(dem.sample({9.99, 48.09}));
    EXPECT_FALSE(dem.sample({10.01, 48.2}));
}

TEST(ElevationModel, VoidsAreFilledFromTheirNeighbours) {
    const auto dir = test::scratch_dir();
    DemSpec spec = wgs84_spec();
    // A 3 x 3 void around pixel (50, 40) and a 30 x 30 one further right.
    test::write_dem(dir / "voids.tif", spec, [&](double lon, double lat) {
        const int c = static_cast<int>(std::floor((lon - spec.x0) / spec.step));
        const int r = static_cast<int>(std::floor((spec.y0 - lat) / spec.step));
        if ((std::abs(c - 50) <= 1 && std::abs(r - 40) <= 1) || (c >= 65 && c < 95 && r >= 20 && r < 50)) {
            return void_value;
        }
        return plane(lon, lat);
    });
    geometry::ElevationModelOptions options;
    options.void_fill_radius_px = 5;
    const ElevationModel dem(dir / "voids.tif", options);
    const double lon = spec.x0 + 50.5 * arcsec;
    const double lat = spec.y0 - 40.5 * arcsec;
    const auto z = dem.sample({lon, lat});
    ASSERT_TRUE(z);
    // Inverse-distance weights blend the rim: within the rim's range, close to the plane.
    EXPECT_GT(*z, plane(lon - 3 * arcsec, lat) - 0.01);
    EXPECT_LT(*z, plane(lon + 3 * arcsec, lat) + 0.01);
    EXPECT_NEAR(*z, plane(lon, lat), 0.5);
    // The middle of the big void is further than 5 px from any valid pixel.
    EXPECT_FALSE(dem.sample({spec.x0 + 80.5 * arcsec, spec.y0 - 35.5 * arcsec}));
    // Its rim is filled.
    EXPECT_TRUE(dem.sample({spec.x0 + 66.5 * arcsec, spec.y0 - 35.5 * arcsec}));
}

// Cells no terrain has (infinities, an unflagged 1e30 or -32768 no-data) are
// voids like flagged ones: filled from their neighbours, never a NaN or an
// infinity in a profile (an inf cell once wrote <elevation a="-nan">).
TEST(ElevationModel, NonFiniteAndImpossibleCellsAreVoids) {
    const auto dir = test::scratch_dir();
    DemSpec spec = wgs84_spec();
    spec.nodata = -9999.0f;
    const double bad[] = {std::numeric_limits<double>::infinity(), -std::numeric_limits<double>::infinity(), 1e30,
                          -32768.0};
    test::write_dem(dir / "inf.tif", spec, [&](double lon, double lat) {
        const int c = static_cast<int>(std::floor((lon - spec.x0) / spec.step));
        const int r = static_cast<int>(std::floor((spec.y0 - lat) / spec.step));
        return r == 40 && c >= 50 && c < 54 ? bad[c - 50] : plane(lon, lat);
    });
    geometry::ElevationModelOptions options;
    options.void_fill_radius_px = 5;
    const ElevationModel dem(dir / "inf.tif", options);
    for (int c = 50; c < 54; ++c) {
        const double lon = spec.x0 + (c + 0.5) * arcsec;
        const double lat = spec.y0 - 40.5 * arcsec;
        const auto z = dem.sample({lon, lat});
        ASSERT_TRUE(z) << c;
        EXPECT_TRUE(std::isfinite(*z)) << c;
        EXPECT_NEAR(*z, plane(lon, lat), 1.5) << c; // filled by inverse distance across a 4-cell row on a slope
    }
}

TEST(ElevationModel, IntegerRasterWithItsOwnNodata) {
    const auto dir = test::scratch_dir();
    DemSpec spec = wgs84_spec();
    spec.type = GDT_Int16;
    spec.nodata = -32767.0f; // like the N46E008 SRTM tile
    test::write_dem(dir / "int16.tif", spec, [&](double lon, double) { return lon < 10.01 ? void_value : 500.0; });
    const ElevationModel dem(dir / "int16.tif");
    const auto z = dem.sample({10.0099, 48.09});
    ASSERT_TRUE(z);
    EXPECT_DOUBLE_EQ(*z, 500.0);
}

TEST(ElevationModel, TilesSideBySide) {
    const auto dir = test::scratch_dir();
    DemSpec west = wgs84_spec();
    DemSpec east = west;
    east.x0 = west.x0 + west.cols * arcsec;
    test::write_dem(dir / "west.tif", west, plane);
    test::write_dem(dir / "east.tif", east, plane);
    const ElevationModel dem(std::vector<std::filesystem::path>{dir / "west.tif", dir / "east.tif"});
    EXPECT_EQ(dem.tile_count(), 2u);
    for (const double lon : {10.01, east.x0 - 0.2 * arcsec, east.x0 + 0.2 * arcsec, east.x0 + 0.02}) {
        const auto z = dem.sample({lon, 48.09});
        ASSERT_TRUE(z) << lon;
        EXPECT_NEAR(*z, plane(lon, 48.09), 1e-3) << lon; // seamless across the seam
    }
}

TEST(ElevationModel, ProjectedRaster) {
    const auto dir = test::scratch_dir();
    // UTM 32N around lon 10.0, lat 48.0 (x ~ 574 km, y ~ 5316 km), 25 m pixels.
    DemSpec spec;
    spec.epsg = 32632;
    spec.x0 = 570000.0;
    spec.y0 = 5320000.0;
    spec.step = 25.0;
    spec.cols = 400;
    spec.rows = 400;
    test::write_dem(dir / "utm.tif", spec, [](double x, double y) { return 100.0 + 0.01 * (x - 570000.0) + 0.002 * (y - 5310000.0); });
    const ElevationModel dem(dir / "utm.tif");
    // lon 10, lat 48 is x = 574,595.1 m, y = 5,316,784.0 m in UTM 32N (gdaltransform).
    const auto z = dem.sample({10.0, 48.0});
    ASSERT_TRUE(z);
    EXPECT_NEAR(*z, 100.0 + 0.01 * 4595.1 + 0.002 * 6784.0, 0.05);
}

TEST(ElevationModel, ErrorsNameTheFile) {
    const auto dir = test::scratch_dir();
    EXPECT_NE(error_of(dir / "missing.tif").find("does not exist"), std::string::npos);

    test::write_file(dir / "junk.tif", "this is not a raster\n");
    EXPECT_NE(error_of(dir / "junk.tif").find("cannot read it as a raster"), std::string::npos);

    test::write_file(dir / "lines.geojson",
                     R"({"type":"FeatureCollection","features":[{"type":"Feature","properties":{},)"
                     R"("geometry":{"type":"LineString","coordinates":[[10,48],[10.1,48.1]]}}]})");
    EXPECT_NE(error_of(dir / "lines.geojson").find("not a raster"), std::string::npos);

    DemSpec no_crs = wgs84_spec();
    no_crs.epsg = 0;
    test::write_dem(dir / "no_crs.tif", no_crs, plane);
    EXPECT_NE(error_of(dir / "no_crs.tif").find("no coordinate reference system"), std::string::npos);

    DemSpec no_gt = wgs84_spec();
    no_gt.georeferenced = false;
    no_gt.epsg = 0;
    test::write_dem(dir / "no_gt.tif", no_gt, plane);
    EXPECT_NE(error_of(dir / "no_gt.tif").find("no georeferencing"), std::string::npos);
}
