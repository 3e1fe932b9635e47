#include "railodd/xodr/rail_network.hpp"

#include "plan_view.hpp"
#include "rail_vertex_plan.hpp"

#include "railodd/geometry/indexed_alignment.hpp"

#include <algorithm>
#include <cmath>
#include <map>
#include <optional>
#include <set>

namespace railodd::xodr {

RoadLocation RailNetwork::locate(std::size_t edge, double s) const {
    const auto& ps = pieces.at(edge);
    const RoadPiece* hit = &ps.at(0);
    for (const auto& p : ps) {
        if (p.s0 <= s) {
            hit = &p;
        }
    }
    return {hit->road, std::clamp(s - hit->s0, 0.0, hit->s1 - hit->s0)};
}

namespace {

constexpr double rail_head_width_m = 0.072; // UIC 60: the lane spans the outer edges of the rail heads

struct SpanRange {
    double s0 = 0.0;
    double s1 = 0.0;
    const ingest::Way* way = nullptr;
};

// What the written roads of one edge need from the ways behind it.
struct EdgeSource {
    std::vector<SpanRange> spans; // ascending s along the alignment
    std::string lane_type = "rail";
    double lane_width = 1.435 + rail_head_width_m;
    std::string name;
};

double gauge_m(const ingest::Tags& tags) {
    const std::string g = ingest::tag_or(tags, "gauge");
    char* end = nullptr;
    const double mm = std::strtod(g.c_str(), &end); // "1435;1000" (dual gauge): the first
    return end != g.c_str() && mm > 300.0 && mm < 3000.0 ? mm / 1000.0 : 1.435;
}

// `prebuilt`: the edge's alignment indexed at 2 m, or null.
EdgeSource source_of(const geometry::GraphEdge& e, const geometry::FittedEdge& fe,
                     const std::map<std::int64_t, const ingest::Way*>& ways, const geometry::IndexedAlignment* prebuilt) {
    EdgeSource src;
    std::optional<geometry::IndexedAlignment> own;
    const geometry::IndexedAlignment& ia = prebuilt ? *prebuilt : own.emplace(fe.alignment, 2.0);
    for (const auto& span : e.ways) {
        const auto it = ways.find(span.way_id);
        const ingest::Way* w = it == ways.end() ? nullptr : it->second;
        const auto& a = e.nodes[span.first].xy;
        const auto& b = e.nodes[span.last].xy;
        const double sa = ia.project(a.x, a.y).s, sb = ia.project(b.x, b.y).s;
        src.spans.push_back({std::min(sa, sb), std::max(sa, sb), w});
        if (w && ingest::tag_or(w->tags, "railway") == "tram") {
            src.lane_type = "tram";
        }
    }
    std::sort(src.spans.begin(), src.spans.end(), [](const SpanRange& x, const SpanRange& y) { return x.s0 < y.s0; });
    if (!src.spans.empty() && src.spans.front().way) {
        const ingest::Tags& t = src.spans.front().way->tags;
        src.lane_width = gauge_m(t) + rail_head_width_m;
        src.name = ingest::tag_or(t, "name", ingest::tag_or(t, "ref"));
    }
    return src;
}

std::string way_list(const EdgeSource& src, double s0, double s1) {
    std::string out;
    std::int64_t last = 0;
    for (const auto& sp : src.spans) {
        const bool overlaps = sp.s1 > s0 + 1e-6 && sp.s0 < s1 - 1e-6;
        const bool holds = s1 - s0 < 1e-6 && sp.s0 <= s0 && s0 <= sp.s1;
        if (!sp.way || !(overlaps || holds) || sp.way->id == last) {
            continue;
        }
        out += (out.empty() ? "way:" : ",way:") + std::to_string(sp.way->id);
        last = sp.way->id;
    }
    return out;
}

class RailBuilder {
public:
    RailBuilder(const RailInput& in, const RailOptions& o, IdCounter& ids, Map& map) : in_(in), o_(o), ids_(ids), map_(map) {
        for (const auto& w : in.ways) {
            ways_[w.id] = &w;
        }
    }

