#include "tag_context.hpp"

#include <algorithm>
#include <cmath>
#include <tuple>

namespace railodd::odd {

TagContext::TagContext(const TaggerInput& in, const Taxonomy& taxonomy, OddProfile& out)
    : in_(in), taxonomy_(taxonomy), out_(out) {
    for (const auto& w : in.map_input.ingest.tracks) {
        way_by_id_[w.id] = &w;
    }
    for (const auto& f : in.map_input.ingest.features) {
        if (f.osm_type == "node") {
            node_features_.emplace(f.id, &f);
        }
    }
}

void TagContext::set_batch(std::size_t first, std::size_t last) {
    first_ = first;
    last_ = last;
}

void TagContext::end_batch() {
    alignments_.clear();
    ways_.clear();
}

void TagContext::for_each_alignment(
    const std::function<void(std::size_t, const geometry::IndexedAlignment&)>& f) const {
    for (std::size_t e = 0; e < geo().geometry.fitted_tracks.edges.size(); ++e) {
        if (const geometry::IndexedAlignment* prebuilt = geo().geometry.indexed_edge(e)) {
            f(e, *prebuilt);
        } else {
            f(e, geometry::IndexedAlignment::for_evaluation(geo().geometry.fitted_tracks.edges[e].alignment));
        }
    }
}

const geometry::IndexedAlignment& TagContext::alignment(std::size_t edge) {
    if (const geometry::IndexedAlignment* prebuilt = geo().geometry.indexed_edge(edge)) {
        return *prebuilt;
    }
    auto& slot = alignments_[edge];
    if (!slot) {
        slot = std::make_unique<geometry::IndexedAlignment>(geo().geometry.fitted_tracks.edges[edge].alignment, 2.0);
    }
    return *slot;
}

const std::vector<WayRange>& TagContext::ways(std::size_t edge) {
    auto it = ways_.find(edge);
    if (it != ways_.end()) {
        return it->second;
    }
    const auto& e = geo().geometry.tracks.edges[edge];
    const auto& ia = alignment(edge);
    // A node's share of the way along the mapped polyline, in the
    // alignment's direction: where a short way's two ends project onto one
    // point (a way of 0.7 m at a spliced end whose curve passes its nodes
    // a metre off: Cologne way 33510672), its range is read from it instead
    // of being dropped.
    std::vector<double> t;
    const auto chainage = [&](std::size_t i) {
        if (t.empty()) {
            t.assign(e.nodes.size(), 0.0);
            for (std::size_t j = 1; j < t.size(); ++j) {
                t[j] = t[j - 1] + std::hypot(e.nodes[j].xy.x - e.nodes[j - 1].xy.x, e.nodes[j].xy.y - e.nodes[j - 1].xy.y);
            }
        }
        return t[i];
    };
    const auto share = [&](std::size_t i) {
        const double u = chainage(e.nodes.size() - 1) > 0.0 ? chainage(i) / chainage(e.nodes.size() - 1) : 0.0;
        return (geo().geometry.fitted_tracks.edges[edge].reversed ? 1.0 - u : u) * ia.length();
    };
    std::vector<WayRange> out;
    for (const auto& span : e.ways) {
        const auto w = way_by_id_.find(span.way_id);
        if (w == way_by_id_.end()) {
            continue;
        }
        const auto& a = e.nodes[span.first].xy;
        const auto& b = e.nodes[span.last].xy;
        double sa = ia.project(a.x, a.y).s, sb = ia.project(b.x, b.y).s;
        if (std::abs(sb - sa) <= 1e-6 && chainage(span.last) > chainage(span.first)) {
            sa = share(span.first);
            sb = share(span.last);
        }
        out.push_back({std::min(sa, sb), std::max(sa, sb), w->second});
    }
    std::sort(out.begin(), out.end(), [](const WayRange& x, const WayRange& y) { return x.s0 < y.s0; });
    // The first and last span reach the alignment's ends (projection of the end
    // nodes can fall a few centimetres short).
    if (!out.empty()) {
        out.front().s0 = 0.0;
        out.back().s1 = ia.length();
    }
    return ways_.emplace(edge, std::move(out)).first->second;
}

const ingest::Feature* TagContext::feature_at_node(std::int64_t node_id) const {
    const auto it = node_features_.find(node_id);
    return it == node_features_.end() ? nullptr : it->second;
}

std::vector<std::string> TagContext::way_ids(std::size_t edge, double s0, double s1) {
    std::vector<std::string> ids;
    for (const auto& r : ways(edge)) {
        const bool overlaps = r.s1 > s0 + 1e-6 && r.s0 < s1 - 1e-6;
        const bool holds = s1 - s0 <= 1e-6 && r.s0 <= s0 + 1e-6 && s0 <= r.s1 + 1e-6;
        const std::string id = "way:" + std::to_string(r.way->id);
        if ((overlaps || holds) && std::find(ids.begin(), ids.end(), id) == ids.end()) {
            ids.push_back(id);
        }
    }
    return ids;
}

void TagContext::sort_elements() {
    auto& elements = out_.elements;
    std::vector<std::size_t> order(elements.size());
    for (std::size_t i = 0; i < order.size(); ++i) {
        order[i] = i;
    }
    std::sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) {
        const TaggedElement& x = elements[a];
        const TaggedElement& y = elements[b];
        return std::tie(x.track, x.chainage_start, x.element, x.chainage_end, a) <
               std::tie(y.track, y.chainage_start, y.element, y.chainage_end, b);
    });
    // The permutation applied in place, cycle by cycle: no second copy of the
    // elements and no merge buffer, as std::stable_sort would take.
    for (std::size_t i = 0; i < order.size(); ++i) {
        if (order[i] == i) {
            continue;
        }
        TaggedElement held = std::move(elements[i]);
        std::size_t at = i;
        while (order[at] != i) {
            const std::size_t from = order[at];
            elements[at] = std::move(elements[from]);
            order[at] = at;
            at = from;
        }
        elements[at] = std::move(held);
        order[at] = at;
    }
}

