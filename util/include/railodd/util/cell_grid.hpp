#pragma once
// Items in the cells of a uniform square grid on the local plane: how the
// stages ask "what lies near this point?" (segments near a road node in
// ingest, a parallel track's segments in the fit, samples of tracks, roads
// and land use in the tagger and the report). One cell holds its items in
// the order they were added, and every query visits cells in a fixed order
// (x, then y), never the hash table's: what a query finds first, and so any
// tie it breaks, does not depend on the table.
#include <cmath>
#include <cstdint>
#include <unordered_map>
#include <utility>
#include <vector>

namespace railodd::util {

template <class T>
class CellGrid {
public:
    explicit CellGrid(double cell_m) : cell_(cell_m) {}

    double cell_size() const { return cell_; }
    std::int64_t cell_of(double v) const { return static_cast<std::int64_t>(std::floor(v / cell_)); }

    void add(std::int64_t cx, std::int64_t cy, T item) { cells_[key(cx, cy)].push_back(std::move(item)); }
    void add_point(double x, double y, T item) { add(cell_of(x), cell_of(y), std::move(item)); }

    // The item in every cell the box [x0, x1] x [y0, y1] touches; false and
    // none where that is over max_cells (a segment kilometres long).
    bool add_box(double x0, double y0, double x1, double y1, const T& item, std::int64_t max_cells = 1 << 20) {
        const std::int64_t cx0 = cell_of(x0), cx1 = cell_of(x1), cy0 = cell_of(y0), cy1 = cell_of(y1);
        if ((cx1 - cx0 + 1) * (cy1 - cy0 + 1) > max_cells) {
            return false;
        }
        for (std::int64_t cx = cx0; cx <= cx1; ++cx) {
            for (std::int64_t cy = cy0; cy <= cy1; ++cy) {
                add(cx, cy, item);
            }
        }
        return true;
    }

    // The items of one cell, in the order added (null where it has none).
    const std::vector<T>* at(std::int64_t cx, std::int64_t cy) const {
        const auto it = cells_.find(key(cx, cy));
        return it == cells_.end() ? nullptr : &it->second;
    }

    // f(item) for every item in the cells within `reach` cells of (x, y)'s
    // cell, cells by x then y, each cell's items in the order added.
    template <class F>
    void near(double x, double y, std::int64_t reach, F&& f) const {
        const std::int64_t cx = cell_of(x), cy = cell_of(y);
        for (std::int64_t gx = cx - reach; gx <= cx + reach; ++gx) {
            for (std::int64_t gy = cy - reach; gy <= cy + reach; ++gy) {
                if (const std::vector<T>* items = at(gx, gy)) {
                    for (const T& item : *items) {
                        f(item);
                    }
                }
            }
        }
    }

    bool empty() const { return cells_.empty(); }

private:
    static std::uint64_t key(std::int64_t cx, std::int64_t cy) {
        return (static_cast<std::uint64_t>(cx) << 32) ^ static_cast<std::uint32_t>(cy);
    }

    double cell_;
    std::unordered_map<std::uint64_t, std::vector<T>> cells_;
};

} // namespace railodd::util
