#pragma once
// Splits a curvature diagram (curvature over chainage, as the fine clothoid
// spline estimated it) into the pieces a railway is built from: lines
// (curvature zero), arcs (constant) and transitions (linear), by dynamic
// programming with a penalty per parameter.
#include <cstddef>
#include <memory>
#include <vector>

namespace railodd::geometry::fit {

enum class PieceKind { line, arc, ramp };

struct Piece {
    PieceKind kind = PieceKind::line;
    double length = 0.0;
    double curv_start = 0.0; // ramps: value at the start; lines: 0; arcs: the value
    double curv_end = 0.0;
};

struct SegmentationOptions {
    double curvature_sigma = 2e-5; // 1/m: scale of the curvature estimate's noise
    double penalty = 8.0;          // per parameter, in units of squared scaled residual
};

// s: knot chainages (ascending), k: curvature at each knot.
std::vector<Piece> segment_curvature(const std::vector<double>& s, const std::vector<double>& k,
                                     const SegmentationOptions& options);

// One window's curvature diagram, segmented at several noise scales and
// penalties: the fits of every knot range are made once (O(n^2)), each
// segmentation is then a dynamic programme over them. `s` must outlive it.
class CurvatureDiagram {
public:
    CurvatureDiagram(const std::vector<double>& s, const std::vector<double>& k);
    ~CurvatureDiagram();
    std::vector<Piece> segment(const SegmentationOptions& options) const;

private:
    struct Tables;
    const std::vector<double>& s_;
    std::unique_ptr<Tables> tables_;
};

// The textbook template: straight where the smoothed curvature is negligible,
// and each curved stretch one arc between two transitions. Catches simple
// curves whose noisy curvature diagram the dynamic programme over-splits.
std::vector<Piece> template_structure(const std::vector<double>& s, const std::vector<double>& k);

} // namespace railodd::geometry::fit
