#pragma once
// A digital elevation model read through GDAL: one raster or several tiles
// side by side (GeoTIFF, SRTM .hgt, .vrt, anything GDAL reads), in any CRS,
// sampled by WGS84 lon/lat with bilinear interpolation and voids filled from
// their valid neighbours. GDAL stays inside the .cpp file.
#include "railodd/ingest/projection.hpp"

#include <cstddef>
#include <filesystem>
#include <memory>
#include <optional>
#include <vector>

namespace railodd::geometry {

struct ElevationModelOptions {
    // Voids (nodata) are filled by inverse-distance weighting of the valid
    // pixels around them; a void with no valid pixel within this many pixels
    // (Chebyshev distance) stays a void. 10 px is ~900 m of SRTM 3".
    int void_fill_radius_px = 10;
    // Each tile is held in memory whole once it is first sampled; a bigger
    // raster is refused at construction (crop it or use a .vrt of tiles).
    std::size_t max_pixels_per_tile = 100'000'000;
};

// Memory: a tile's band is read whole, as float, the first time a sample
// falls on it, and its voids are filled then, once; tiles never sampled are
// never read. SRTM tiles are 1.4 M (3") or 13 M (1") pixels, so this costs
// little and makes every later sample a pure lookup.
//
// Thread safety: sample() may be called concurrently; calls are serialised
// (lazy loading and OGR coordinate transformations are not reentrant).
class ElevationModel {
public:
    // Opens every file and reads its metadata; pixels are read lazily.
    // Throws railodd::InputError naming the file when it does not exist, is
    // unreadable or not a raster, has no georeferencing or no CRS, or exceeds
    // max_pixels_per_tile.
    explicit ElevationModel(const std::filesystem::path& file, ElevationModelOptions options = {});
    explicit ElevationModel(const std::vector<std::filesystem::path>& files, ElevationModelOptions options = {});
    ~ElevationModel();
    ElevationModel(ElevationModel&&) noexcept;
    ElevationModel& operator=(ElevationModel&&) noexcept;
    ElevationModel(const ElevationModel&) = delete;
    ElevationModel& operator=(const ElevationModel&) = delete;

    // Elevation in metres (the band's scale, offset and feet are applied) at
    // a WGS84 position; nullopt outside every tile, or where a void has no
    // valid pixel within the fill radius. Where tiles overlap, the first tile
    // (in the order given) whose pixel centres surround the point answers.
    // Within half a pixel of a tile's edge, the pixels beyond it come from the
    // tile holding their centres (abutting tiles interpolate across the seam
    // as one raster), or are the edge pixels at the outer edge of the DEM.
    // Throws railodd::InputError naming the file if a tile's pixels cannot
    // be read when first needed.
    std::optional<double> sample(ingest::LonLat p) const;

    std::size_t tile_count() const noexcept;

private:
    struct Impl;
    std::unique_ptr<Impl> impl_;
};

} // namespace railodd::geometry
