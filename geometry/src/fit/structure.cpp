#include "structure.hpp"

#include <algorithm>
#include <cmath>

namespace railodd::geometry::fit {

namespace {

bool constant(const Piece& p) { return p.kind != PieceKind::ramp; }

// Neighbouring constant pieces of (nearly) one curvature are one piece.
std::vector<Piece> merge_equal(std::vector<Piece> in) {
    std::vector<Piece> out;
    for (const Piece& p : in) {
        if (!out.empty() && constant(out.back()) && constant(p) && out.back().kind == p.kind &&
            std::abs(out.back().curv_start - p.curv_start) < 1e-6) {
            const double l = out.back().length + p.length;
            const double c = (out.back().curv_start * out.back().length + p.curv_start * p.length) / l;
            out.back() = {p.kind, l, c, c};
        } else {
            out.push_back(p);
        }
    }
    return out;
}

// A transition cut out of the constant pieces on either side of a jump. The
// jump sits where the curvature diagram crosses half way, i.e. mid
// transition, so the transition is centred on it; its length is a guess the
// least-squares fit corrects (railway transitions run 30-200 m).
Piece take_transition(Piece& before, Piece& after) {
    const double half = 40.0;
    const double from_before = std::min(half, 0.3 * before.length);
    const double from_after = std::min(half, 0.3 * after.length);
    before.length -= from_before;
    after.length -= from_after;
    return {PieceKind::ramp, from_before + from_after, before.curv_end, after.curv_start};
}

std::vector<Piece> insert_transitions(std::vector<Piece> in, const StructureEnds& ends) {
    std::vector<Piece> out;
    for (Piece p : in) {
        if (!out.empty() && constant(out.back()) && constant(p)) {
            const Piece t = take_transition(out.back(), p);
            out.push_back(t);
        }
        out.push_back(p);
    }
    if (ends.start_fixed && constant(out.front()) && std::abs(out.front().curv_start - ends.start.curvature) > 1e-9) {
        const double l = std::min(10.0, 0.25 * out.front().length);
        out.front().length -= l;
        out.insert(out.begin(), Piece{PieceKind::ramp, l, ends.start.curvature, out.front().curv_start});
    }
    if (ends.end_curvature && constant(out.back()) && std::abs(out.back().curv_end - *ends.end_curvature) > 1e-9) {
        const double l = std::min(10.0, 0.25 * out.back().length);
        out.back().length -= l;
        out.push_back(Piece{PieceKind::ramp, l, out.back().curv_end, *ends.end_curvature});
    }
    return out;
}

} // namespace

CurvatureModel build_structure(std::vector<Piece> pieces, const StructureEnds& ends) {
    pieces = insert_transitions(merge_equal(std::move(pieces)), ends);
    CurvatureModel m;
    m.start = ends.start;
    m.start_free = !ends.start_fixed;
    auto new_var = [&](double value) {
        m.curv.push_back(value);
        return static_cast<int>(m.curv.size() - 1);
    };
    // Knot 0.
    const Piece& first = pieces.front();
    if (ends.start_fixed) {
        m.knot_var.push_back(-1);
        m.knot_fixed.push_back(ends.start.curvature);
    } else if (first.kind == PieceKind::line) {
        m.knot_var.push_back(-1);
        m.knot_fixed.push_back(0.0);
    } else {
        m.knot_var.push_back(new_var(first.curv_start));
        m.knot_fixed.push_back(0.0);
    }
    for (std::size_t i = 0; i < pieces.size(); ++i) {
        const Piece& p = pieces[i];
        const bool last = i + 1 == pieces.size();
        const Piece* next = last ? nullptr : &pieces[i + 1];
        const double length = std::max(p.length, 0.5);
        if (last && ends.end_curvature) {
            m.push_segment(length, true, -1, *ends.end_curvature);
        } else if (p.kind == PieceKind::line || (next && next->kind == PieceKind::line)) {
            m.push_segment(length, true, -1, 0.0);
        } else if (p.kind == PieceKind::arc) {
            // Transitions were inserted before every arc, so its start knot already
            // holds its variable (or a fixed start curvature equal to it).
            m.push_segment(length, true, m.knot_var.back(), m.knot_fixed.back());
        } else if (next && next->kind == PieceKind::arc) {
            m.push_segment(length, true, new_var(next->curv_start));
        } else {
            m.push_segment(length, true, new_var(p.curv_end));
        }
    }
    return m;
}

} // namespace railodd::geometry::fit
