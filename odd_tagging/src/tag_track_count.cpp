// Track count: how many tracks run side by side. Every track is sampled every
// few metres; at each sample the other tracks passing within track_spacing_m
// of it, roughly parallel, are counted, and stretches of equal count become
// Track count elements (1 single, 2 double, more multiple through the
// taxonomy's bins).
#include "tag_context.hpp"

#include "railodd/util/cell_grid.hpp"

#include <cmath>
#include <map>
#include <set>

namespace railodd::odd {

namespace {

constexpr double sample_m = 10.0;
constexpr double probe_m = 25.0;
// Track centres are 3.5-4.5 m apart on European main lines (up to ~6 m at
// platforms): a neighbour within 6.5 m counts as a parallel track.
constexpr double track_spacing_m = 6.5;
constexpr double max_skew = 0.25; // |sin| of the angle between parallel tracks

struct Sample {
    std::size_t edge;
    double x, y, hdg;
};

using Grid = util::CellGrid<Sample>;

int neighbours(const Grid& grid, std::size_t edge, const geometry::Pose& p) {
    std::set<std::size_t> found;
    grid.near(p.x, p.y, 1, [&](const Sample& s) {
        if (s.edge != edge && std::hypot(s.x - p.x, s.y - p.y) <= track_spacing_m &&
            std::abs(std::sin(s.hdg - p.hdg)) <= max_skew) {
            found.insert(s.edge);
        }
    });
    return static_cast<int>(found.size());
}

} // namespace

void tag_track_count(TagContext& ctx) {
    // Every track's samples, once for all batches: a batch's tracks count
    // their neighbours in any batch.
    const Grid& grid = ctx.prepared<Grid>("track_count", [&] {
        Grid g(track_spacing_m);
        ctx.for_each_alignment([&](std::size_t e, const geometry::IndexedAlignment& ia) {
            for (double s = 0.0; s <= ia.length(); s += sample_m) {
                const auto p = ia.evaluate(s);
                g.add_point(p.x, p.y, {e, p.x, p.y, p.hdg});
            }
        });
        return g;
    });
    for (std::size_t e = ctx.first(); e < ctx.last(); ++e) {
        const auto& ia = ctx.alignment(e);
        const double len = ia.length();
        if (len <= 1e-6) {
            continue;
        }
        const int k = std::max(1, static_cast<int>(std::ceil(len / probe_m)));
        double start = 0.0;
        int current = -1;
        for (int i = 0; i <= k; ++i) {
            const double s = len * std::min(i, k - 1) / k + len / (2.0 * k); // mid of each probe stretch
            const int count = i < k ? 1 + neighbours(grid, e, ia.evaluate(s)) : -1;
            if (count != current) {
                const double boundary = len * i / k;
                if (current > 0) {
                    ctx.tag("Scenery/Track layout/Track count", e, start, boundary,
                            {{"tracks", static_cast<double>(current)}}, ctx.way_ids(e, start, boundary), "derived");
                }
                start = boundary;
                current = count;
            }
        }
    }
}

} // namespace railodd::odd
