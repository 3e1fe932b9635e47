#pragma once
// The DEM raster: a north-up EPSG:4326 grid of whole arc-seconds, written as a
// Float32 GeoTIFF through GDAL (kept out of every header).
#include <filesystem>
#include <vector>

namespace railodd::sample {

struct DemGrid {
    double west = 0.0;  // lon of the left edge of column 0, degrees
    double north = 0.0; // lat of the top edge of row 0, degrees
    double step = 1.0 / 3600.0;
    int cols = 0;
    int rows = 0;

    double lon(int col) const { return west + (col + 0.5) * step; }
    double lat(int row) const { return north - (row + 0.5) * step; }
};

inline constexpr float dem_nodata = -32768.0f;

// Smallest arc-second-aligned grid covering the box plus margin_m on each side.
DemGrid dem_grid(double min_lon, double min_lat, double max_lon, double max_lat, double margin_m);

// values: rows * cols, row-major from the north-west corner. Throws
// railodd::OutputError naming path when GDAL fails.
void write_dem(const std::filesystem::path& path, const DemGrid& grid, const std::vector<float>& values);

} // namespace railodd::sample
