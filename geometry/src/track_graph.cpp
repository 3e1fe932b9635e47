// The track graph: way segments keyed by node id, walked from vertex to
// vertex so that way splits (tag changes) never break an edge.
#include "railodd/geometry/track_graph.hpp"

#include <algorithm>
#include <limits>
#include <stdexcept>
#include <string>
#include <tuple>

namespace railodd::geometry {

namespace {

constexpr std::size_t npos = std::numeric_limits<std::size_t>::max();

// Segment `index` of a way part: nodes [index, index + 1].
struct Segment {
    std::size_t way;
    std::size_t part;
    std::size_t index;
    std::size_t a; // dense node index of the first node
    std::size_t b; // dense node index of the second node
};

// One end of a segment at a node; leaving the node through it runs with the
// way when `at_a`, against it otherwise.
struct End {
    std::size_t segment;
    bool at_a;
};

enum class NodeTag { none, switch_, railway_crossing };

VertexKind classify(std::size_t degree, NodeTag tag) {
    if (degree == 1) {
        return VertexKind::end;
    }
    // Tags decide between switch and crossing where the degree is ambiguous:
    // a slip or three-way switch has four or more ends.
    if (degree >= 3 && tag == NodeTag::switch_) {
        return VertexKind::switch_;
    }
    if (degree >= 3 && tag == NodeTag::railway_crossing) {
        return VertexKind::crossing;
    }
    if (degree == 3) {
        return VertexKind::switch_;
    }
    if (degree == 4) {
        return VertexKind::crossing;
    }
    return VertexKind::join;
}

// Where the current WaySpan of a walk stands.
struct SpanCursor {
    bool open = false;
    std::size_t way = 0;
    std::size_t part = 0;
    std::size_t index = 0; // last segment index taken
    bool reversed = false;
    std::size_t first = 0; // edge node position where the span began
};

class GraphBuilder {
public:
    GraphBuilder(const std::vector<ingest::Way>& ways, const std::vector<ingest::Feature>& features);
    TrackGraph build();

private:
    std::size_t node_index(std::int64_t id) const;
    const ingest::NodeRef& node_ref(const Segment& s, bool second) const;
    std::int64_t neighbour_id(const End& e) const;
    void index_nodes();
    void index_segments();
    void tag_nodes(const std::vector<ingest::Feature>& features);
    void walk_all_from(std::size_t node);
    GraphEdge walk(std::size_t start, End first);
    void step_span(GraphEdge& edge, SpanCursor& cur, const Segment& seg, bool reversed) const;
    TrackGraph finish();

