#pragma once
// An alignment prepared for many queries: primitive start poses are chained
// once and a coarse sample polyline seeds nearest-point searches, so residual
// measurement over thousands of points stays linear in their number.
#include "railodd/geometry/alignment.hpp"

#include <optional>
#include <vector>

namespace railodd::geometry {

class IndexedAlignment {
public:
    // sample_step (m) must be small against the tightest radius and the
    // distance of the queried points, or a search may settle in the wrong
    // basin; 2 m is ample for railway geometry.
    explicit IndexedAlignment(Alignment alignment, double sample_step = 2.0);
    // For length() and evaluate() only, which it answers as the indexed one
    // does: sampled at the primitives' joints alone, so that project() may
    // settle in the wrong basin. A network's worth costs its primitives, not
    // its length (the tagger's passes over every track).
    static IndexedAlignment for_evaluation(Alignment alignment);

    const Alignment& alignment() const noexcept { return alignment_; }
    double length() const noexcept { return length_; }

    // Same contract as evaluate(const Alignment&, double).
    Pose evaluate(double s) const;

    // Nearest point: the closest coarse sample picks the basin, then a
    // safeguarded Newton iteration on the tangential residual finds s.
    Projection project(double x, double y) const;

    // Nearest point with arc length in [s_lo, s_hi]: for points known to lie
    // near a stretch (ordered points along a track), far cheaper than project().
    Projection project_within(double x, double y, double s_lo, double s_hi) const;

    // project(), or nothing where the curve passes nowhere within `radius`
    // of (x, y) (no sample within radius plus the sample step): the refine
    // is spared for points that are not near.
    std::optional<Projection> project_near(double x, double y, double radius) const;

    // Same as chord_stations(alignment(), ...), in O(log n + stations).
    std::vector<double> chord_stations(double s0, double s1, double max_sagitta) const;

private:
    struct Sample {
        double s;
        double x;
        double y;
    };

    // Bounding box of block_size consecutive samples; tree_ holds them as the
    // leaves of a binary tree (heap order) whose inner boxes enclose their
    // children, so a nearest-sample search costs O(log n), not O(n), blocks.
    struct Box {
        double x0, y0, x1, y1;
    };
    static constexpr std::size_t block_size = 32;

    std::size_t primitive_at(double s) const;
    std::size_t nearest_sample(double x, double y, std::size_t first, std::size_t last) const;
    void build_tree();
    double refine(double x, double y, double lo, double hi, double guess) const;
    Projection project_samples(double x, double y, std::size_t first, std::size_t last) const;
    // The foot near sample `best`.
    Projection refined(double x, double y, std::size_t best) const;

    Alignment alignment_;
    double step_ = 0.0; // the largest gap between samples
    std::vector<Pose> starts_;
    std::vector<double> s_starts_;
    double length_ = 0.0;
    std::vector<Sample> samples_;
    std::vector<Box> tree_;
    std::size_t leaves_ = 0; // blocks rounded up to a power of two
};

} // namespace railodd::geometry
