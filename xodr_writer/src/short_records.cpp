// planView records under 1 cm merged into their neighbours. Readers divide by
// a record's length (a spiral's curvature rate), and cuts that fall a
// rounding error from a primitive's end, or the corner construction at a node
// with a tiny deflection, left records of 1e-14 m to a few mm in the map (175
// on Cologne). Each record keeps its own start pose, so a merge moves nothing
// but the joints beside the run, by far less than the continuity limits
// (docs/xodr.md, "Short records").
#include "plan_view.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace railodd::xodr {

namespace {

using Kind = PlanGeometry::Kind;
using Records = std::vector<PlanGeometry>;

// What a merge may leave at a joint beside it: half the checker's heading
// limit (1e-4 rad) and gap limit (1 mm); curvature continuous to 1e-9.
constexpr double max_heading_change = 5e-5;
constexpr double max_shift_m = 5e-4;

bool constant(const PlanGeometry& g) { return g.kind == Kind::line || g.kind == Kind::arc; }

bool same_curvature(double a, double b) { return std::abs(a - b) <= 1e-9 * std::max(1.0, std::abs(a) + std::abs(b)); }

geometry::Primitive primitive_of(const PlanGeometry& g) {
    switch (g.kind) {
    case Kind::line: return geometry::make_line(g.length);
    case Kind::arc: return geometry::make_arc(g.length, g.curv_start);
    default: return geometry::make_spiral(g.length, g.curv_start, g.curv_end);
    }
}

geometry::Pose start_of(const PlanGeometry& g) { return {g.x, g.y, g.hdg, g.curv_start}; }

geometry::Pose at(const PlanGeometry& g, double ds) { return geometry::evaluate(start_of(g), primitive_of(g), ds); }

void place(PlanGeometry& g, const geometry::Pose& p) {
    g.x = p.x;
    g.y = p.y;
    g.hdg = p.hdg;
}

// The record's kind from its curvatures (a spiral that a cut left constant
// stays a spiral: it is one, of rate 0).
void set_curvatures(PlanGeometry& g, double k0, double k1) {
    g.curv_start = k0;
    g.curv_end = k1;
    if (!same_curvature(k0, k1) && constant(g)) {
        g.kind = Kind::spiral;
    }
}

double heading_change(const Records& recs, std::size_t first, std::size_t last) {
    double d = 0.0;
    for (std::size_t i = first; i < last; ++i) {
        d += 0.5 * (recs[i].curv_start + recs[i].curv_end) * recs[i].length;
    }
    return d;
}

double run_length(const Records& recs, std::size_t first, std::size_t last) {
    double d = 0.0;
    for (std::size_t i = first; i < last; ++i) {
        d += recs[i].length;
    }
    return d;
}

// Whether g may grow by d (d < 0: shrink) with its end curvatures kept: a
// line or arc runs on along its own circle; a spiral's rate changes, which
// turns its far end by about |dk| d / 2 and moves it by |dk| d L / 3.
bool can_stretch(const PlanGeometry& g, double d) {
    if (constant(g)) {
        return true;
    }
    const double dk = std::abs(g.curv_end - g.curv_start);
    return g.kind == Kind::spiral && dk * std::abs(d) / 2 <= max_heading_change &&
           dk * std::abs(d) * g.length / 3 <= max_shift_m;
}

// [first, last) is a run of short records whose curvature nets out (the
// curvature before it equals the one after it) and turns little: it goes and
// a neighbour takes its length (a line or arc along its own circle, else a
// spiral within can_stretch). False when no neighbour can.
bool absorb(Records& recs, std::size_t first, std::size_t last, bool rail, bool& next_moved) {
    const double run = run_length(recs, first, last);
    const double turn = heading_change(recs, first, last);
    const std::size_t prev = first > 0 ? first - 1 : recs.size();
    const auto fits = [&](std::size_t i, bool line_or_arc) {
        if (i >= recs.size() || constant(recs[i]) != line_or_arc || !can_stretch(recs[i], run)) {
            return false;
        }
        const double k = i == prev ? recs[i].curv_end : recs[i].curv_start;
        return std::abs(turn - k * run) <= max_heading_change;
    };
    if (fits(prev, true) || (!fits(last, true) && fits(prev, false))) {
        recs[prev].length += run;
    } else if (fits(last, true)) {
        // Continued back along its own circle.
        PlanGeometry& g = recs[last];
        geometry::Pose back{g.x, g.y, g.hdg + std::numbers::pi, -g.curv_start};
        back = geometry::evaluate(back, g.kind == Kind::line ? geometry::make_line(run) : geometry::make_arc(run, -g.curv_start), run);
        back.hdg -= std::numbers::pi;
        place(g, back);
        g.s -= run;
        g.length += run;
    } else if (fits(last, false)) {
        next_moved = true; // its far end moves too
        place(recs[last], start_of(recs[first]));
        recs[last].s -= run;
        recs[last].length += run;
    } else if (!rail && first > 0 && recs[prev].kind == Kind::spiral) {
        // A road need not keep its curvature continuous: the spiral runs on
        // at its own rate, its shape exact.
        PlanGeometry& p = recs[prev];
        const double rate = p.length > 0 ? (p.curv_end - p.curv_start) / p.length : 0.0;
        p.curv_end += rate * run;
        p.length += run;
    } else {
        return false;
    }
    recs.erase(recs.begin() + static_cast<long>(first), recs.begin() + static_cast<long>(last));
    return true;
}

// The run lengthened by `need` in all: from `first` on, records chained from
// `from` at s; then `next` started where the run ends, cut exactly from its own
// shape (its remaining part is what it was), and the run's last curvature
// made its new start curvature.
void rechain(Records& recs, std::size_t first, std::size_t last, geometry::Pose from, double s) {
    for (std::size_t i = first; i < last; ++i) {
        recs[i].s = s;
        place(recs[i], from);
        from = at(recs[i], recs[i].length);
        s += recs[i].length;
    }
}

// A run at the end of which the curvature differs (a short transition): each
// record lengthened to min_length, the length cut from the longer neighbour
// exactly along its own shape, curvature matched at the cut. The road's
// length stays what it was; the one joint that moves is the run's far one.
bool widen(Records& recs, std::size_t first, std::size_t last, double min_length) {
    double need = 0.0;
    for (std::size_t i = first; i < last; ++i) {
        need += std::max(min_length, recs[i].length) - recs[i].length;
    }
    const std::size_t prev = first > 0 ? first - 1 : recs.size();
    const auto can_lend = [&](std::size_t i) {
        return i < recs.size() && recs[i].kind != Kind::param_poly3 && recs[i].length >= min_length + need;
    };
    const bool from_prev = can_lend(prev) && (!can_lend(last) || recs[prev].length >= recs[last].length);
    if (!from_prev && !can_lend(last)) {
        return false;
    }
    for (std::size_t i = first; i < last; ++i) {
        recs[i].length = std::max(min_length, recs[i].length);
    }
    if (from_prev) {
        PlanGeometry& p = recs[prev];
        const geometry::Pose cut = at(p, p.length - need);
        set_curvatures(p, p.curv_start, cut.curvature);
        p.length -= need;
        set_curvatures(recs[first], cut.curvature, recs[first].curv_end);
        rechain(recs, first, last, cut, p.s + p.length);
    } else {
        PlanGeometry& n = recs[last];
        const geometry::Pose cut = at(n, need);
        rechain(recs, first, last, start_of(recs[first]), recs[first].s);
        set_curvatures(recs[last - 1], recs[last - 1].curv_start, cut.curvature);
        place(n, cut);
        set_curvatures(n, cut.curvature, n.curv_end);
        n.s += need;
        n.length -= need;
    }
    return true;
}

// A short corner between two straights that turns too much to be dropped (a
// road's corner at a node): scaled by f (lengths times f, curvatures over f,
// so it turns by what it did and keeps its shape), the straights shortened
// by a and b so that the corner's ends stay on them: a u0 + b u1 = (f - 1) C,
// C the corner's chord. Both joints then hold exactly; the road is shorter by
// (f - 1)(run - |C|) / cos, under 0.1 mm for a 10 degree corner.
bool scale_corner(Records& recs, std::size_t first, std::size_t last, double min_length) {
    if (first == 0 || last >= recs.size() || recs[first - 1].kind != Kind::line || recs[last].kind != Kind::line) {
        return false;
    }
    double shortest = min_length;
    for (std::size_t i = first; i < last; ++i) {
        shortest = std::min(shortest, recs[i].length);
    }
    if (shortest <= 1e-9) {
        return false;
    }
    const double f = min_length / shortest;
    const geometry::Pose end = at(recs[last - 1], recs[last - 1].length);
    const double cx = end.x - recs[first].x, cy = end.y - recs[first].y;
    const double u0x = std::cos(recs[first - 1].hdg), u0y = std::sin(recs[first - 1].hdg);
    const double u1x = std::cos(recs[last].hdg), u1y = std::sin(recs[last].hdg);
    const double det = u0x * u1y - u0y * u1x;
    if (std::abs(det) < 1e-6) {
        return false; // no turn: nothing to keep
    }
    const double rx = (f - 1) * cx, ry = (f - 1) * cy;
    const double a = (rx * u1y - ry * u1x) / det, b = (u0x * ry - u0y * rx) / det;
    if (a < 0 || b < 0 || recs[first - 1].length < a + min_length || recs[last].length < b + min_length) {
        return false;
    }
    recs[first - 1].length -= a;
    for (std::size_t i = first; i < last; ++i) {
        recs[i].length *= f;
        set_curvatures(recs[i], recs[i].curv_start / f, recs[i].curv_end / f);
    }
    const PlanGeometry& p = recs[first - 1];
    rechain(recs, first, last, at(p, p.length), p.s + p.length);
    PlanGeometry& n = recs[last];
    place(n, at(n, b));
    n.length -= b;
    for (std::size_t i = last; i < recs.size(); ++i) {
        recs[i].s = recs[i - 1].s + recs[i - 1].length;
    }
    return true;
}

// Whether the joints i -> i + 1 for i in [lo, hi) hold within the limits
// above (curvature only on rail roads): every merge is checked so at the
// joints it moves, and undone if they do not.
bool joints_hold(const Records& recs, std::size_t lo, std::size_t hi, bool rail) {
    for (std::size_t i = lo; i < hi && i + 1 < recs.size(); ++i) {
        const geometry::Pose e = at(recs[i], recs[i].length);
        const PlanGeometry& n = recs[i + 1];
        const double dh = std::remainder(e.hdg - n.hdg, 2 * std::numbers::pi);
        if (std::hypot(e.x - n.x, e.y - n.y) > max_shift_m || std::abs(dh) > max_heading_change ||
            (rail && std::abs(recs[i].curv_end - n.curv_start) > 1e-9)) {
            return false;
        }
    }
    return true;
}

// One merge of the run [first, last): false (and nothing changed) when none
// holds.
bool merge_run(Records& recs, std::size_t first, std::size_t last, double min_length, bool rail) {
    const Records saved = recs;
    const double before = first > 0 ? recs[first - 1].curv_end : recs[first].curv_start;
    const double after = last < recs.size() ? recs[last].curv_start : recs[last - 1].curv_end;
    const std::size_t lo = first > 0 ? first - 1 : 0;
    if (same_curvature(before, after)) {
        bool next_moved = false;
        if (absorb(recs, first, last, rail, next_moved) && joints_hold(recs, lo, first + (next_moved ? 1 : 0), rail)) {
            return true;
        }
        recs = saved;
        if (before == 0.0 && scale_corner(recs, first, last, min_length) && joints_hold(recs, lo, last + 1, rail)) {
            return true;
        }
        recs = saved;
    }
    if (widen(recs, first, last, min_length) && joints_hold(recs, last - 1, last, rail)) {
        return true;
    }
    recs = saved;
    return false;
}

} // namespace

void merge_short_records(Records& recs, double min_length, bool rail) {
    const auto is_short = [&](const PlanGeometry& g) { return g.length < min_length && g.kind != Kind::param_poly3; };
    std::size_t i = 0;
    while (i < recs.size() && recs.size() > 1) {
        if (!is_short(recs[i])) {
            ++i;
            continue;
        }
        std::size_t last = i;
        while (last < recs.size() && is_short(recs[last])) {
            ++last;
        }
        if (i == 0 && last == recs.size()) {
            break; // the whole road is that short
        }
        const std::size_t n = recs.size();
        if (merge_run(recs, i, last, min_length, rail) && recs.size() < n) {
            continue; // the run is gone: what followed it is at i now
        }
        i = last;
    }
}

} // namespace railodd::xodr
