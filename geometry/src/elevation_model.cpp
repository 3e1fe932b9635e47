// GDAL side of the elevation model: opening tiles, mapping lon/lat to pixels
// and reading bands lazily; the pixel arithmetic lives in vertical/raster_grid.
#include "railodd/geometry/elevation_model.hpp"

#include "vertical/raster_grid.hpp"

#include "railodd/util/errors.hpp"

#include <cpl_error.h>
#include <gdal_priv.h>
#include <ogr_spatialref.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <limits>
#include <mutex>
#include <string>
#include <system_error>

namespace railodd::geometry {

namespace {

namespace fs = std::filesystem;

struct CtDeleter {
    void operator()(OGRCoordinateTransformation* ct) const { OGRCoordinateTransformation::DestroyCT(ct); }
};
using Transform = std::unique_ptr<OGRCoordinateTransformation, CtDeleter>;

struct Tile {
    fs::path path;
    GDALDatasetUniquePtr dataset;
    Transform to_raster; // null when the raster is already WGS84 lon/lat
    Transform to_wgs84;  // its inverse, for pixel centres beyond a seam
    double gt[6] = {};
    double inverse_gt[6] = {};
    int cols = 0;
    int rows = 0;
    std::optional<vertical::RasterGrid> grid; // filled on first use
};

[[noreturn]] void fail(const fs::path& file, const std::string& problem) {
    throw InputError(file.string(), problem);
}

std::string gdal_message() {
    const std::string msg = CPLGetLastErrorMsg();
    return msg.empty() ? std::string{} : ": " + msg;
}

GDALDatasetUniquePtr open_raster(const fs::path& file) {
    std::error_code ec;
    if (!fs::exists(file, ec)) {
        fail(file, "DEM file does not exist");
    }
    // GDAL would print its own complaints to stderr; the InputError carries them.
    CPLErrorHandlerPusher quiet(CPLQuietErrorHandler);
    CPLErrorReset();
    GDALDatasetUniquePtr ds(GDALDataset::Open(file.c_str(), GDAL_OF_RASTER | GDAL_OF_READONLY));
    if (!ds) {
        const std::string why = gdal_message();
        if (GDALDatasetUniquePtr v{GDALDataset::Open(file.c_str(), GDAL_OF_VECTOR | GDAL_OF_READONLY)}) {
            fail(file, "not a raster: GDAL reads it as vector data");
        }
        fail(file, "GDAL cannot read it as a raster" + why);
    }
    if (ds->GetRasterCount() < 1) {
        fail(file, "not a raster: it has no bands");
    }
    return ds;
}

// lon/lat (WGS84, traditional GIS order) to the raster's CRS and back; both
// null if the raster is WGS84 lon/lat already.
void set_transforms(Tile& t, const OGRSpatialReference& raster_crs) {
    OGRSpatialReference wgs84;
    wgs84.importFromEPSG(4326);
    wgs84.SetAxisMappingStrategy(OAMS_TRADITIONAL_GIS_ORDER);
    OGRSpatialReference target(raster_crs);
    target.SetAxisMappingStrategy(OAMS_TRADITIONAL_GIS_ORDER);
    if (target.IsSame(&wgs84)) {
        return;
    }
    t.to_raster.reset(OGRCreateCoordinateTransformation(&wgs84, &target));
    t.to_wgs84.reset(OGRCreateCoordinateTransformation(&target, &wgs84));
    if (!t.to_raster || !t.to_wgs84) {
        fail(t.path, "no transformation between WGS84 and the raster's CRS" + gdal_message());
    }
}

Tile open_tile(const fs::path& file, const ElevationModelOptions& options) {
    Tile t;
    t.path = file;
    t.dataset = open_raster(file);
    t.cols = t.dataset->GetRasterXSize();
    t.rows = t.dataset->GetRasterYSize();
    if (static_cast<std::size_t>(t.cols) * static_cast<std::size_t>(t.rows) > options.max_pixels_per_tile) {
        fail(file, "raster of " + std::to_string(t.cols) + " x " + std::to_string(t.rows) +
                       " pixels is too large to hold in memory; crop it or use a .vrt of smaller tiles");
    }
    if (t.dataset->GetGeoTransform(t.gt) != CE_None) {
        fail(file, "raster has no georeferencing (geotransform)");
    }
    if (!GDALInvGeoTransform(t.gt, t.inverse_gt)) {
        fail(file, "raster geotransform is not invertible");
    }
    const OGRSpatialReference* crs = t.dataset->GetSpatialRef();
    if (!crs || crs->IsEmpty()) {
        fail(file, "raster has no coordinate reference system");
    }
    set_transforms(t, *crs);
    return t;
}

// Metres per unit of the band, from its unit type; SRTM and most DEMs say
// "m" or nothing.
double unit_factor(GDALRasterBand& band) {
    std::string unit = band.GetUnitType();
    std::transform(unit.begin(), unit.end(), unit.begin(), [](unsigned char c) { return std::tolower(c); });
    if (unit == "ft" || unit == "foot" || unit == "feet" || unit == "international foot") {
        return 0.3048;
    }
    if (unit == "us survey foot" || unit == "us-ft") {
        return 1200.0 / 3937.0;
    }
    return 1.0;
}

vertical::RasterGrid read_grid(const Tile& t, const ElevationModelOptions& options) {
    GDALRasterBand* band = t.dataset->GetRasterBand(1);
    vertical::RasterGrid g;
    g.cols = t.cols;
    g.rows = t.rows;
    g.values.resize(static_cast<std::size_t>(t.cols) * static_cast<std::size_t>(t.rows));
    CPLErrorHandlerPusher quiet(CPLQuietErrorHandler);
    CPLErrorReset();
    if (band->RasterIO(GF_Read, 0, 0, t.cols, t.rows, g.values.data(), t.cols, t.rows, GDT_Float32, 0, 0,
                       nullptr) != CE_None) {
        fail(t.path, "cannot read elevations" + gdal_message());
    }
    int has_nodata = 0;
    const double nodata = band->GetNoDataValue(&has_nodata);
    const auto nodata_f = static_cast<float>(nodata);
    const double scale = band->GetScale() * unit_factor(*band);
    const double offset = band->GetOffset() * unit_factor(*band);
    constexpr float nan = std::numeric_limits<float>::quiet_NaN();
    // Cells no terrain can have (infinities, or beyond the Dead Sea shore and
    // Everest with a margin: an unflagged no-data value such as -32768 or
    // 1e30) are voids like the no-data ones, filled or reported the same way.
    constexpr double lowest_m = -1000.0, highest_m = 10000.0;
    for (float& v : g.values) {
        const double e = static_cast<double>(v) * scale + offset;
        if (std::isnan(v) || (has_nodata && v == nodata_f) || !(e >= lowest_m && e <= highest_m)) {
            v = nan;
        } else {
            v = static_cast<float>(e);
        }
    }
    return vertical::fill_voids(g, options.void_fill_radius_px);
}

struct PixelPos {
    double col;
    double row;
};

std::optional<PixelPos> to_pixel(const Tile& t, ingest::LonLat p) {
    double x = p.lon;
    double y = p.lat;
    if (t.to_raster && !t.to_raster->Transform(1, &x, &y)) {
        return std::nullopt;
    }
    const double* g = t.inverse_gt;
    return PixelPos{g[0] + g[1] * x + g[2] * y, g[3] + g[4] * x + g[5] * y};
}

std::optional<ingest::LonLat> pixel_centre(const Tile& t, int col, int row) {
    const double* g = t.gt;
    double x = g[0] + (col + 0.5) * g[1] + (row + 0.5) * g[2];
    double y = g[3] + (col + 0.5) * g[4] + (row + 0.5) * g[5];
    if (t.to_wgs84 && !t.to_wgs84->Transform(1, &x, &y)) {
        return std::nullopt;
    }
    return ingest::LonLat{x, y};
}

// Inset 0.5: the pixel centres surround the point, bilinear needs no other
// tile. Inset 0: anywhere on the raster, including the outer half-pixel rim.
bool inside(const Tile& t, const PixelPos& px, double inset) {
    return px.col >= inset && px.col <= t.cols - inset && px.row >= inset && px.row <= t.rows - inset;
}

} // namespace

struct ElevationModel::Impl {
    ElevationModelOptions options;
    std::vector<Tile> tiles;
    std::mutex mutex; // guards lazy loading and the OGR transformations

