#pragma once
// One tile's elevations in memory, independent of GDAL: void filling and
// bilinear interpolation in pixel coordinates.
#include <functional>
#include <optional>
#include <vector>

namespace railodd::geometry::vertical {

// Row-major from the top-left pixel; NaN marks a void.
struct RasterGrid {
    int cols = 0;
    int rows = 0;
    std::vector<float> values;

    float at(int col, int row) const {
        return values[static_cast<std::size_t>(row) * static_cast<std::size_t>(cols) + static_cast<std::size_t>(col)];
    }
};

// Returns the grid with each void replaced by the inverse-square-distance
// mean of the valid pixels around it: the search grows ring by ring until a
// valid pixel appears at ring r0, then takes every valid pixel within ring
// 2 r0 (capped at radius) so the fill blends the void's whole rim rather than
// copying the single nearest pixel. Only original valid pixels feed the fill,
// so the result does not depend on the order of the voids. Voids with no
// valid pixel within radius stay NaN.
RasterGrid fill_voids(const RasterGrid& grid, int radius);

// Value of a pixel beyond the grid's edge (col or row out of range), e.g.
// from the neighbouring tile; nullopt if unknown.
using OutsideFn = std::function<std::optional<double>(int col, int row)>;

// Bilinear interpolation between pixel centres at pixel coordinates (col, row)
// measured from the top-left corner of the raster (the centre of pixel (0, 0)
// is (0.5, 0.5)). Within half a pixel of the outer edge the missing pixels
// come from `outside`, or are the nearest edge pixels where it does not know
// them. nullopt if a pixel with non-zero weight is a void.
std::optional<double> bilinear(const RasterGrid& grid, double col, double row, const OutsideFn& outside = {});

} // namespace railodd::geometry::vertical
