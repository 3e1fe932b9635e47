#include "raster_grid.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace railodd::geometry::vertical {

namespace {

// Smallest Chebyshev ring around (c, r) holding a valid pixel, 0 if none
// within radius.
int first_valid_ring(const RasterGrid& g, int c, int r, int radius) {
    for (int ring = 1; ring <= radius; ++ring) {
        for (int dr = -ring; dr <= ring; ++dr) {
            const int rr = r + dr;
            if (rr < 0 || rr >= g.rows) {
                continue;
            }
            // Whole rows at the top and bottom of the ring, two pixels otherwise.
            const int step = (dr == -ring || dr == ring) ? 1 : 2 * ring;
            for (int dc = -ring; dc <= ring; dc += step) {
                const int cc = c + dc;
                if (cc >= 0 && cc < g.cols && !std::isnan(g.at(cc, rr))) {
                    return ring;
                }
            }
        }
    }
    return 0;
}

float idw(const RasterGrid& g, int c, int r, int reach) {
    double sum = 0.0;
    double weight = 0.0;
    for (int rr = std::max(0, r - reach); rr <= std::min(g.rows - 1, r + reach); ++rr) {
        for (int cc = std::max(0, c - reach); cc <= std::min(g.cols - 1, c + reach); ++cc) {
            const float v = g.at(cc, rr);
            if (std::isnan(v)) {
                continue;
            }
            const double d2 = static_cast<double>((cc - c) * (cc - c) + (rr - r) * (rr - r));
            sum += v / d2;
            weight += 1.0 / d2;
        }
    }
    return static_cast<float>(sum / weight);
}

} // namespace

RasterGrid fill_voids(const RasterGrid& grid, int radius) {
    RasterGrid out = grid;
    for (int r = 0; r < grid.rows; ++r) {
        for (int c = 0; c < grid.cols; ++c) {
            if (!std::isnan(grid.at(c, r))) {
                continue;
            }
            const int ring = first_valid_ring(grid, c, r, radius);
            if (ring > 0) {
                out.values[static_cast<std::size_t>(r) * static_cast<std::size_t>(grid.cols) +
                           static_cast<std::size_t>(c)] = idw(grid, c, r, std::min(2 * ring, radius));
            }
        }
    }
    return out;
}

std::optional<double> bilinear(const RasterGrid& grid, double col, double row, const OutsideFn& outside) {
    if (grid.cols <= 0 || grid.rows <= 0) {
        return std::nullopt;
    }
    const double fc = col - 0.5;
    const double fr = row - 0.5;
    const int c0 = static_cast<int>(std::floor(fc));
    const int r0 = static_cast<int>(std::floor(fr));
    const double tc = fc - c0;
    const double tr = fr - r0;
    double z = 0.0;
    for (int k = 0; k < 4; ++k) {
        const int c = c0 + (k & 1);
        const int r = r0 + (k >> 1);
        const double w = ((k & 1) ? tc : 1.0 - tc) * ((k >> 1) ? tr : 1.0 - tr);
        if (w == 0.0) {
            continue; // a pixel the point does not touch does not matter
        }
        std::optional<double> v;
        if (c >= 0 && c < grid.cols && r >= 0 && r < grid.rows) {
            v = grid.at(c, r);
        } else if (outside) {
            v = outside(c, r);
        }
        if (!v) {
            v = grid.at(std::clamp(c, 0, grid.cols - 1), std::clamp(r, 0, grid.rows - 1));
        }
        if (std::isnan(*v)) {
            return std::nullopt;
        }
        z += w * *v;
    }
    return z;
}

} // namespace railodd::geometry::vertical