    const vertical::RasterGrid& grid(Tile& t) {
        if (!t.grid) {
            t.grid = read_grid(t, options);
            t.dataset.reset(); // every pixel is in memory now
        }
        return *t.grid;
    }

    // From the first tile, other than `skip`, whose pixel centres surround p.
    std::optional<double> interior(ingest::LonLat p, const Tile* skip) {
        for (Tile& t : tiles) {
            const auto px = &t == skip ? std::nullopt : to_pixel(t, p);
            if (px && inside(t, *px, 0.5)) {
                if (auto z = vertical::bilinear(grid(t), px->col, px->row)) {
                    return z;
                }
            }
        }
        return std::nullopt;
    }

    // On a tile's outer rim: the pixels beyond its edge come from whichever
    // tile holds their centres, so abutting tiles interpolate across the seam
    // as if they were one raster; with no neighbour the edge pixels stand.
    std::optional<double> rim(ingest::LonLat p) {
        for (Tile& t : tiles) {
            const auto px = to_pixel(t, p);
            if (!px || !inside(t, *px, 0.0)) {
                continue;
            }
            const auto beyond = [&](int col, int row) -> std::optional<double> {
                const auto centre = pixel_centre(t, col, row);
                return centre ? interior(*centre, &t) : std::nullopt;
            };
            if (auto z = vertical::bilinear(grid(t), px->col, px->row, beyond)) {
                return z;
            }
        }
        return std::nullopt;
    }
};

ElevationModel::ElevationModel(const fs::path& file, ElevationModelOptions options)
    : ElevationModel(std::vector<fs::path>{file}, options) {}

ElevationModel::ElevationModel(const std::vector<fs::path>& files, ElevationModelOptions options)
    : impl_(std::make_unique<Impl>()) {
    GDALAllRegister();
    impl_->options = options;
    for (const auto& f : files) {
        impl_->tiles.push_back(open_tile(f, options));
    }
}

ElevationModel::~ElevationModel() = default;
ElevationModel::ElevationModel(ElevationModel&&) noexcept = default;
ElevationModel& ElevationModel::operator=(ElevationModel&&) noexcept = default;

std::size_t ElevationModel::tile_count() const noexcept { return impl_ ? impl_->tiles.size() : 0; }

std::optional<double> ElevationModel::sample(ingest::LonLat p) const {
    std::lock_guard lock(impl_->mutex);
    if (auto z = impl_->interior(p, nullptr)) {
        return z;
    }
    return impl_->rim(p);
}

} // namespace railodd::geometry
