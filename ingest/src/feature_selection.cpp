#include "feature_selection.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>

namespace railodd::ingest {

namespace {

double reach_for(const std::string& kind, const IngestOptions& options) {
    return (kind == "station" || kind == "halt") ? options.station_distance_m : options.feature_distance_m;
}

NodeRef node_ref(std::int64_t id, LonLat ll, const LocalProjection& proj) {
    NodeRef n;
    n.id = id;
    n.lonlat = ll;
    n.xy = proj.forward(ll);
    return n;
}

// Area centroid (shoelace) for closed outlines, mean of vertices otherwise or
// when the area is degenerate.
XY centroid(const std::vector<NodeRef>& outline, bool area) {
    double cx = 0, cy = 0, a2 = 0;
    if (area) {
        for (std::size_t i = 0, j = outline.size() - 1; i < outline.size(); j = i++) {
            const XY p = outline[j].xy, q = outline[i].xy;
            const double cross = p.x * q.y - q.x * p.y;
            a2 += cross;
            cx += (p.x + q.x) * cross;
            cy += (p.y + q.y) * cross;
        }
    }
    if (std::abs(a2) > 1e-9) {
        return {cx / (3 * a2), cy / (3 * a2)};
    }
    XY m{0, 0};
    for (const auto& n : outline) {
        m.x += n.xy.x / static_cast<double>(outline.size());
        m.y += n.xy.y / static_cast<double>(outline.size());
    }
    return m;
}

std::string too_far(double limit) {
    std::ostringstream s;
    s << "farther than " << limit << " m from every selected track";
    return s.str();
}

// Decides and records one feature: `in_selection` says whether it lies in the
// selection, `near` whether it is close enough to a track to be kept.
void place(Feature f, bool in_selection, bool near, bool text_repaired, const FeatureContext& ctx,
           IngestResult& result) {
    const double limit = reach_for(f.kind, ctx.options);
    // Features near a selected track are kept even just outside a bbox: the
    // selected ways are complete, and so is what stands on them.
    const bool counted = near || (ctx.selection.spatial() ? in_selection : !ctx.selection.relation);
    if (!counted) {
        return;
    }
    ++result.counts.input_features;
    if (text_repaired) {
        result.repairs.push_back({"feature", f.osm_type, f.id, text_repair_action});
    }
    if (near) {
        result.features.push_back(std::move(f));
    } else {
        result.dropped.push_back({"feature", f.osm_type, f.id, f.kind + " " + too_far(limit)});
    }
}

void place_point(RawFeature& raw, const FeatureContext& ctx, IngestResult& result) {
    Feature f;
    f.osm_type = raw.osm_type;
    f.id = raw.id;
    f.kind = std::move(raw.kind);
    f.tags = std::move(raw.tags);
    f.position = node_ref(raw.id, raw.lonlat, ctx.projection);
    f.on_track = std::binary_search(ctx.track_nodes.begin(), ctx.track_nodes.end(), raw.id);
    const bool near = f.on_track || ctx.grid.within(f.position.xy, reach_for(f.kind, ctx.options));
    place(std::move(f), ctx.selection.contains(raw.lonlat), near, raw.text_repaired, ctx, result);
}

void place_area(RawFeature& raw, const NodeLocations& locs, const FeatureContext& ctx, IngestResult& result) {
    Feature f;
    f.osm_type = raw.osm_type;
    f.id = raw.id;
    f.kind = std::move(raw.kind);
    f.tags = std::move(raw.tags);
    f.area = is_closed(raw.refs);
    bool in_selection = false;
    for (std::int64_t ref : raw.refs) {
        if (const auto* e = locs.located(ref)) {
            f.outline.push_back(node_ref(ref, e->lonlat, ctx.projection));
            in_selection = in_selection || ctx.selection.contains(e->lonlat);
        }
    }
    if (f.outline.empty()) {
        if (!ctx.selection.spatial() && !ctx.selection.relation) {
            ++result.counts.input_features;
            result.dropped.push_back({"feature", f.osm_type, f.id, f.kind + ": none of its nodes is in the input"});
        }
        return;
    }
    if (f.outline.size() < raw.refs.size()) {
        f.area = false; // a clipped outline is no longer a closed ring
        result.repairs.push_back({"feature", f.osm_type, f.id,
                                  "clipped: " + std::to_string(raw.refs.size() - f.outline.size()) + " of " +
                                      std::to_string(raw.refs.size()) + " nodes missing; outline kept open"});
    }
    const XY c = centroid(f.outline, f.area);
    f.position.id = 0; // a derived point, not an OSM node
    f.position.xy = c;
    f.position.lonlat = ctx.projection.inverse(c);
    const double limit = reach_for(f.kind, ctx.options);
    const bool near = std::any_of(f.outline.begin(), f.outline.end(),
                                  [&](const NodeRef& n) { return ctx.grid.within(n.xy, limit); });
    place(std::move(f), in_selection, near, raw.text_repaired, ctx, result);
}

} // namespace

void select_features(std::vector<RawFeature> points, std::vector<RawFeature> areas, const NodeLocations& locs,
                     const FeatureContext& ctx, IngestResult& result) {
    for (auto& raw : points) {
        place_point(raw, ctx, result);
    }
    for (auto& raw : areas) {
        place_area(raw, locs, ctx, result);
    }
}

} // namespace railodd::ingest
