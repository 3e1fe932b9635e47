// Features onto edges: on-track nodes by node id, everything else by the
// nearest alignment among the edges whose polylines pass near.
#include "railodd/geometry/feature_attachment.hpp"

#include "edge_index.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>
#include <stdexcept>
#include <string>
#include <tuple>

namespace railodd::geometry {

namespace {

// A fitted alignment may lie this far from its polyline (chords of curves,
// smoothed-out mapping noise): edges whose polylines are this much farther
// than the nearest are still asked.
constexpr double alignment_slack_m = 3.0;

struct NodePass {
    std::int64_t node;
    std::size_t edge;
    std::size_t index;
};

bool is_station(const ingest::Feature& f) { return f.kind == "station" || f.kind == "halt"; }

std::string too_far(const ingest::Feature& f, double distance, std::size_t edge, double limit) {
    std::ostringstream s;
    s.precision(1);
    s << std::fixed << f.kind << " is " << distance << " m from the nearest track (edge " << edge
      << "), farther than the " << limit << " m limit";
    return s.str();
}

class Attacher {
public:
    Attacher(const TrackGraph& tracks, const std::vector<IndexedAlignment>& alignments, double max_distance_m,
             double station_max_distance_m);
    void attach(std::size_t i, const ingest::Feature& f, Attachment& out) const;

private:
    std::optional<AttachedFeature> on_track_node(const ingest::Feature& f) const;
    std::optional<AttachedFeature> nearest(const ingest::Feature& f, double limit, std::string& reason) const;
    void set_extent(const ingest::Feature& f, AttachedFeature& a) const;

    const TrackGraph& tracks_;
    const std::vector<IndexedAlignment>& alignments_;
    double max_distance_m_;
    double station_max_distance_m_;
    detail::EdgeIndex index_;
    std::vector<NodePass> passes_; // by node id, then edge, then index
};

Attacher::Attacher(const TrackGraph& tracks, const std::vector<IndexedAlignment>& alignments, double max_distance_m,
                   double station_max_distance_m)
    : tracks_(tracks), alignments_(alignments), max_distance_m_(max_distance_m),
      station_max_distance_m_(station_max_distance_m), index_(tracks) {
    if (alignments.size() != tracks.edges.size()) {
        throw std::invalid_argument("attach_features: " + std::to_string(alignments.size()) + " alignments for " +
                                    std::to_string(tracks.edges.size()) + " track edges");
    }
    for (const auto& e : tracks.edges) {
        for (std::size_t k = 0; k < e.nodes.size(); ++k) {
            passes_.push_back({e.nodes[k].id, e.id, k});
        }
    }
    std::sort(passes_.begin(), passes_.end(), [](const NodePass& a, const NodePass& b) {
        return std::tie(a.node, a.edge, a.index) < std::tie(b.node, b.edge, b.index);
    });
}

// The node's own edge: topology, not proximity, which could pick a parallel
// track or the other leg of a switch.
std::optional<AttachedFeature> Attacher::on_track_node(const ingest::Feature& f) const {
    if (!f.on_track || f.osm_type != "node") {
        return std::nullopt;
    }
    const auto it = std::lower_bound(passes_.begin(), passes_.end(), f.id,
                                     [](const NodePass& p, std::int64_t id) { return p.node < id; });
    if (it == passes_.end() || it->node != f.id) {
        return std::nullopt;
    }
    const GraphEdge& e = tracks_.edges[it->edge];
    const IndexedAlignment& al = alignments_[it->edge];
    const Projection p = al.project(f.position.xy.x, f.position.xy.y);
    AttachedFeature a;
    a.edge = it->edge;
    a.s = p.s;
    a.offset = p.offset;
    a.distance = p.distance;
    if (it->index == 0 || it->index + 1 == e.nodes.size()) {
        a.vertex = it->index == 0 ? e.from : e.to;
        // Exactly at the alignment's end; which end is asked of the alignment,
        // so one fitted against the edge's node order works as well.
        a.s = p.s < 0.5 * al.length() ? 0.0 : al.length();
    }
    return a;
}

std::optional<AttachedFeature> Attacher::nearest(const ingest::Feature& f, double limit, std::string& reason) const {
    const ingest::XY p = f.position.xy;
    const detail::EdgeIndex::Near near = index_.near(p, alignment_slack_m);
    if (near.edges.empty()) {
        reason = "no track edge to attach to";
        return std::nullopt;
    }
    std::optional<AttachedFeature> best;
    for (const std::size_t edge : near.edges) {
        const Projection q = alignments_[edge].project(p.x, p.y);
        if (!best || q.distance < best->distance) {
            best = AttachedFeature{0, edge, q.s, q.offset, q.distance, q.s, q.s, std::nullopt};
        }
    }
    // An outline reaching towards the track counts from its nearest node.
    double reach = best->distance;
    for (const auto& n : f.outline) {
        reach = std::min(reach, alignments_[best->edge].project(n.xy.x, n.xy.y).distance);
    }
    if (reach > limit) {
        reason = too_far(f, reach, best->edge, limit);
        return std::nullopt;
    }
    return best;
}

void Attacher::set_extent(const ingest::Feature& f, AttachedFeature& a) const {
    a.s_start = a.s_end = a.s;
    if (f.outline.empty()) {
        return;
    }
    a.s_start = a.s_end = alignments_[a.edge].project(f.outline[0].xy.x, f.outline[0].xy.y).s;
    for (const auto& n : f.outline) {
        const double s = alignments_[a.edge].project(n.xy.x, n.xy.y).s;
        a.s_start = std::min(a.s_start, s);
        a.s_end = std::max(a.s_end, s);
    }
}

void Attacher::attach(std::size_t i, const ingest::Feature& f, Attachment& out) const {
    std::optional<AttachedFeature> a = on_track_node(f);
    std::string reason;
    if (!a) {
        a = nearest(f, is_station(f) ? station_max_distance_m_ : max_distance_m_, reason);
    }
    if (!a) {
        out.unattached.push_back({i, reason});
        return;
    }
    a->feature = i;
    set_extent(f, *a);
    out.attached.push_back(*a);
}

} // namespace

Attachment attach_features(const TrackGraph& tracks, const std::vector<IndexedAlignment>& alignments,
                           const std::vector<ingest::Feature>& features, double max_distance_m,
                           double station_max_distance_m) {
    const Attacher attacher(tracks, alignments, max_distance_m, station_max_distance_m);
    Attachment out;
    for (std::size_t i = 0; i < features.size(); ++i) {
        attacher.attach(i, features[i], out);
    }
    return out;
}

Attachment attach_features(const TrackGraph& tracks, const std::vector<IndexedAlignment>& alignments,
                           const std::vector<ingest::Feature>& features, double max_distance_m) {
    return attach_features(tracks, alignments, features, max_distance_m, max_distance_m);
}

} // namespace railodd::geometry