    RailNetwork run() {
        const std::size_t n = in_.graph.edges.size();
        net_.pieces.resize(n);
        std::vector<bool> written(n, false);
        for (std::size_t e = 0; e < n; ++e) {
            written[e] = geometry::length(in_.fitted.edges[e].alignment) > 1e-6;
            if (!written[e]) {
                net_.unwritten.push_back({e, "zero length: all its nodes lie at one position"});
            }
        }
        const std::vector<VertexPlan> plans = plan_vertices(in_.graph, in_.fitted, written);
        cut_back(plans);
        main_.assign(n, 0);
        for (std::size_t e = 0; e < n; ++e) {
            if (written[e]) {
                const double len = geometry::length(in_.fitted.edges[e].alignment);
                main_[e] = add_piece(e, d_start_[e], len - d_end_[e], "-1");
            }
        }
        for (const auto& plan : plans) {
            plan.junction ? add_junction(plan) : add_direct_link(plan);
            for (const auto& [leg, why] : plan.unlinked) {
                net_.unlinked.push_back({plan.vertex, plan.legs[leg].edge, why});
            }
        }
        for (auto& ps : net_.pieces) {
            std::sort(ps.begin(), ps.end(), [](const RoadPiece& a, const RoadPiece& b) { return a.s0 < b.s0; });
        }
        return std::move(net_);
    }

private:
    void cut_back(const std::vector<VertexPlan>& plans) {
        const std::size_t n = in_.graph.edges.size();
        d_start_.assign(n, 0.0);
        d_end_.assign(n, 0.0);
        for (const auto& plan : plans) {
            for (std::size_t i = 0; i < plan.legs.size(); ++i) {
                if (plan.cut[i]) {
                    const Leg& leg = plan.legs[i];
                    const double d = std::min(o_.connecting_length_m, geometry::length(in_.fitted.edges[leg.edge].alignment) / 3.0);
                    (leg.at_start ? d_start_ : d_end_)[leg.edge] = d;
                }
            }
        }
    }

    const geometry::IndexedAlignment* prebuilt(std::size_t e) const {
        return in_.indexed && in_.indexed->size() == in_.fitted.edges.size() ? &(*in_.indexed)[e] : nullptr;
    }

    const EdgeSource& source(std::size_t e) {
        auto it = sources_.find(e);
        if (it == sources_.end()) {
            it = sources_.emplace(e, source_of(in_.graph.edges[e], in_.fitted.edges[e], ways_, prebuilt(e))).first;
        }
        return it->second;
    }

    // Writes [s0, s1] of edge e's alignment as a road; returns its index.
    std::size_t add_piece(std::size_t e, double s0, double s1, const std::string& junction, bool piece = true) {
        const geometry::Alignment& a = in_.fitted.edges[e].alignment;
        const double len = geometry::length(a);
        std::vector<double> cuts;
        if (s0 > 0.0) {
            cuts.push_back(s0);
        }
        if (s1 < len) {
            cuts.push_back(s1);
        }
        const std::vector<geometry::Alignment> parts = geometry::split_alignment(a, cuts);
        const EdgeSource& src = source(e);
        Road r;
        r.id = ids_.road();
        r.name = src.name;
        r.junction = junction;
        r.type.clear();
        r.rail = true;
        r.plan_view = plan_view_of(parts[s0 > 0.0 ? 1 : 0], true);
        if (e < in_.profiles.size()) {
            r.elevation = cut_polys(in_.profiles[e].polys, s0, s1);
        }
        if (e < in_.cants.size() && !in_.cants[e].empty()) {
            r.superelevation = cut_superelevation(superelevation_of(in_.cants[e], len, o_.rail_spacing_m), s0, s1);
        }
        r.lane_offset = src.lane_width / 2.0; // centres the single lane on the reference line (the track axis)
        LaneSection ls;
        ls.right.push_back(Lane{-1, src.lane_type, src.lane_width, {}, ""});
        r.lane_sections.push_back(ls);
        r.user_data.push_back({"osm", way_list(src, s0, s1)});
        const auto& ge = in_.graph.edges[e];
        r.user_data.push_back({"osm_edge_nodes", "node:" + std::to_string(ge.nodes.front().id) + ",node:" +
                                                      std::to_string(ge.nodes.back().id)});
        map_.roads.push_back(std::move(r));
        const RoadPiece p{map_.roads.size() - 1, s0, s1};
        if (piece) {
            net_.pieces[e].push_back(p);
        } else {
            net_.copies.emplace_back(e, p);
        }
        return map_.roads.size() - 1;
    }

    void add_direct_link(const VertexPlan& plan) {
        for (const auto& [i, j] : plan.movements) {
            const Leg& a = plan.legs[i];
            const Leg& b = plan.legs[j];
            Road& ra = map_.roads[main_[a.edge]];
            Road& rb = map_.roads[main_[b.edge]];
            set_road_link(ra, a.at_start, rb.id, b.at_start);
            set_road_link(rb, b.at_start, ra.id, a.at_start);
            ++net_.direct_links;
        }
    }

    static void set_road_link(Road& r, bool at_start, const std::string& other, bool other_at_start) {
        (at_start ? r.predecessor : r.successor) = {ElementType::road, other, other_at_start ? Contact::start : Contact::end};
        auto& lane = r.lane_sections.front().right.front().link;
        (at_start ? lane.predecessor : lane.successor) = -1;
    }

    void add_junction(const VertexPlan& plan);
    void add_switch(const VertexPlan& plan, std::size_t stem, const std::map<std::size_t, std::size_t>& connecting);