void TagContext::unparsed(std::vector<std::string> osm_ids, const std::string& tag, const std::string& value,
                          const std::string& reason) {
    out_.unparsed.push_back({std::move(osm_ids), tag, value, reason});
}

namespace {

// A stretch's line in the GeoJSON stays this close (m) to the fitted
// centreline: a point per primitive joint and as many between as the
// curvature needs (R 300 m: one every 11 m; lines: their ends). Every 20 m
// whatever the curve had left 17 cm at R 300 and sampled straights for
// nothing.
constexpr double max_sagitta_m = 0.05;

std::vector<TaggedAttribute> classified(const Taxonomy& t, const Element& element, std::vector<TaggedAttribute> attrs) {
    std::vector<TaggedAttribute> out;
    for (auto& a : attrs) {
        const Attribute* def = t.attribute(element, a.name);
        const double* v = std::get_if<double>(&a.value);
        std::string label = def && v ? classify(*def, *v) : "";
        out.push_back(std::move(a));
        if (!label.empty()) {
            out.push_back({out.back().name + "_class", label});
        }
    }
    return out;
}

} // namespace

void TagContext::tag(const std::string& path, std::size_t edge, double s0, double s1,
                     std::vector<TaggedAttribute> attributes, std::vector<std::string> osm_ids,
                     const std::string& source) {
    const Element* element = taxonomy_.find(path);
    if (!element) {
        throw std::logic_error("the tagger names '" + path + "', which is not in " + taxonomy_.source);
    }
    if (!written(edge) || !in_batch(edge)) {
        return;
    }
    attributes = classified(taxonomy_, *element, std::move(attributes));
    const auto& ia = alignment(edge);
    const auto& proj = geo().ingest.projection;
    auto lonlat = [&](double s) {
        const auto p = ia.evaluate(s);
        const auto ll = proj.inverse({p.x, p.y});
        return std::pair{ll.lon, ll.lat};
    };
    for (const auto& piece : in_.map.rail.pieces[edge]) {
        const bool point = s1 - s0 <= 1e-9;
        const double a = std::max(s0, piece.s0), b = std::min(s1, piece.s1);
        if (point ? (s0 < piece.s0 - 1e-9 || s0 > piece.s1 + 1e-9) : b - a <= 1e-6) {
            continue;
        }
        TaggedElement t;
        t.element = path;
        t.element_id = element->id;
        t.attributes = attributes;
        t.road_id = in_.map.map.roads[piece.road].id;
        t.s_start = (point ? s0 : a) - piece.s0;
        t.s_end = (point ? s0 : b) - piece.s0;
        t.track = edge;
        t.chainage_start = point ? s0 : a;
        t.chainage_end = point ? s0 : b;
        t.point = point;
        t.osm_ids = osm_ids;
        t.source = source;
        const std::vector<double> at = point ? std::vector<double>{s0}
                                             : ia.chord_stations(a, b, max_sagitta_m);
        // Exactly: grown by doubling, the network's sampled stretches (half a
        // million points on Cologne) held up to twice their size.
        t.lonlat.reserve(at.size());
        for (const double s : at) {
            t.lonlat.push_back(lonlat(s));
        }
        out_.elements.push_back(std::move(t));
        if (point) {
            break; // at a piece boundary, the first road holding the point
        }
    }
}

} // namespace railodd::odd
