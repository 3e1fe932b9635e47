// ElevationModel on the real SRTM tiles in ../shared/data/dem.
#include "railodd/geometry/elevation_model.hpp"

#include "test_support.hpp"

#include <gdal_priv.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <iostream>
#include <optional>
#include <vector>

using namespace railodd;
using geometry::ElevationModel;

namespace {

std::filesystem::path dem_file(const char* name) { return test::shared_data() / "dem" / name; }

constexpr const char* monaco = "N43E007_srtm3_monaco.tif";
constexpr const char* franconia = "N49-50E011_srtm3_franconia.tif";
constexpr const char* alps = "N46E008_srtm3.tif";

struct Void {
    ingest::LonLat centre;
    double low;  // range of the valid pixels within two pixels
    double high;
};

// A void pixel of the tile with a valid pixel among its eight neighbours: the
// fill then blends the valid pixels within two pixels of it.
std::optional<Void> find_rim_void(const std::filesystem::path& file) {
    GDALAllRegister();
    GDALDatasetUniquePtr ds(GDALDataset::Open(file.c_str(), GDAL_OF_RASTER | GDAL_OF_READONLY));
    if (!ds) {
        return std::nullopt;
    }
    GDALRasterBand* band = ds->GetRasterBand(1);
    const int cols = ds->GetRasterXSize();
    const int rows = ds->GetRasterYSize();
    std::vector<float> v(static_cast<std::size_t>(cols) * rows);
    if (band->RasterIO(GF_Read, 0, 0, cols, rows, v.data(), cols, rows, GDT_Float32, 0, 0, nullptr) != CE_None) {
        return std::nullopt;
    }
    const auto nodata = static_cast<float>(band->GetNoDataValue());
    auto at = [&](int c, int r) { return v[static_cast<std::size_t>(r) * cols + c]; };
    double gt[6];
    ds->GetGeoTransform(gt);
    for (int r = 100; r < rows - 100; ++r) {
        for (int c = 100; c < cols - 100; ++c) {
            if (at(c, r) != nodata || at(c - 1, r) == nodata) {
                continue; // a void with a valid western neighbour
            }
            double low = 1e9;
            double high = -1e9;
            for (int rr = r - 2; rr <= r + 2; ++rr) {
                for (int cc = c - 2; cc <= c + 2; ++cc) {
                    if (at(cc, rr) != nodata) {
                        low = std::min<double>(low, at(cc, rr));
                        high = std::max<double>(high, at(cc, rr));
                    }
                }
            }
            if (high - low > 20.0) { // an informative spot, not a flat lake
                return Void{{gt[0] + (c + 0.5) * gt[1], gt[3] + (r + 0.5) * gt[5]}, low, high};
            }
        }
    }
    return std::nullopt;
}

} // namespace

TEST(DemShared, MonacoCoastIsAtSeaLevel) {
    RAILODD_REQUIRE_SHARED_DATA();
    const ElevationModel dem(dem_file(monaco));
    const auto harbour = dem.sample({7.4235, 43.7350}); // Port Hercule
    ASSERT_TRUE(harbour);
    EXPECT_NEAR(*harbour, 0.0, 3.0);
    const auto town = dem.sample({7.41, 43.73}); // Fontvieille / Monaco-Ville, above the sea
    ASSERT_TRUE(town);
    EXPECT_GT(*town, 20.0);
    EXPECT_LT(*town, 200.0);
    const auto agel = dem.sample({7.4206, 43.7650}); // slopes of Mont Agel
    ASSERT_TRUE(agel);
    EXPECT_GT(*agel, 600.0);
    EXPECT_FALSE(dem.sample({8.5, 43.5}));
}

TEST(DemShared, FranconiaHeights) {
    RAILODD_REQUIRE_SHARED_DATA();
    const ElevationModel dem(dem_file(franconia));
    for (const auto& p : {ingest::LonLat{11.57, 50.03}, {11.58, 49.95}, {11.28, 49.51}}) {
        const auto z = dem.sample(p);
        ASSERT_TRUE(z) << p.lon << " " << p.lat;
        EXPECT_GT(*z, 300.0);
        EXPECT_LT(*z, 600.0);
    }
    // Neighbouring samples 10 m apart differ by little: bilinear, not nearest pixel.
    double worst = 0.0;
    for (int i = 0; i < 200; ++i) {
        const double lon = 11.57 + i * 0.00014;
        worst = std::max(worst, std::abs(*dem.sample({lon + 0.00014, 50.03}) - *dem.sample({lon, 50.03})));
    }
    EXPECT_LT(worst, 5.0);
}

TEST(DemShared, AlpineVoidsAreFilled) {
    RAILODD_REQUIRE_SHARED_DATA();
    const auto v = find_rim_void(dem_file(alps));
    ASSERT_TRUE(v) << "no void with valid neighbours in " << alps;
    const ElevationModel dem(dem_file(alps));
    const auto z = dem.sample(v->centre);
    ASSERT_TRUE(z) << v->centre.lon << " " << v->centre.lat;
    std::cout << "[ measured ] void at lon " << v->centre.lon << " lat " << v->centre.lat << " filled with " << *z
              << " m, valid pixels within 2 px range " << v->low << " .. " << v->high << " m\n";
    EXPECT_GE(*z, v->low - 1e-6);
    EXPECT_LE(*z, v->high + 1e-6);
    // The tile's nodata (-32767, not SRTM's usual -32768) never leaks out.
    for (int i = 0; i < 400; ++i) {
        const auto s = dem.sample({8.0 + 0.0025 * i, 46.0 + 0.0025 * i});
        if (s) {
            EXPECT_GT(*s, 0.0);
            EXPECT_LT(*s, 4800.0);
        }
    }
}

TEST(DemShared, SeveralTilesAtOnce) {
    RAILODD_REQUIRE_SHARED_DATA();
    const ElevationModel all(std::vector<std::filesystem::path>{dem_file(monaco), dem_file(alps), dem_file(franconia)});
    EXPECT_EQ(all.tile_count(), 3u);
    const ElevationModel only_monaco(dem_file(monaco));
    const ElevationModel only_alps(dem_file(alps));
    const ElevationModel only_franconia(dem_file(franconia));
    EXPECT_EQ(all.sample({7.41, 43.73}), only_monaco.sample({7.41, 43.73}));
    EXPECT_EQ(all.sample({8.3, 46.9}), only_alps.sample({8.3, 46.9}));
    EXPECT_EQ(all.sample({11.57, 50.03}), only_franconia.sample({11.57, 50.03}));
    EXPECT_FALSE(all.sample({10.0, 45.0}));
}
