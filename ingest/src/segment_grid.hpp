#pragma once
// Uniform grid over polyline segments in the local frame, answering "is this
// point within d metres of a track?" for the road corridor and feature snapping.
#include "railodd/ingest/projection.hpp"
#include "railodd/util/cell_grid.hpp"

#include <cstdint>
#include <vector>

namespace railodd::ingest {

class SegmentGrid {
public:
    explicit SegmentGrid(double cell_size_m);

    void add_polyline(const std::vector<XY>& points);

    // True if some segment passes within max_distance of p. Cells are visited
    // nearest first so points on or beside a track answer after a few tests.
    bool within(XY p, double max_distance) const;

private:
    struct Segment {
        XY a, b;
    };
    std::int64_t cell(double v) const noexcept;
    void register_cells(std::uint32_t index);
    bool cell_within(std::int64_t cx, std::int64_t cy, XY p, double max_distance) const;

    double cell_;
    std::vector<Segment> segments_;
    util::CellGrid<std::uint32_t> cells_;
};

} // namespace railodd::ingest
