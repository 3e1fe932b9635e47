// Lines joined by clothoid corners (corner_shape.hpp): a G2 centreline that
// stays close to every mapped vertex whatever the mapping looks like, and
// begins / ends exactly with given poses. See docs/geometry.md.
#include "railodd/geometry/corner_fit.hpp"

#include "corner_shape.hpp"

#include <algorithm>
#include <cmath>
#include <iterator>
#include <limits>
#include <numbers>
#include <optional>

namespace railodd::geometry {

namespace {

using corner::Corner;
using corner::CornerLimits;

// A deflection this close to a full reversal is a spike (the way doubling
// back on itself): a symmetric corner there would reach far beyond the tip.
constexpr double spike_deflection = 3.0;
// Points closer than this are one point to the polyline.
constexpr double same_point_m = 1e-6;
// A tied end leaves its pose along a spiral to zero curvature: at most this
// long, at most this much turn, and over at most a quarter of the way to the
// next node.
constexpr double max_transition_m = 30.0;
constexpr double max_transition_turn = 0.2;
// Rounds of taking dropped nodes back before the corners stand on every
// vertex (assemble_simplest).
constexpr int max_simplify_rounds = 16;

struct Vertex {
    Point p;
    bool mapped = true; // a mapped node: its corner is held within the deviation limit
    bool fixed = false; // an end or a tie's construction vertex: never dropped
};

double dist(const Point& a, const Point& b) { return std::hypot(b.x - a.x, b.y - a.y); }
double heading(const Point& a, const Point& b) { return std::atan2(b.y - a.y, b.x - a.x); }

// The turn at b going a -> b -> c, in (-pi, pi].
double deflection(const Point& a, const Point& b, const Point& c) {
    return std::remainder(heading(b, c) - heading(a, b), 2 * std::numbers::pi);
}

// A tied end: the pose, the spiral that brings its curvature to zero, and the
// pose (zero curvature) where the straight part of the path begins.
struct TiedEnd {
    Pose pose;
    Primitive transition;
    Pose straight; // start of the straight (start end) or its end (end end)
    bool has_transition = false;
};

double transition_length(double curvature, double room) {
    if (curvature == 0.0) {
        return 0.0;
    }
    return std::min({max_transition_m, 0.25 * room, 2.0 * max_transition_turn / std::abs(curvature)});
}

TiedEnd tie_start(const Pose& pose, double room) {
    TiedEnd t;
    t.pose = pose;
    t.straight = pose;
    const double l = transition_length(pose.curvature, room);
    if (l > 0.0) {
        t.transition = make_spiral(l, pose.curvature, 0.0);
        t.straight = evaluate(pose, t.transition, l);
        t.has_transition = true;
    }
    t.straight.curvature = 0.0;
    return t;
}

// The end transition is found by running the spiral backwards from the end
// pose; forwards it starts at `straight` with zero curvature and ends there.
TiedEnd tie_end(const Pose& pose, double room) {
    TiedEnd t;
    t.pose = pose;
    t.straight = pose;
    const double l = transition_length(pose.curvature, room);
    if (l > 0.0) {
        const Pose back{pose.x, pose.y, pose.hdg + std::numbers::pi, -pose.curvature};
        const Pose b = evaluate(back, make_spiral(l, -pose.curvature, 0.0), l);
        t.straight = {b.x, b.y, b.hdg - std::numbers::pi, 0.0};
        t.transition = make_spiral(l, 0.0, pose.curvature);
        t.has_transition = true;
    }
    t.straight.curvature = 0.0;
    return t;
}

std::vector<Vertex> without_repeats(const std::vector<Vertex>& in) {
    std::vector<Vertex> out;
    for (const Vertex& v : in) {
        while (!out.empty() && !out.back().fixed && dist(out.back().p, v.p) < same_point_m) {
            out.pop_back();
        }
        if (out.empty() || v.fixed || dist(out.back().p, v.p) >= same_point_m) {
            out.push_back(v);
        }
    }
    return out;
}

// A spike (the way running out to a node and straight back) has no symmetric
// corner: its tip becomes the midpoint of a short crossbar of two
// construction vertices, each turning about a right angle, so the curve makes
// a hairpin through the tip instead of dropping it.
std::vector<Vertex> with_hairpins(const std::vector<Vertex>& in, double half_width) {
    std::vector<Vertex> out;
    for (std::size_t i = 0; i < in.size(); ++i) {
        if (out.empty() || i + 1 == in.size() || in[i].fixed ||
            std::abs(deflection(out.back().p, in[i].p, in[i + 1].p)) <= spike_deflection) {
            out.push_back(in[i]);
            continue;
        }
        const Point& a = out.back().p;
        const Point& b = in[i].p;
        const Point& c = in[i + 1].p;
        const double turn = deflection(a, b, c);
        // Into the spike: the mean of the way in and the way back reversed.
        const double ux = (b.x - a.x) / dist(a, b) + (b.x - c.x) / dist(b, c);
        const double uy = (b.y - a.y) / dist(a, b) + (b.y - c.y) / dist(b, c);
        const double norm = std::hypot(ux, uy);
        const double side = turn > 0 ? 1.0 : -1.0; // the crossbar runs towards the turn
        const double r = std::min(half_width, 0.25 * std::min(dist(a, b), dist(b, c)));
        const double nx = -side * uy / norm;
        const double ny = side * ux / norm;
        out.push_back({{b.x - r * nx, b.y - r * ny}, false, true});
        out.push_back({{b.x + r * nx, b.y + r * ny}, false, true});
    }
    return out;
}

struct Path {
    std::vector<Vertex> vertices;
    std::vector<double> dirs; // heading of each segment
    std::optional<TiedEnd> start, end;
};

Point along(const Pose& p, double d) { return {p.x + d * std::cos(p.hdg), p.y + d * std::sin(p.hdg)}; }

// How many mapped nodes next to a tied end already lie on its straight
// (ahead of its start, or behind its end, within `tolerance` of the line).
std::size_t on_straight(const std::vector<Vertex>& inner, const Pose& straight, bool ahead, double tolerance) {
    const double c = std::cos(straight.hdg);
    const double s = std::sin(straight.hdg);
    std::size_t n = 0;
    for (; n < inner.size(); ++n) {
        const Point& q = inner[ahead ? n : inner.size() - 1 - n].p;
        const double dx = q.x - straight.x;
        const double dy = q.y - straight.y;
        const double forward = ahead ? dx * c + dy * s : -(dx * c + dy * s);
        if (forward <= 0.0 || std::abs(dy * c - dx * s) > tolerance) {
            break;
        }
    }
    return n;
}

// Each segment's heading; the straights of tied ends carry the given
// headings, not their rounding.
void set_directions(Path& path) {
    const std::vector<Vertex>& v = path.vertices;
    path.dirs.clear();
    for (std::size_t i = 0; i + 1 < v.size(); ++i) {
        path.dirs.push_back(heading(v[i].p, v[i + 1].p));
    }
    if (path.start && !path.dirs.empty()) {
        path.dirs.front() = path.start->straight.hdg;
    }
    if (path.end && !path.dirs.empty()) {
        path.dirs.back() = path.end->straight.hdg;
    }
}

// The polyline the corners are built on. A tied end's node is replaced by
// the straight's end point, and a construction vertex a third of the way to
// the next node puts the straight's heading into the polyline exactly.
// Nodes already on a tied straight (within clearance) are left to it and
// listed in `cleared`: tram switches are often drawn with a node within a
// metre of the switch, and a corner squeezed in before it would be far
// tighter than the track.
Path build_path(const std::vector<Point>& p, const std::optional<Pose>& start, const std::optional<Pose>& end,
                double clearance, double hairpin_half_width, std::vector<Point>& cleared) {
    Path path;
    if (start) {
        path.start = tie_start(*start, dist({start->x, start->y}, p[1]));
    }
    if (end) {
        path.end = tie_end(*end, dist(p[p.size() - 2], {end->x, end->y}));
    }
    const Point a = path.start ? Point{path.start->straight.x, path.start->straight.y} : p.front();
    const Point b = path.end ? Point{path.end->straight.x, path.end->straight.y} : p.back();
    std::vector<Vertex> inner;
    for (std::size_t i = 1; i + 1 < p.size(); ++i) {
        if (dist(p[i], a) >= same_point_m && dist(p[i], b) >= same_point_m) {
            inner.push_back({p[i], true, false});
        }
    }
    if (path.start) {
        const auto n = static_cast<long>(on_straight(inner, path.start->straight, true, clearance));
        std::transform(inner.begin(), inner.begin() + n, std::back_inserter(cleared), [](const Vertex& q) { return q.p; });
        inner.erase(inner.begin(), inner.begin() + n);
    }
    if (path.end) {
        const auto n = static_cast<long>(on_straight(inner, path.end->straight, false, clearance));
        std::transform(inner.end() - n, inner.end(), std::back_inserter(cleared), [](const Vertex& q) { return q.p; });
        inner.erase(inner.end() - n, inner.end());
    }
    std::vector<Vertex>& v = path.vertices;
    v.push_back({a, !start, true});
    if (path.start) {
        const Point next = inner.empty() ? b : inner.front().p;
        v.push_back({along(path.start->straight, dist(a, next) / 3.0), false, true});
    }
    v.insert(v.end(), inner.begin(), inner.end());
    if (path.end) {
        const Point prev = inner.empty() ? a : inner.back().p;
        v.push_back({along(path.end->straight, -dist(prev, b) / 3.0), false, true});
    }
    v.push_back({b, !end, true});
    v = with_hairpins(without_repeats(v), hairpin_half_width);
    set_directions(path);
    return path;
}

// Douglas-Peucker between fixed vertices: which vertices the polyline keeps
// when a mapped vertex within `tolerance` of the chord between its kept
// neighbours is dropped.
std::vector<char> douglas_peucker(const std::vector<Vertex>& v, double tolerance) {
    std::vector<char> keep(v.size(), 0);
    std::vector<std::pair<std::size_t, std::size_t>> spans;
    std::size_t from = 0;
    for (std::size_t i = 0; i < v.size(); ++i) {
        if (v[i].fixed || !v[i].mapped || i == 0 || i + 1 == v.size()) {
            keep[i] = 1;
            if (i > from + 1) {
                spans.push_back({from, i});
            }
            from = i;
        }
    }
    while (!spans.empty()) {
        const auto [a, b] = spans.back();
        spans.pop_back();
        const double len = dist(v[a].p, v[b].p);
        const double dx = v[b].p.x - v[a].p.x, dy = v[b].p.y - v[a].p.y;
        double worst = 0.0;
        std::size_t at = a;
        for (std::size_t i = a + 1; i < b; ++i) {
            const double qx = v[i].p.x - v[a].p.x, qy = v[i].p.y - v[a].p.y;
            const double d = len > same_point_m ? std::abs(dx * qy - dy * qx) / len : std::hypot(qx, qy);
            if (d > worst) {
                worst = d;
                at = i;
            }
        }
        if (worst > tolerance) {
            keep[at] = 1;
            spans.push_back({a, at});
            spans.push_back({at, b});
        }
    }
    return keep;
}

Path kept_part(const Path& full, const std::vector<char>& keep) {
    Path path{{}, {}, full.start, full.end};
    for (std::size_t i = 0; i < full.vertices.size(); ++i) {
        if (keep[i]) {
            path.vertices.push_back(full.vertices[i]);
        }
    }
    set_directions(path);
    return path;
}

// Corner sizes: first every corner within half of each adjacent segment (all
// of it where the neighbour is an end without a corner), then, in order,
// each takes the room its neighbours left.
std::vector<Corner> size_corners(const Path& path, const CornerFitOptions& o) {
    const std::vector<Vertex>& v = path.vertices;
    const std::size_t n = v.size();
    std::vector<double> seg(n - 1);
    for (std::size_t i = 0; i + 1 < n; ++i) {
        seg[i] = dist(v[i].p, v[i + 1].p);
    }
    std::vector<Corner> corners(n);
    auto build = [&](std::size_t i, double room) {
        const double turn = std::remainder(path.dirs[i] - path.dirs[i - 1], 2 * std::numbers::pi);
        // Only a construction vertex can still be this close to reversing.
        const double capped = std::copysign(std::min(std::abs(turn), std::numbers::pi - 1e-6), turn);
        const double deviation = v[i].mapped ? o.max_deviation_m : std::numeric_limits<double>::infinity();
        if (!(room > 0.0)) {
            return Corner{}; // both tied ends at one spot: nothing to round
        }
        return corner::make_corner(capped, {room, deviation, o.max_radius_m});
    };
    for (std::size_t i = 1; i + 1 < n; ++i) {
        const double left = i == 1 ? seg[0] : 0.5 * seg[i - 1];
        const double right = i + 2 == n ? seg[i] : 0.5 * seg[i];
        corners[i] = build(i, std::min(left, right));
    }
    for (std::size_t i = 1; i + 1 < n; ++i) {
        const double left = seg[i - 1] - corners[i - 1].tangent;
        const double right = seg[i] - corners[i + 1].tangent;
        corners[i] = build(i, std::min(left, right));
    }
    return corners;
}

// The alignment along the path: the tied start's transition, then straights
// and corners, then the tied end's transition.
Alignment assemble(const Path& path, const std::optional<Pose>& start, const CornerFitOptions& o) {
    Alignment a;
    const std::vector<Vertex>& v = path.vertices;
    a.start = start.value_or(Pose{v.front().p.x, v.front().p.y, path.dirs.front(), 0.0});
    if (path.start && path.start->has_transition) {
        a.primitives.push_back(path.start->transition);
    }
    const std::vector<Corner> corners = size_corners(path, o);
    for (std::size_t i = 0; i + 1 < v.size(); ++i) {
        const double line = dist(v[i].p, v[i + 1].p) - corners[i].tangent - corners[i + 1].tangent;
        if (line > 1e-12) {
            a.primitives.push_back(make_line(line));
        }
        const auto& c = corners[i + 1].primitives;
        a.primitives.insert(a.primitives.end(), c.begin(), c.end());
    }
    if (path.end && path.end->has_transition) {
        a.primitives.push_back(path.end->transition);
    }
    return a;
}

// The corners on as few of the path's vertices as keep every mapped one
// within the deviation bound: the vertices Douglas-Peucker keeps at half
// the bound, and each dropped one the corners then pass beyond it taken
// back, until none is. A corner at every node of a densely mapped stretch
// is a few decimetres long: Cologne's spliced ends were 24 % elements under
// a metre, its corner chains 12 %.
Alignment assemble_simplest(const Path& full, const std::optional<Pose>& start, const CornerFitOptions& o) {
    std::vector<char> keep = douglas_peucker(full.vertices, 0.5 * o.max_deviation_m);
    std::vector<Point> mapped;
    std::vector<std::size_t> at;
    for (std::size_t i = 0; i < full.vertices.size(); ++i) {
        if (full.vertices[i].mapped) {
            mapped.push_back(full.vertices[i].p);
            at.push_back(i);
        }
    }
    // Each round takes back every node beyond the bound; after a few (the
    // extracts need at most a handful), every vertex, as before.
    for (int round = 0; round < max_simplify_rounds; ++round) {
        Alignment a = assemble(kept_part(full, keep), start, o);
        const std::vector<double> d = distances(a, mapped);
        bool taken = false;
        for (std::size_t j = 0; j < d.size(); ++j) {
            if (d[j] > o.max_deviation_m && !keep[at[j]]) {
                keep[at[j]] = 1;
                taken = true;
            }
        }
        if (!taken) {
            return a;
        }
    }
    return assemble(full, start, o);
}

} // namespace

Alignment corner_polyline(const std::vector<Point>& points, const std::optional<Pose>& start,
                          const std::optional<Pose>& end, const CornerFitOptions& o) {
    std::vector<Point> p;
    for (const auto& q : points) {
        if (p.empty() || dist(p.back(), q) >= same_point_m) {
            p.push_back(q);
        }
    }
    Alignment a;
    if (p.size() < 2) {
        // Nothing to follow: a zero-length line keeps the track and its links.
        a.start = start.value_or(Pose{p.empty() ? 0.0 : p[0].x, p.empty() ? 0.0 : p[0].y, 0.0, 0.0});
        a.primitives.push_back(make_line(0.0));
        return a;
    }
    std::vector<Point> cleared;
    a = assemble_simplest(build_path(p, start, end, o.max_deviation_m, o.max_deviation_m, cleared), start, o);
    if (!cleared.empty()) {
        // The straight holds them unless a corner beyond bends it away early.
        const std::vector<double> d = distances(a, cleared);
        if (*std::max_element(d.begin(), d.end()) > o.max_deviation_m) {
            cleared.clear();
            a = assemble_simplest(build_path(p, start, end, -1.0, o.max_deviation_m, cleared), start, o);
        }
    }
    if (a.primitives.empty()) {
        a.primitives.push_back(make_line(0.0));
    }
    return a;
}

} // namespace railodd::geometry
