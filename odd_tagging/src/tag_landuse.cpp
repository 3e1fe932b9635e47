// Surroundings: land use. Every track is probed every 25 m; the smallest
// land-use area holding the probe gives its kind (a village inside a forest
// polygon is the village), and stretches of one kind become Land use
// elements with the areas' OSM ids and the track's ways. landuse=railway is
// the railway's own strip of land, mapped between the town or fields around
// it: where it holds the probe, the area beside it (40, 80, 150 m either
// side) is the surroundings, and only without one does the railway land
// (industrial) count. Where no area holds the track nothing is tagged:
// unmapped land is not assumed rural.
#include "tag_context.hpp"

#include "railodd/util/cell_grid.hpp"

#include <algorithm>
#include <cmath>
#include <map>
#include <set>
#include <tuple>

namespace railodd::odd {

namespace {

constexpr double probe_m = 25.0;
constexpr double cell_m = 250.0; // a few probes per cell; big areas register only cells with probes
constexpr double beside_m[] = {40.0, 80.0, 150.0}; // lateral probes across railway land

using Cell = std::pair<long, long>;

Cell cell_of(double x, double y) {
    return {static_cast<long>(std::floor(x / cell_m)), static_cast<long>(std::floor(y / cell_m))};
}

struct Box {
    double x0, y0, x1, y1;
    bool holds(double x, double y) const { return x >= x0 && x <= x1 && y >= y0 && y <= y1; }
};

Box box_of(const ingest::LandUseArea& a) {
    Box b{1e300, 1e300, -1e300, -1e300};
    for (const auto& ring : a.rings) {
        for (const auto& p : ring) {
            b = {std::min(b.x0, p.x), std::min(b.y0, p.y), std::max(b.x1, p.x), std::max(b.y1, p.y)};
        }
    }
    return b;
}

// Even-odd over all rings: holes of multipolygons are outside.
bool inside(const ingest::LandUseArea& a, double x, double y) {
    bool in = false;
    for (const auto& r : a.rings) {
        for (std::size_t i = 0, j = r.size() - 1; i < r.size(); j = i++) {
            if ((r[i].y > y) != (r[j].y > y) && x < (r[j].x - r[i].x) * (y - r[i].y) / (r[j].y - r[i].y) + r[i].x) {
                in = !in;
            }
        }
    }
    return in;
}

// Areas by cell, smallest first (then by OSM type and id: deterministic ties),
// registered only in the cells that hold probes.
class AreaIndex {
public:
    AreaIndex(const std::vector<ingest::LandUseArea>& areas, const std::set<Cell>& probed) {
        for (const auto& a : areas) {
            order_.push_back({&a, box_of(a)});
        }
        std::sort(order_.begin(), order_.end(), [](const Entry& x, const Entry& y) {
            return std::tie(x.area->area_m2, x.area->osm_type, x.area->id) <
                   std::tie(y.area->area_m2, y.area->osm_type, y.area->id);
        });
        for (std::size_t i = 0; i < order_.size(); ++i) {
            const Box& b = order_[i].box;
            const Cell lo = cell_of(b.x0, b.y0), hi = cell_of(b.x1, b.y1);
            const double span = double(hi.first - lo.first + 1) * double(hi.second - lo.second + 1);
            if (span <= double(probed.size())) {
                for (long cx = lo.first; cx <= hi.first; ++cx) {
                    for (long cy = lo.second; cy <= hi.second; ++cy) {
                        if (probed.contains({cx, cy})) {
                            cells_.add(cx, cy, i);
                        }
                    }
                }
            } else {
                for (const Cell& c : probed) {
                    if (c.first >= lo.first && c.first <= hi.first && c.second >= lo.second && c.second <= hi.second) {
                        cells_.add(c.first, c.second, i);
                    }
                }
            }
        }
    }