    const RailInput& in_;
    const RailOptions& o_;
    IdCounter& ids_;
    Map& map_;
    RailNetwork net_;
    std::map<std::int64_t, const ingest::Way*> ways_;
    std::map<std::size_t, EdgeSource> sources_;
    std::vector<double> d_start_, d_end_;
    std::vector<std::size_t> main_; // main road index per edge
    std::map<std::size_t, std::size_t> switches_at_; // vertex -> switches written there
};

// One connecting road per movement, named by exactly one connection: CARLA
// matches connections on the connecting road's own links and lists a road
// once per connection naming it, and esmini adds the counter connection
// from the other side itself. The connection's incoming road is the one at
// the connecting road's start, so every contactPoint is "start".
void RailBuilder::add_junction(const VertexPlan& plan) {
    if (plan.movements.empty()) {
        return;
    }
    const auto& vertex = in_.graph.vertices[plan.vertex];
    Junction j;
    j.id = ids_.junction();
    j.name = std::string(geometry::to_string(vertex.kind)) + " " + std::to_string(vertex.node_id);
    j.user_data.push_back({"osm", "node:" + std::to_string(vertex.node_id)});
    std::map<std::size_t, std::size_t> connecting; // movement -> its connecting road
    std::set<std::size_t> pieced;                  // cut legs whose stretch is mapped to a road already
    for (std::size_t m = 0; m < plan.movements.size(); ++m) {
        const auto& [u, k] = plan.movements[m];
        const Leg& cut = plan.legs[k];
        const double len = geometry::length(in_.fitted.edges[cut.edge].alignment);
        // A cut leg with several movements gets a copy per movement; the
        // profile maps its stretch to the first.
        const bool piece = pieced.insert(k).second;
        const std::size_t c = cut.at_start ? add_piece(cut.edge, 0.0, d_start_[cut.edge], j.id, piece)
                                           : add_piece(cut.edge, len - d_end_[cut.edge], len, j.id, piece);
        connecting[m] = c;
        const Road& in = map_.roads[main_[plan.legs[u].edge]];
        const Road& out = map_.roads[main_[cut.edge]];
        set_road_link(map_.roads[c], !cut.at_start, out.id, cut.at_start);
        set_road_link(map_.roads[c], cut.at_start, in.id, plan.legs[u].at_start);
        j.connections.push_back({std::to_string(j.connections.size()), cut.at_start ? in.id : out.id,
                                 map_.roads[c].id, Contact::start, {{-1, -1}}});
    }
    for (std::size_t i = 0; i < plan.legs.size(); ++i) {
        const bool moves = std::any_of(plan.movements.begin(), plan.movements.end(),
                                       [&](const auto& m) { return m.first == i || m.second == i; });
        if (moves) {
            Road& r = map_.roads[main_[plan.legs[i].edge]];
            (plan.legs[i].at_start ? r.predecessor : r.successor) = {ElementType::junction, j.id, Contact::start};
        }
    }
    net_.connections += j.connections.size();
    ++net_.junctions;
    map_.junctions.push_back(std::move(j));
    for (std::size_t u = 0; u < plan.legs.size(); ++u) {
        const auto n = std::count_if(plan.movements.begin(), plan.movements.end(), [&](const auto& m) { return m.first == u; });
        if (n == 2 && vertex.kind == geometry::VertexKind::switch_) {
            add_switch(plan, u, connecting);
        }
    }
}

// <railroad><switch> on the stem's road: the main track is the connecting
// road that continues the stem's own fitted chain, the side track the other.
void RailBuilder::add_switch(const VertexPlan& plan, std::size_t stem, const std::map<std::size_t, std::size_t>& connecting) {
    std::vector<std::size_t> legs, roads; // the stem's two movements: cut leg, connecting road
    for (std::size_t m = 0; m < plan.movements.size(); ++m) {
        if (plan.movements[m].first == stem) {
            legs.push_back(plan.movements[m].second);
            roads.push_back(connecting.at(m));
        }
    }
    const std::size_t chain = in_.fitted.edges[plan.legs[stem].edge].chain;
    if (in_.fitted.edges[plan.legs[legs[1]].edge].chain == chain) {
        std::swap(legs[0], legs[1]);
        std::swap(roads[0], roads[1]);
    }
    auto ref = [&](std::size_t i) {
        const Road& c = map_.roads[roads[i]];
        const bool at_start = plan.legs[legs[i]].at_start;
        return TrackRef{c.id, at_start ? 0.0 : c.length(), at_start ? "+" : "-"};
    };
    const auto& vertex = in_.graph.vertices[plan.vertex];
    Switch sw;
    sw.id = ids_.other();
    // A vertex with two stems (a double slip) has two switches; names are unique.
    const std::size_t before = switches_at_[plan.vertex]++;
    sw.name = "switch " + std::to_string(vertex.node_id) + (before ? "/" + std::to_string(before + 1) : "");
    sw.main_track = ref(0);
    sw.side_track = ref(1);
    sw.user_data.push_back({"osm", "node:" + std::to_string(vertex.node_id)});
    map_.roads[main_[plan.legs[stem].edge]].switches.push_back(std::move(sw));
    ++net_.switches;
}

} // namespace

RailNetwork add_rail_network(const RailInput& input, const RailOptions& options, IdCounter& ids, Map& map) {
    return RailBuilder(input, options, ids, map).run();
}

} // namespace railodd::xodr
