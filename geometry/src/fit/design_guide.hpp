#pragma once
// A parallel track's design as a prior on a chain's curvature in the design
// search (issue 37 item 7): where the chain's reference runs 2.5-6.5 m
// beside a track already fitted, the same way or the other, the design's
// curvature is pulled to the neighbour's concentric one, k / (1 - d k) at
// offset d, so the two tracks of a double-track line share their curves and
// their knots where their nodes allow.
#include "design_quadratic.hpp"

#include "railodd/geometry/indexed_alignment.hpp"

#include <memory>
#include <utility>
#include <vector>

namespace railodd::geometry::fit {

class ReferenceLine;

class GuideCurvature {
public:
    // Sampled every `step` metres of the reference over chainages [t0, t1];
    // `weight` per metre per (1/m)^2, in the cost's units. Only where the
    // chain's own last design (`own`, in this frame) agrees with the guide
    // within the noise of a design's curvature: where they differ more, the
    // neighbour's curve is not this track's (a track leaving for a flyover,
    // a siding beside a platform).
    GuideCurvature(const ReferenceLine& ref, double t0, double t1, const std::vector<IndexedAlignment>& guides,
                   const std::vector<FrameElement>& own, double weight, double step = 2.0);
    bool empty() const { return !(sums_.back().w > 0.0); }
    // The same prior over chainages negated (StructureCosts' mirrored chain;
    // curvature keeps its sign when the chainage runs the other way), built
    // with it: every local search mirrors the chain, and mirroring the prior
    // each time cost 3 % of a fit.
    const std::shared_ptr<const GuideCurvature>& mirrored() const { return mirrored_; }
    // Adds sum w (k(t) - g(t))^2 over the samples in [a, b) to the cost of
    // an element starting at chainage s (k = (x2 + x3 u) / S^2, u = (t - s) / S).
    void add(design::Quad& f, double s, double a, double b) const;
    // The prior over [a, b): its weight, the mean curvature it asks for
    // and the mean chainage it asks for it at (weight 0 where it has none).
    struct Mean {
        double weight = 0.0, curvature = 0.0, at = 0.0;
    };
    Mean over(double a, double b) const;
    // A guide's element joint where the chain runs beside it at a steady
    // offset (whether or not the prior holds there): the chainage across
    // from it, the guide's element kinds before and after it in this
    // chain's direction, and which run beside a guide it lies in.
    struct Joint {
        double t = 0.0;
        ElementKind before = ElementKind::line, after = ElementKind::line;
        std::size_t run = 0;
    };
    const std::vector<Joint>& joints() const { return joints_; }

private:
    GuideCurvature() = default;
    struct Sums {
        double w = 0, wt = 0, wtt = 0, wg = 0, wgt = 0, wgg = 0;
    };
    // The samples in [a, b): indices [first, last).
    std::pair<std::size_t, std::size_t> samples_in(double a, double b) const;
    // A sample at chainage t with its terms w, w g and w g^2.
    void append(double t, double w, double wg, double wgg);
    std::vector<double> t_;          // sample chainages, ascending
    std::vector<Sums> sums_{Sums{}}; // prefix sums: sums_[i] over samples [0, i)
    std::vector<Joint> joints_; // ascending
    std::shared_ptr<const GuideCurvature> mirrored_;
    GuideCurvature mirror() const;
};

// Each of the guide's curves in a run beside it (the whole run where it
// has none): the design's elements there replaced by the guide's structure
// (its kinds at its knots, the curvatures solved), kept where that costs
// less and moves no node far off (design_guided.cpp).
FrameDesign take_guided_runs(const std::vector<FrameNode>& nodes, FrameDesign design, const DesignDpOptions& o);

} // namespace railodd::geometry::fit
