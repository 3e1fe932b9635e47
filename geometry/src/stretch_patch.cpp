// Cutting a chain's fit round the nodes it misses; see stretch_patch.hpp.
#include "stretch_patch.hpp"

#include "design_splice.hpp"
#include "tie_splice.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace railodd::geometry {

namespace {

void append(Alignment& out, const Alignment& a) {
    if (out.primitives.empty()) {
        out.start = a.start;
    }
    out.primitives.insert(out.primitives.end(), a.primitives.begin(), a.primitives.end());
}

} // namespace

std::vector<std::pair<std::size_t, std::size_t>> missed_stretches(const Alignment& fit, const std::vector<Point>& p,
                                                                  const std::vector<char>& skip, double limit,
                                                                  std::size_t min_run, std::size_t reach) {
    const std::vector<double> t = polyline_chainage(p);
    const IndexedAlignment ia(fit, 2.0);
    const std::size_t n = p.size();
    std::vector<std::pair<std::size_t, std::size_t>> out;
    for (std::size_t k = 0; k < n; ++k) {
        if (skip[k] || !(node_on(ia, p, t, k).distance > limit)) {
            continue;
        }
        std::size_t a = k > reach ? k - reach : 0, b = std::min(n - 1, k + reach);
        a = a + 1 < min_run ? 0 : a;
        b = n - b < min_run ? n - 1 : b;
        if (!out.empty() && a + 1 < out.back().second + min_run) {
            out.back().second = b;
        } else {
            out.push_back({a, b});
        }
    }
    return out;
}

std::vector<std::pair<std::size_t, std::size_t>> runs_between(
    const std::vector<std::pair<std::size_t, std::size_t>>& stretches, std::size_t nodes) {
    std::vector<std::pair<std::size_t, std::size_t>> runs;
    std::size_t from = 0;
    bool open = true; // a run starts at `from`
    for (const auto& [a, b] : stretches) {
        if (open && a > from) {
            runs.push_back({from, a});
        }
        from = b;
        open = b + 1 < nodes;
    }
    if (open && from + 1 < nodes) {
        runs.push_back({from, nodes - 1});
    }
    return runs;
}

std::vector<std::pair<std::size_t, std::size_t>> with_failed_runs(
    std::vector<std::pair<std::size_t, std::size_t>> stretches,
    const std::vector<std::pair<std::size_t, std::size_t>>& runs, const std::vector<char>& ok) {
    for (std::size_t i = 0; i < runs.size(); ++i) {
        if (!ok[i]) {
            stretches.push_back(runs[i]);
        }
    }
    std::sort(stretches.begin(), stretches.end());
    std::vector<std::pair<std::size_t, std::size_t>> merged;
    for (const auto& r : stretches) {
        if (!merged.empty() && r.first <= merged.back().second) {
            merged.back().second = std::max(merged.back().second, r.second);
        } else {
            merged.push_back(r);
        }
    }
    return merged;
}

std::optional<Alignment> assemble_patched(const std::vector<Point>& p,
                                          const std::vector<std::pair<std::size_t, std::size_t>>& stretches,
                                          const std::vector<Alignment>& run_fits, const std::optional<Pose>& start,
                                          const std::optional<Pose>& end, const CornerFitOptions& o, double limit) {
    Alignment out;
    std::size_t next_run = 0; // index into run_fits
    if ((stretches.empty() || stretches.front().first > 0) && !run_fits.empty()) {
        append(out, run_fits[next_run++]);
    }
    for (const auto& [a, b] : stretches) {
        const std::optional<Pose> from =
            a == 0 ? start : std::optional<Pose>(evaluate(run_fits[next_run - 1], length(run_fits[next_run - 1])));
        const bool at_end = b + 1 == p.size();
        const std::optional<Pose> to = at_end ? end : std::optional<Pose>(run_fits[next_run].start);
        const std::vector<Point> nodes(p.begin() + static_cast<long>(a), p.begin() + static_cast<long>(b) + 1);
        Alignment piece = corner_polyline(nodes, from, to, o);
        if (from && to && !drivable(piece)) {
            // Corners tighter than a track turns between two poses (a jog
            // where two ways do not meet, nodes leaving a tie at an angle):
            // the design closest to the nodes within the limit, or no patch.
            std::optional<Alignment> design = closest_design_splice(nodes, *from, *to, limit);
            if (!design) {
                return std::nullopt;
            }
            piece = std::move(*design);
        } else if (off_polyline(piece, nodes) > limit) {
            return std::nullopt;
        }
        append(out, piece);
        if (!at_end) {
            append(out, run_fits[next_run++]);
        }
    }
    return out;
}

} // namespace railodd::geometry
