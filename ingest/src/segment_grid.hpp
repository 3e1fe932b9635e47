#pragma once
// Uniform grid over polyline segments in the local frame, answering "is this
// point within d metres of a track?" for the road corridor and feature snapping.
#include "railodd/ingest/projection.hpp"

#include <cstdint>
#include <unordered_map>
#include <vector>

namespace railodd::ingest {

class SegmentGrid {
public:
    explicit SegmentGrid(double cell_size_m);

    void add_polyline(const std::vector<XY>& points);

    // Distance from p to the nearest segment if it is at most max_distance, else a
    // value greater than max_distance.
    double distance(XY p, double max_distance) const;

    bool empty() const noexcept { return segments_.empty(); }

private:
    struct Segment {
        XY a, b;
    };
    std::int64_t key(std::int64_t cx, std::int64_t cy) const noexcept { return (cx << 32) ^ (cy & 0xffffffff); }
    std::int64_t cell(double v) const noexcept;

    double cell_;
    std::vector<Segment> segments_;
    std::unordered_map<std::int64_t, std::vector<std::uint32_t>> cells_;
};

} // namespace railodd::ingest