    const std::vector<ingest::Way>& ways_;
    std::vector<std::int64_t> ids_; // ascending; a node's dense index is its rank
    std::vector<const ingest::NodeRef*> refs_;
    std::vector<std::vector<End>> ends_;
    std::vector<NodeTag> tags_;
    std::vector<bool> vertex_;
    std::vector<Segment> segments_;
    std::vector<bool> used_;
    std::vector<GraphEdge> edges_;
    std::vector<std::size_t> edge_from_; // dense node index per edge, until finish()
    std::vector<std::size_t> edge_to_;
};

GraphBuilder::GraphBuilder(const std::vector<ingest::Way>& ways, const std::vector<ingest::Feature>& features)
    : ways_(ways) {
    index_nodes();
    index_segments();
    tag_nodes(features);
    vertex_.resize(ids_.size());
    for (std::size_t n = 0; n < ids_.size(); ++n) {
        vertex_[n] = ends_[n].size() != 2 || tags_[n] != NodeTag::none;
    }
}

std::size_t GraphBuilder::node_index(std::int64_t id) const {
    const auto it = std::lower_bound(ids_.begin(), ids_.end(), id);
    return it != ids_.end() && *it == id ? static_cast<std::size_t>(it - ids_.begin()) : npos;
}

const ingest::NodeRef& GraphBuilder::node_ref(const Segment& s, bool second) const {
    return ways_[s.way].parts[s.part][s.index + (second ? 1 : 0)];
}

std::int64_t GraphBuilder::neighbour_id(const End& e) const {
    const Segment& s = segments_[e.segment];
    return ids_[e.at_a ? s.b : s.a];
}

// Only nodes of parts with a segment: a lone node of a clipped way joins nothing.
void GraphBuilder::index_nodes() {
    for (const auto& way : ways_) {
        for (const auto& part : way.parts) {
            if (part.size() >= 2) {
                for (const auto& n : part) {
                    ids_.push_back(n.id);
                }
            }
        }
    }
    std::sort(ids_.begin(), ids_.end());
    ids_.erase(std::unique(ids_.begin(), ids_.end()), ids_.end());
    refs_.assign(ids_.size(), nullptr);
    ends_.resize(ids_.size());
}

void GraphBuilder::index_segments() {
    for (std::size_t w = 0; w < ways_.size(); ++w) {
        for (std::size_t p = 0; p < ways_[w].parts.size(); ++p) {
            const auto& part = ways_[w].parts[p];
            for (std::size_t i = 0; i + 1 < part.size(); ++i) {
                const Segment s{w, p, i, node_index(part[i].id), node_index(part[i + 1].id)};
                ends_[s.a].push_back({segments_.size(), true});
                ends_[s.b].push_back({segments_.size(), false});
                refs_[s.a] = refs_[s.a] ? refs_[s.a] : &part[i];
                refs_[s.b] = refs_[s.b] ? refs_[s.b] : &part[i + 1];
                segments_.push_back(s);
            }
        }
    }
    used_.assign(segments_.size(), false);
    // Walk order, and so edge ids, follow neighbour ids, then way ids: never
    // the order of the input.
    const auto key = [this](const End& e) {
        const Segment& s = segments_[e.segment];
        return std::make_tuple(neighbour_id(e), ways_[s.way].id, s.way, s.part, s.index, e.at_a);
    };
    for (auto& list : ends_) {
        std::sort(list.begin(), list.end(), [&](const End& x, const End& y) { return key(x) < key(y); });
    }
}

void GraphBuilder::tag_nodes(const std::vector<ingest::Feature>& features) {
    tags_.assign(ids_.size(), NodeTag::none);
    for (const auto& f : features) {
        if (!f.on_track || f.osm_type != "node") {
            continue;
        }
        const std::size_t n = node_index(f.id);
        if (n == npos) {
            continue;
        }
        if (f.kind == "switch") {
            tags_[n] = NodeTag::switch_;
        } else if (f.kind == "railway_crossing" && tags_[n] == NodeTag::none) {
            tags_[n] = NodeTag::railway_crossing;
        }
    }
}

void GraphBuilder::walk_all_from(std::size_t node) {
    for (const End& e : ends_[node]) {
        if (!used_[e.segment]) {
            edges_.push_back(walk(node, e));
        }
    }
}

void GraphBuilder::step_span(GraphEdge& edge, SpanCursor& cur, const Segment& seg, bool reversed) const {
    const std::size_t at = edge.nodes.size() - 1; // position of the segment's first node in the edge
    const bool continues = cur.open && cur.way == seg.way && cur.part == seg.part && cur.reversed == reversed &&
                           (reversed ? seg.index + 1 == cur.index : seg.index == cur.index + 1);
    if (!continues) {
        if (cur.open) {
            edge.ways.push_back({ways_[cur.way].id, cur.first, at, cur.reversed});
        }
        cur = {true, seg.way, seg.part, seg.index, reversed, at};
    }
    cur.index = seg.index;
}

GraphEdge GraphBuilder::walk(std::size_t start, End first) {
    GraphEdge edge;
    edge.id = edges_.size();
    edge.nodes.push_back(*refs_[start]);
    SpanCursor cur;
    End e = first;
    std::size_t node = start;
    for (;;) {
        const Segment& seg = segments_[e.segment];
        used_[e.segment] = true;
        step_span(edge, cur, seg, !e.at_a);
        node = e.at_a ? seg.b : seg.a;
        edge.nodes.push_back(node_ref(seg, e.at_a));
        if (vertex_[node]) {
            break;
        }
        // A node of degree two: leave through the end that is not the one we came in by.
        const auto& list = ends_[node];
        const End in{e.segment, !e.at_a};
        e = (list[0].segment == in.segment && list[0].at_a == in.at_a) ? list[1] : list[0];
        if (used_[e.segment]) {
            throw std::logic_error("track graph: segment of way " + std::to_string(ways_[seg.way].id) +
                                   " reached twice at node " + std::to_string(ids_[node]));
        }
    }
    edge.ways.push_back({ways_[cur.way].id, cur.first, edge.nodes.size() - 1, cur.reversed});
    edge_from_.push_back(start);
    edge_to_.push_back(node);
    return edge;
}

TrackGraph GraphBuilder::build() {
    for (std::size_t n = 0; n < ids_.size(); ++n) {
        if (vertex_[n]) {
            walk_all_from(n);
        }
    }
    // What is left are rings of degree-2 nodes; each starts at its smallest node.
    for (std::size_t n = 0; n < ids_.size(); ++n) {
        const bool unused = std::any_of(ends_[n].begin(), ends_[n].end(), [&](const End& e) { return !used_[e.segment]; });
        if (unused) {
            vertex_[n] = true;
            walk_all_from(n);
        }
    }
    return finish();
}

TrackGraph GraphBuilder::finish() {
    TrackGraph g;
    std::vector<std::size_t> vertex_of(ids_.size(), npos);
    for (std::size_t n = 0; n < ids_.size(); ++n) {
        if (vertex_[n]) {
            vertex_of[n] = g.vertices.size();
            g.vertices.push_back({ids_[n], refs_[n]->xy, classify(ends_[n].size(), tags_[n]), {}});
        }
    }
    for (std::size_t i = 0; i < edges_.size(); ++i) {
        edges_[i].from = vertex_of[edge_from_[i]];
        edges_[i].to = vertex_of[edge_to_[i]];
        g.vertices[edges_[i].from].edges.push_back(i);
        g.vertices[edges_[i].to].edges.push_back(i); // twice for a loop, as documented
    }
    for (auto& v : g.vertices) {
        std::sort(v.edges.begin(), v.edges.end());
    }
    g.edges = std::move(edges_);
    return g;
}

} // namespace

const char* to_string(VertexKind kind) {
    switch (kind) {
    case VertexKind::end:
        return "end";
    case VertexKind::switch_:
        return "switch";
    case VertexKind::crossing:
        return "crossing";
    case VertexKind::join:
        return "join";
    }
    return "unknown";
}

TrackGraph build_track_graph(const std::vector<ingest::Way>& ways, const std::vector<ingest::Feature>& features) {
    return GraphBuilder(ways, features).build();
}

} // namespace railodd::geometry
