#include "parallel_guide.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace railodd::geometry::fit {

namespace {

constexpr double min_offset_m = 2.5, max_offset_m = 6.5; // double track: 3.5-6 m between centres

// The guide's primitive turned to run the other way.
Primitive reversed(const Primitive& q) {
    return {q.kind, q.length, -q.curv_end, -q.curv_start};
}

// The piece a primitive becomes offset d to its left (concentric: radius
// shorter by d on the inside of a left curve).
Piece offset_piece(const Primitive& q, double d) {
    auto concentric = [d](double k) { return k / (1.0 - d * k); };
    const double mid = 0.5 * (q.curv_start + q.curv_end);
    const double length = q.length * (1.0 - d * mid);
    switch (q.kind) {
    case PrimitiveKind::line: return {PieceKind::line, q.length, 0.0, 0.0};
    case PrimitiveKind::arc: return {PieceKind::arc, length, concentric(mid), concentric(mid)};
    case PrimitiveKind::spiral: break;
    }
    return {PieceKind::ramp, length, concentric(q.curv_start), concentric(q.curv_end)};
}

struct Beside {
    double s_first = 0.0, s_last = 0.0; // on the guide, of the window's first and last node
    double offset = 0.0;                // median signed offset (left of the guide positive)
};

// Where the window's nodes lie on the guide, if they run beside it.
std::optional<Beside> beside(const std::vector<Point2>& p, const IndexedAlignment& guide) {
    std::vector<double> offsets;
    std::vector<double> s;
    for (const Point2& q : p) {
        const Projection pr = guide.project(q.x, q.y);
        s.push_back(pr.s);
        const bool inside = pr.s > 1e-6 && pr.s < guide.length() - 1e-6;
        if (inside && std::abs(pr.offset) >= min_offset_m && std::abs(pr.offset) <= max_offset_m) {
            offsets.push_back(pr.offset);
        }
    }
    if (offsets.size() < 5 || static_cast<double>(offsets.size()) < 0.8 * static_cast<double>(p.size())) {
        return std::nullopt;
    }
    const auto left = std::count_if(offsets.begin(), offsets.end(), [](double o) { return o > 0; });
    const auto n = static_cast<std::ptrdiff_t>(offsets.size());
    if (left != n && left != 0) {
        return std::nullopt; // crosses over: not one neighbour
    }
    std::nth_element(offsets.begin(), offsets.begin() + n / 2, offsets.end());
    Beside b{s.front(), s.back(), offsets[static_cast<std::size_t>(n / 2)]};
    // The nodes must run along the guide one way, as far as they run themselves.
    double run = 0.0;
    for (std::size_t i = 1; i < p.size(); ++i) {
        run += std::hypot(p[i].x - p[i - 1].x, p[i].y - p[i - 1].y);
    }
    if (std::abs(b.s_last - b.s_first) < 0.9 * run) {
        return std::nullopt;
    }
    return b;
}

} // namespace

std::optional<GuidedStructure> guided_structure(const std::vector<Point2>& p, const IndexedAlignment& guide) {
    const std::optional<Beside> b = beside(p, guide);
    if (!b) {
        return std::nullopt;
    }
    const bool forward = b->s_last > b->s_first;
    const double lo = std::min(b->s_first, b->s_last), hi = std::max(b->s_first, b->s_last);
    const std::vector<Alignment> parts = split_alignment(guide.alignment(), {lo, hi});
    std::vector<Primitive> stretch = parts[1].primitives;
    std::erase_if(stretch, [](const Primitive& q) { return q.length < 1e-3; });
    if (stretch.empty()) {
        return std::nullopt;
    }
    // Offset to the window's left, in its own direction.
    const double d = forward ? b->offset : -b->offset;
    GuidedStructure g;
    Pose at = guide.evaluate(forward ? lo : hi);
    if (!forward) {
        std::reverse(stretch.begin(), stretch.end());
        for (Primitive& q : stretch) {
            q = reversed(q);
        }
        at.hdg += std::numbers::pi;
        at.curvature = -at.curvature;
    }
    for (const Primitive& q : stretch) {
        g.pieces.push_back(offset_piece(q, d));
    }
    g.start = {at.x - d * std::sin(at.hdg), at.y + d * std::cos(at.hdg), at.hdg, g.pieces.front().curv_start};
    return g;
}

} // namespace railodd::geometry::fit
