#include "land_use.hpp"

#include <algorithm>
#include <cmath>
#include <map>
#include <optional>
#include <tuple>

namespace railodd::ingest {

namespace {

constexpr double simplify_m = 1.0; // outline detail kept: far below the 25 m track sampling of the tagger

using Ring = std::vector<std::int64_t>; // node ids, closed (front == back)

// Joins ways into closed rings by shared end nodes, lowest member first so the
// result depends only on the input; nothing if some way cannot be closed.
std::optional<std::vector<Ring>> join_rings(std::vector<Ring> parts) {
    std::vector<Ring> rings;
    std::vector<bool> used(parts.size(), false);
    for (std::size_t i = 0; i < parts.size(); ++i) {
        if (used[i] || parts[i].size() < 2) {
            continue;
        }
        used[i] = true;
        Ring ring = parts[i];
        while (ring.front() != ring.back()) {
            bool extended = false;
            for (std::size_t j = 0; j < parts.size() && !extended; ++j) {
                if (used[j] || parts[j].size() < 2) {
                    continue;
                }
                Ring& p = parts[j];
                if (p.back() == ring.back()) {
                    std::reverse(p.begin(), p.end());
                }
                if (p.front() == ring.back()) {
                    ring.insert(ring.end(), p.begin() + 1, p.end());
                    used[j] = extended = true;
                }
            }
            if (!extended) {
                return std::nullopt;
            }
        }
        if (ring.size() >= 4) {
            rings.push_back(std::move(ring));
        }
    }
    return rings;
}

double distance_to_segment(XY p, XY a, XY b) {
    const double dx = b.x - a.x, dy = b.y - a.y, len2 = dx * dx + dy * dy;
    const double t = len2 > 0 ? std::clamp(((p.x - a.x) * dx + (p.y - a.y) * dy) / len2, 0.0, 1.0) : 0.0;
    return std::hypot(p.x - a.x - t * dx, p.y - a.y - t * dy);
}

// Douglas-Peucker on a closed ring (front == back), returned open.
std::vector<XY> simplify(const std::vector<XY>& pts) {
    std::vector<bool> keep(pts.size(), false);
    keep.front() = keep.back() = true;
    // The first point of a closed ring is its own chord: split at the farthest point first.
    std::size_t far = 0;
    double best = -1.0;
    for (std::size_t i = 1; i + 1 < pts.size(); ++i) {
        const double d = std::hypot(pts[i].x - pts[0].x, pts[i].y - pts[0].y);
        if (d > best) {
            best = d;
            far = i;
        }
    }
    keep[far] = true;
    std::vector<std::pair<std::size_t, std::size_t>> todo{{0, far}, {far, pts.size() - 1}};
    while (!todo.empty()) {
        const auto [a, b] = todo.back();
        todo.pop_back();
        std::size_t worst = a;
        double dmax = simplify_m;
        for (std::size_t i = a + 1; i < b; ++i) {
            const double d = distance_to_segment(pts[i], pts[a], pts[b]);
            if (d > dmax) {
                dmax = d;
                worst = i;
            }
        }
        if (worst != a) {
            keep[worst] = true;
            todo.push_back({a, worst});
            todo.push_back({worst, b});
        }
    }
    std::vector<XY> out;
    for (std::size_t i = 0; i + 1 < pts.size(); ++i) {
        if (keep[i]) {
            out.push_back(pts[i]);
        }
    }
    return out;
}

double ring_area(const std::vector<XY>& r) {
    double a = 0.0;
    for (std::size_t i = 0, j = r.size() - 1; i < r.size(); j = i++) {
        a += (r[j].x + r[i].x) * (r[j].y - r[i].y);
    }
    return std::abs(a) / 2.0;
}

struct Candidate {
    std::string osm_type;
    std::int64_t id = 0;
    std::string kind, tag;
    std::vector<Ring> outer, inner; // member ways, or the closed way as one outer ring
};

enum class Built { kept, far, dropped };

// Whether the located nodes' bounds overlap the tracks' bounds (an area
// around the whole route has no node inside them), and whether all are located.
std::pair<bool, bool> near_and_located(const Candidate& c, const Locator& locate, const BBox& tracks) {
    BBox b{180, 90, -180, -90};
    bool located = true;
    for (const auto* parts : {&c.outer, &c.inner}) {
        for (const Ring& part : *parts) {
            for (const std::int64_t ref : part) {
                const auto* e = locate(ref);
                if (!e) {
                    located = false;
                    continue;
                }
                b = {std::min(b.west, e->lonlat.lon), std::min(b.south, e->lonlat.lat),
                     std::max(b.east, e->lonlat.lon), std::max(b.north, e->lonlat.lat)};
            }
        }
    }
    const bool near = b.west <= tracks.east && b.east >= tracks.west && b.south <= tracks.north &&
                      b.north >= tracks.south;
    return {near, located};
}

// Bounds-checks, assembles, projects and simplifies one candidate.
Built build_area(const Candidate& c, const Locator& locate, const LandUseContext& ctx, IngestResult& result,
                 std::string& reason) {
    const auto [near, located] = near_and_located(c, locate, ctx.near);
    if (!near) {
        return Built::far;
    }
    const auto outer = join_rings(c.outer);
    const auto inner = join_rings(c.inner);
    if (!outer || !inner) {
        reason = "ring not closed (members missing from the extract or mapped open)";
        return Built::dropped;
    }
    if (!located) {
        reason = "nodes missing from the extract";
        return Built::dropped;
    }
    LandUseArea area{c.osm_type, c.id, c.kind, c.tag, {}, 0.0};
    for (const auto* rings : {&*outer, &*inner}) {
        for (const Ring& ring : *rings) {
            std::vector<XY> pts;
            for (const std::int64_t ref : ring) {
                pts.push_back(result.projection.forward(locate(ref)->lonlat));
            }
            area.rings.push_back(simplify(pts));
            area.area_m2 += (rings == &*outer ? 1.0 : -1.0) * ring_area(area.rings.back());
        }
    }
    std::erase_if(area.rings, [](const std::vector<XY>& r) { return r.size() < 3; });
    if (area.rings.empty()) {
        reason = "degenerate outline";
        return Built::dropped;
    }
    area.area_m2 = std::max(area.area_m2, 0.0);
    result.land_use.push_back(std::move(area));
    return Built::kept;
}

} // namespace

void build_land_use(std::vector<RawLandUseWay> ways, const std::vector<RawLandUseRelation>& relations,
                    const Locator& locate, const LandUseContext& ctx, IngestResult& result) {
    std::vector<Candidate> candidates;
    std::map<std::int64_t, const Ring*> member_refs;
    for (const auto& w : ways) {
        member_refs.emplace(w.way.id, &w.way.refs);
        if (!w.kind.empty()) {
            candidates.push_back({"way", w.way.id, w.kind, w.tag, {w.way.refs}, {}});
        }
    }
    for (const auto& r : relations) {
        Candidate c{"relation", r.id, r.kind, r.tag, {}, {}};
        for (const auto& [way, inner] : r.ways) {
            const auto it = member_refs.find(way);
            if (it != member_refs.end()) {
                (inner ? c.inner : c.outer).push_back(*it->second);
            }
        }
        if (!c.outer.empty()) {
            candidates.push_back(std::move(c));
        }
    }
    for (const auto& c : candidates) {
        std::string reason;
        const Built b = build_area(c, locate, ctx, result, reason);
        result.counts.input_land_use += b == Built::far ? 0 : 1;
        if (b == Built::dropped) {
            result.dropped.push_back({"land_use", c.osm_type, c.id, reason});
        }
    }
    std::stable_sort(result.land_use.begin(), result.land_use.end(), [](const LandUseArea& a, const LandUseArea& b) {
        return std::tie(a.osm_type, a.id) < std::tie(b.osm_type, b.id);
    });
    result.counts.output_land_use = result.land_use.size();
}

void read_land_use_near(const LandUseContext& ctx, const RelationScan& relations, IngestResult& result) {
    NodeLocations near = collect_nodes(ctx.file, [&](LonLat ll) { return ctx.search.contains(ll); });
    std::vector<RawLandUseWay> ways = scan_land_use_ways(ctx.file, relations.land_use_members, near);
    NodeLocations outer;
    for (const auto& w : ways) {
        for (const std::int64_t ref : w.way.refs) {
            if (!near.located(ref)) {
                outer.want(ref);
            }
        }
    }
    outer.seal();
    if (outer.size() > 0) {
        locate_nodes(ctx.file, outer, "reading land-use nodes");
    }
    build_land_use(std::move(ways), relations.land_use, [&](std::int64_t id) {
        const auto* e = near.located(id);
        return e ? e : outer.located(id);
    }, ctx, result);
}

} // namespace railodd::ingest
