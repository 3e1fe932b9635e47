#include "dem_writer.hpp"

#include "railodd/util/errors.hpp"

#include <cpl_conv.h>
#include <cpl_error.h>
#include <cpl_string.h>
#include <gdal.h>
#include <ogr_srs_api.h>

#include <cmath>
#include <memory>
#include <numbers>
#include <string>

namespace railodd::sample {

namespace {

constexpr double metres_per_degree_lat = 111320.0;

struct DatasetCloser {
    void operator()(void* ds) const { GDALClose(ds); }
};
using Dataset = std::unique_ptr<void, DatasetCloser>;

struct SrsDestroyer {
    void operator()(void* srs) const { OSRDestroySpatialReference(srs); }
};

[[noreturn]] void fail(const std::filesystem::path& path, const std::string& what) {
    throw OutputError(path.string(), what + ": " + CPLGetLastErrorMsg());
}

void set_georeference(GDALDatasetH ds, const DemGrid& grid, const std::filesystem::path& path) {
    double transform[6] = {grid.west, grid.step, 0.0, grid.north, 0.0, -grid.step};
    if (GDALSetGeoTransform(ds, transform) != CE_None) {
        fail(path, "cannot set the geotransform");
    }
    std::unique_ptr<void, SrsDestroyer> srs(OSRNewSpatialReference(nullptr));
    if (!srs || OSRImportFromEPSG(srs.get(), 4326) != OGRERR_NONE ||
        GDALSetSpatialRef(ds, srs.get()) != CE_None) {
        fail(path, "cannot set EPSG:4326");
    }
}

} // namespace

DemGrid dem_grid(double min_lon, double min_lat, double max_lon, double max_lat, double margin_m) {
    const double mid_lat = 0.5 * (min_lat + max_lat) * std::numbers::pi / 180.0;
    const double dlat = margin_m / metres_per_degree_lat;
    const double dlon = margin_m / (metres_per_degree_lat * std::cos(mid_lat));
    DemGrid g;
    const double west = std::floor((min_lon - dlon) * 3600.0);
    const double east = std::ceil((max_lon + dlon) * 3600.0);
    const double south = std::floor((min_lat - dlat) * 3600.0);
    const double north = std::ceil((max_lat + dlat) * 3600.0);
    g.west = west / 3600.0;
    g.north = north / 3600.0;
    g.cols = static_cast<int>(east - west);
    g.rows = static_cast<int>(north - south);
    return g;
}

void write_dem(const std::filesystem::path& path, const DemGrid& grid, const std::vector<float>& values) {
    if (values.size() != static_cast<std::size_t>(grid.cols) * static_cast<std::size_t>(grid.rows)) {
        throw OutputError(path.string(), "DEM values do not fill the grid");
    }
    GDALAllRegister();
    CPLErrorReset();
    GDALDriverH driver = GDALGetDriverByName("GTiff");
    if (!driver) {
        fail(path, "GDAL has no GTiff driver");
    }
    char** options = nullptr;
    options = CSLSetNameValue(options, "COMPRESS", "DEFLATE");
    options = CSLSetNameValue(options, "PREDICTOR", "3"); // floating-point predictor
    Dataset ds(GDALCreate(driver, path.string().c_str(), grid.cols, grid.rows, 1, GDT_Float32, options));
    CSLDestroy(options);
    if (!ds) {
        fail(path, "cannot create GeoTIFF");
    }
    set_georeference(ds.get(), grid, path);
    GDALRasterBandH band = GDALGetRasterBand(ds.get(), 1);
    if (GDALSetRasterNoDataValue(band, dem_nodata) != CE_None) {
        fail(path, "cannot set nodata");
    }
    // GDALRasterIO takes a non-const buffer even for writing.
    std::vector<float> buffer = values;
    if (GDALRasterIO(band, GF_Write, 0, 0, grid.cols, grid.rows, buffer.data(), grid.cols, grid.rows,
                     GDT_Float32, 0, 0) != CE_None) {
        fail(path, "cannot write elevations");
    }
    ds.reset(); // flushes; a failure shows up as a pending error
    if (CPLGetLastErrorType() >= CE_Failure) {
        fail(path, "cannot finish GeoTIFF");
    }
}

} // namespace railodd::sample