    const ingest::LandUseArea* at(double x, double y) const {
        const std::vector<std::size_t>* ids = cells_.at(cells_.cell_of(x), cells_.cell_of(y));
        if (!ids) {
            return nullptr;
        }
        for (const std::size_t i : *ids) {
            if (order_[i].box.holds(x, y) && inside(*order_[i].area, x, y)) {
                return order_[i].area;
            }
        }
        return nullptr;
    }

private:
    struct Entry {
        const ingest::LandUseArea* area;
        Box box;
    };
    std::vector<Entry> order_;
    util::CellGrid<std::size_t> cells_{cell_m};
};

int probe_count(double length) { return std::max(1, static_cast<int>(std::ceil(length / probe_m))); }

bool railway_land(const ingest::LandUseArea* a) { return a && a->tag == "landuse=railway"; }

// The point `d` metres left (side 1) or right (side -1) of the track.
std::pair<double, double> beside(const geometry::Pose& p, double d, int side) {
    return {p.x - side * d * std::sin(p.hdg), p.y + side * d * std::cos(p.hdg)};
}

std::set<Cell> probed_cells(const TagContext& ctx) {
    std::set<Cell> cells;
    ctx.for_each_alignment([&](std::size_t, const geometry::IndexedAlignment& ia) {
        const int k = probe_count(ia.length());
        for (int i = 0; i < k; ++i) {
            const auto p = ia.evaluate(ia.length() * (i + 0.5) / k);
            cells.insert(cell_of(p.x, p.y));
            for (const double d : beside_m) {
                for (const int side : {1, -1}) {
                    const auto [x, y] = beside(p, d, side);
                    cells.insert(cell_of(x, y));
                }
            }
        }
    });
    return cells;
}

// The area holding the probe; across railway land, the nearest other area
// beside the track (the smaller of the two sides at one distance).
const ingest::LandUseArea* surroundings(const AreaIndex& index, const geometry::Pose& p) {
    const ingest::LandUseArea* here = index.at(p.x, p.y);
    if (!railway_land(here)) {
        return here;
    }
    for (const double d : beside_m) {
        const ingest::LandUseArea* best = nullptr;
        for (const int side : {1, -1}) {
            const auto [x, y] = beside(p, d, side);
            const ingest::LandUseArea* a = index.at(x, y);
            if (a && !railway_land(a) && (!best || a->area_m2 < best->area_m2)) {
                best = a;
            }
        }
        if (best) {
            return best;
        }
    }
    return here;
}

std::string id_of(const ingest::LandUseArea& a) { return a.osm_type + ":" + std::to_string(a.id); }

} // namespace

void tag_land_use(TagContext& ctx) {
    const char* const path = "Scenery/Surroundings/Land use";
    const auto& areas = ctx.geo().ingest.land_use;
    if (areas.empty()) {
        return;
    }
    // Registered in the cells of every batch's probes, once.
    const AreaIndex& index = ctx.prepared<AreaIndex>("land_use", [&] { return AreaIndex(areas, probed_cells(ctx)); });
    for (std::size_t e = ctx.first(); e < ctx.last(); ++e) {
        const auto& ia = ctx.alignment(e);
        const int k = probe_count(ia.length());
        std::string kind; // of the open run; "" none
        double start = 0.0;
        std::set<std::string> area_ids;
        for (int i = 0; i <= k; ++i) {
            const ingest::LandUseArea* a = nullptr;
            if (i < k) {
                a = surroundings(index, ia.evaluate(ia.length() * (i + 0.5) / k));
            }
            const std::string now = a ? a->kind : "";
            const double boundary = ia.length() * i / k;
            if (now != kind) {
                if (!kind.empty()) {
                    auto ids = ctx.way_ids(e, start, boundary);
                    ids.insert(ids.end(), area_ids.begin(), area_ids.end());
                    ctx.tag(path, e, start, boundary, {{"kind", kind}}, ids, "osm");
                }
                kind = now;
                start = boundary;
                area_ids.clear();
            }
            if (a) {
                area_ids.insert(id_of(*a));
            }
        }
    }
}

} // namespace railodd::odd
