#pragma once
// Synthetic DEM rasters for the elevation tests, written through GDAL's C API.
#include <cpl_conv.h>
#include <gdal.h>
#include <ogr_srs_api.h>

#include <cmath>
#include <filesystem>
#include <functional>
#include <limits>
#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

namespace railodd::test {

// A north-up grid: (x0, y0) is the top-left corner, step the pixel size in
// CRS units; epsg 0 writes no CRS. value(x, y) gets the pixel centre and may
// return NaN for a void (written as nodata).
struct DemSpec {
    double x0 = 0.0;
    double y0 = 0.0;
    double step = 1.0 / 3600.0;
    int cols = 0;
    int rows = 0;
    int epsg = 4326;
    bool georeferenced = true;
    float nodata = -32768.0f;
    GDALDataType type = GDT_Float32;
};

inline void write_dem(const std::filesystem::path& path, const DemSpec& spec,
                      const std::function<double(double x, double y)>& value) {
    GDALAllRegister();
    GDALDriverH driver = GDALGetDriverByName("GTiff");
    auto close = [](GDALDatasetH h) { GDALClose(h); };
    std::unique_ptr<void, decltype(close)> ds(
        GDALCreate(driver, path.string().c_str(), spec.cols, spec.rows, 1, spec.type, nullptr), close);
    if (!ds) {
        throw std::runtime_error("cannot create " + path.string());
    }
    if (spec.georeferenced) {
        double gt[6] = {spec.x0, spec.step, 0.0, spec.y0, 0.0, -spec.step};
        GDALSetGeoTransform(ds.get(), gt);
    }
    if (spec.epsg != 0) {
        OGRSpatialReferenceH srs = OSRNewSpatialReference(nullptr);
        OSRImportFromEPSG(srs, spec.epsg);
        GDALSetSpatialRef(ds.get(), srs);
        OSRDestroySpatialReference(srs);
    }
    GDALRasterBandH band = GDALGetRasterBand(ds.get(), 1);
    GDALSetRasterNoDataValue(band, spec.nodata);
    std::vector<float> values;
    for (int r = 0; r < spec.rows; ++r) {
        for (int c = 0; c < spec.cols; ++c) {
            const double v = value(spec.x0 + (c + 0.5) * spec.step, spec.y0 - (r + 0.5) * spec.step);
            values.push_back(std::isnan(v) ? spec.nodata : static_cast<float>(v));
        }
    }
    if (GDALRasterIO(band, GF_Write, 0, 0, spec.cols, spec.rows, values.data(), spec.cols, spec.rows, GDT_Float32,
                     0, 0) != CE_None) {
        throw std::runtime_error("cannot write " + path.string());
    }
}

} // namespace railodd::test
