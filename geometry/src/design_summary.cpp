#include "railodd/geometry/design_summary.hpp"

#include "railodd/geometry/indexed_alignment.hpp"
#include "railodd/util/beside.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <future>
#include <numbers>
#include <optional>
#include <unordered_map>

namespace railodd::geometry {

namespace {

constexpr double straight = 1.0 / 20000.0; // curvature below which a track is straight
constexpr double curved = 1.0 / 5000.0;    // curvature from which parallel curves are compared
constexpr double short_element_m = 1.0;
constexpr double steady_m = 20.0, steady_offset_m = 0.5; // a parallel track keeps its offset this far either way

struct Sample {
    std::size_t track = 0;
    double s = 0.0;
    Pose pose;
};

// What a neighbour query reads of a sample.
struct Entry {
    std::uint32_t track = 0;
    double s = 0.0;
    double x = 0.0, y = 0.0;
};

// Every track's samples by 10 m cell: one flat array sorted by cell (in the
// order added within a cell) rather than a hash map of vectors, which on
// Cologne's 194,000 samples held 30 MB for a moment and set the run's peak.
class SampleGrid {
public:
    static constexpr double cell = 10.0;
    void add(const Sample& q) {
        cells_.push_back({key(q.pose.x, q.pose.y), {static_cast<std::uint32_t>(q.track), q.s, q.pose.x, q.pose.y}});
    }
    void seal() {
        std::stable_sort(cells_.begin(), cells_.end(),
                         [](const auto& a, const auto& b) { return a.first < b.first; });
    }
    template <typename F>
    void near(double x, double y, F&& f) const {
        const auto cx = static_cast<std::int64_t>(std::floor(x / cell)), cy = static_cast<std::int64_t>(std::floor(y / cell));
        for (std::int64_t dx = -1; dx <= 1; ++dx) {
            for (std::int64_t dy = -1; dy <= 1; ++dy) {
                const std::int64_t k = pack(cx + dx, cy + dy);
                auto it = std::lower_bound(cells_.begin(), cells_.end(), k,
                                           [](const auto& c, std::int64_t v) { return c.first < v; });
                for (; it != cells_.end() && it->first == k; ++it) {
                    f(it->second);
                }
            }
        }
    }

private:
    static std::int64_t pack(std::int64_t cx, std::int64_t cy) { return cx * 4294967311LL + cy; }
    static std::int64_t key(double x, double y) {
        return pack(static_cast<std::int64_t>(std::floor(x / cell)), static_cast<std::int64_t>(std::floor(y / cell)));
    }
    std::vector<std::pair<std::int64_t, Entry>> cells_;
};

// Whether a track keeps its offset from a neighbour (foot f) 20 m either
// way, within 0.5 m: a turnout's leg or a crossover passes 3-6 m from the
// other track for a few tens of metres at an angle, and is no double track
// (VDE 8.2: 3,531 of the 5,207 points over 10 % lay on such encounters
// shorter than 100 m, of 4,007 points there). A side where either track
// ends (an edge at a switch) tells nothing; one side must tell.
bool keeps_offset(const Sample& q, const IndexedAlignment& self, const IndexedAlignment& other, const Projection& f) {
    int told = 0;
    for (const double ds : {-steady_m, steady_m}) {
        const double s = q.s + ds;
        if (s < 0.0 || s > self.length()) {
            continue;
        }
        const Pose p = self.evaluate(s);
        const Projection g = other.project_within(p.x, p.y, f.s - 2.0 * steady_m, f.s + 2.0 * steady_m);
        if (g.s <= 0.0 || g.s >= other.length()) {
            continue;
        }
        if (std::abs(g.offset - f.offset) > steady_offset_m) {
            return false;
        }
        ++told;
    }
    return told > 0;
}

// The relative curvature difference at a curved sample and its parallel
// neighbour: the nearest other track whose foot lies 3-6 m beside it, within
// 0.05 rad of its direction (either way), keeping that offset 20 m either
// way. The track's own continuation (another edge) is at its foot and is
// passed over.
std::optional<double> parallel_difference(const Sample& q, const SampleGrid& grid,
                                          const std::vector<IndexedAlignment>& tracks) {
    std::vector<std::pair<double, const Entry*>> near;
    grid.near(q.pose.x, q.pose.y, [&](const Entry& c) {
        const double d = std::hypot(c.x - q.pose.x, c.y - q.pose.y);
        if (c.track != q.track && d < 12.0) {
            near.emplace_back(d, &c);
        }
    });
    std::sort(near.begin(), near.end(), [](const auto& a, const auto& b) {
        return a.first < b.first || (a.first == b.first && a.second->track < b.second->track);
    });
    for (std::size_t i = 0; i < near.size(); ++i) {
        const std::size_t other = near[i].second->track;
        if (std::any_of(near.begin(), near.begin() + static_cast<std::ptrdiff_t>(i),
                        [&](const auto& e) { return e.second->track == other; })) {
            continue;
        }
        const double at = near[i].second->s;
        const Projection f = tracks[other].project_within(q.pose.x, q.pose.y, at - 20.0, at + 20.0);
        if (f.distance < 3.0 || f.distance > 6.0 || f.s <= 0.0 || f.s >= tracks[other].length()) {
            continue;
        }
        const Pose n = tracks[other].evaluate(f.s);
        const double turn = std::remainder(n.hdg - q.pose.hdg, 2 * std::numbers::pi);
        const bool opposite = std::abs(turn) > 0.5 * std::numbers::pi;
        if (std::abs(std::remainder(turn, std::numbers::pi)) > 0.05 || !keeps_offset(q, tracks[q.track], tracks[other], f)) {
            continue;
        }
        // The neighbour's curvature and this point's offset from it (left
        // positive), both in this track's direction; concentric with the
        // neighbour, this track's curvature is k / (1 - k d).
        const double k = opposite ? -n.curvature : n.curvature;
        const double d = opposite ? -f.offset : f.offset;
        const double expected = k / (1.0 - k * d);
        return std::abs(q.pose.curvature - expected) / std::max(std::abs(q.pose.curvature), std::abs(expected));
    }
    return std::nullopt;
}

double quantile(std::vector<double> v, double q) {
    if (v.empty()) {
        return 0.0;
    }
    std::sort(v.begin(), v.end());
    return v[static_cast<std::size_t>(std::floor(q * static_cast<double>(v.size() - 1)))];
}

} // namespace

std::size_t curvature_sign_changes(const IndexedAlignment& a) {
    std::size_t n = 0;
    int last = 0;
    for (double s = 0.0; s <= a.length(); s += 5.0) {
        const double k = a.evaluate(s).curvature;
        const int sign = k > straight ? 1 : (k < -straight ? -1 : 0);
        if (sign != 0) {
            n += last != 0 && sign != last ? 1 : 0;
            last = sign;
        }
    }
    return n;
}

DesignSummary summarise_design(const std::vector<Alignment>& alignments, bool two_threads) {
    std::vector<IndexedAlignment> tracks;
    tracks.reserve(alignments.size());
    for (const Alignment& a : alignments) {
        tracks.emplace_back(a, 2.0);
    }
    return summarise_design(tracks, two_threads);
}

namespace {

// The parallel curvature differences at samples [first, last) of `curved`.
std::vector<double> parallel_differences(const std::vector<Sample>& curved, std::size_t first, std::size_t last,
                                         const SampleGrid& grid, const std::vector<IndexedAlignment>& tracks) {
    std::vector<double> diff;
    for (std::size_t i = first; i < last; ++i) {
        if (const auto d = parallel_difference(curved[i], grid, tracks)) {
            diff.push_back(*d);
        }
    }
    return diff;
}

} // namespace

DesignSummary summarise_design(const std::vector<IndexedAlignment>& tracks, bool two_threads) {
    // Each half of the work beside the other: the sign changes beside the
    // sample grid, the second half of the curved samples' neighbours beside
    // the first. Each reads the tracks and the grid only, and the quantiles
    // sort, so no figure depends on the split.
    const std::launch beside = util::beside(two_threads);
    std::future<std::size_t> sign_changes = std::async(beside, [&tracks] {
        std::size_t n = 0;
        for (const IndexedAlignment& t : tracks) {
            n += curvature_sign_changes(t);
        }
        return n;
    });
    DesignSummary out;
    double length_m = 0.0, spiral_m = 0.0, arc_m = 0.0;
    std::size_t elements = 0, short_elements = 0, joints = 0;
    for (const IndexedAlignment& t : tracks) {
        for (const Primitive& p : t.alignment().primitives) {
            length_m += p.length;
            spiral_m += p.kind == PrimitiveKind::spiral ? p.length : 0.0;
            arc_m += p.kind == PrimitiveKind::arc ? p.length : 0.0;
            short_elements += p.length < short_element_m ? 1 : 0;
        }
        elements += t.alignment().primitives.size();
        joints += std::max<std::size_t>(t.alignment().primitives.size(), 1) - 1;
    }
    if (length_m <= 0.0) {
        return out; // the sign changes are none (an async future joins as it goes)
    }
    out.length_km = length_m / 1000.0;
    out.spiral_share = spiral_m / length_m;
    out.arc_share = arc_m / length_m;
    out.elements_per_km = static_cast<double>(elements) / out.length_km;
    out.joints_per_km = static_cast<double>(joints) / out.length_km;
    out.short_element_share = static_cast<double>(short_elements) / static_cast<double>(elements);
    SampleGrid grid;
    std::vector<Sample> curved_samples;
    for (std::size_t t = 0; t < tracks.size(); ++t) {
        for (double s = 0.0; s <= tracks[t].length(); s += 10.0) {
            const Sample q{t, s, tracks[t].evaluate(s)};
            grid.add(q);
            if (std::abs(q.pose.curvature) > curved) {
                curved_samples.push_back(q);
            }
        }
    }
    grid.seal();
    out.sign_changes_per_km = static_cast<double>(sign_changes.get()) / out.length_km;
    const std::size_t half = curved_samples.size() / 2;
    std::future<std::vector<double>> second = std::async(beside, [&] {
        return parallel_differences(curved_samples, half, curved_samples.size(), grid, tracks);
    });
    std::vector<double> diff = parallel_differences(curved_samples, 0, half, grid, tracks);
    const std::vector<double> rest = second.get();
    diff.insert(diff.end(), rest.begin(), rest.end());
    out.parallel_pairs = diff.size();
    out.parallel_difference_p50 = quantile(diff, 0.5);
    out.parallel_difference_p95 = quantile(diff, 0.95);
    out.parallel_share_over_10pct =
        diff.empty() ? 0.0
                     : static_cast<double>(std::count_if(diff.begin(), diff.end(), [](double x) { return x > 0.1; })) /
                           static_cast<double>(diff.size());
    return out;
}

} // namespace railodd::geometry
