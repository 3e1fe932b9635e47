// Tunnels and bridges: the s-ranges of the tunnel / bridge ways of each
// track, cut to the roads the track was written as.
#include "feature_context.hpp"

#include "railodd/geometry/indexed_alignment.hpp"

#include <algorithm>
#include <map>

namespace railodd::xodr {

namespace {

struct Span {
    Structure::Kind kind;
    double s0, s1;
    const ingest::Way* way;
};

std::optional<Structure::Kind> kind_of(const ingest::Tags& tags) {
    if (ingest::tag_or(tags, "tunnel", "no") != "no") {
        return Structure::Kind::tunnel;
    }
    if (ingest::tag_or(tags, "bridge", "no") != "no") {
        return Structure::Kind::bridge;
    }
    return std::nullopt;
}

std::string structure_type(const Span& sp) {
    if (sp.kind == Structure::Kind::tunnel) {
        return "standard";
    }
    const std::string m = ingest::tag_or(sp.way->tags, "bridge:material", ingest::tag_or(sp.way->tags, "material"));
    if (m == "steel" || m == "wood" || m == "brick") {
        return m;
    }
    return m == "stone" ? "brick" : "concrete"; // masonry; otherwise the commonest
}

std::vector<Span> spans_of(const geometry::GraphEdge& e, const geometry::FittedEdge& fe,
                           const std::map<std::int64_t, const ingest::Way*>& ways) {
    std::vector<Span> out;
    std::optional<geometry::IndexedAlignment> ia;
    for (const auto& span : e.ways) {
        const auto it = ways.find(span.way_id);
        const auto kind = it == ways.end() ? std::nullopt : kind_of(it->second->tags);
        if (!kind) {
            continue;
        }
        if (!ia) {
            ia.emplace(fe.alignment, 2.0);
        }
        const auto& a = e.nodes[span.first].xy;
        const auto& b = e.nodes[span.last].xy;
        const double sa = ia->project(a.x, a.y).s, sb = ia->project(b.x, b.y).s;
        out.push_back({*kind, std::min(sa, sb), std::max(sa, sb), it->second});
    }
    std::sort(out.begin(), out.end(), [](const Span& x, const Span& y) { return x.s0 < y.s0; });
    return out;
}

} // namespace

void add_structures(FeatureContext& ctx) {
    std::map<std::int64_t, const ingest::Way*> ways;
    for (const auto& w : ctx.in.ingest.tracks) {
        ways[w.id] = &w;
    }
    for (std::size_t e = 0; e < ctx.in.geometry.tracks.edges.size(); ++e) {
        const auto& pieces = ctx.build.rail.pieces[e];
        for (const Span& sp : spans_of(ctx.in.geometry.tracks.edges[e], ctx.in.geometry.fitted_tracks.edges[e], ways)) {
            for (const RoadPiece& p : pieces) {
                const double s0 = std::max(sp.s0, p.s0), s1 = std::min(sp.s1, p.s1);
                if (s1 - s0 < 1e-3) {
                    continue;
                }
                Structure st;
                st.kind = sp.kind;
                st.id = ctx.ids.object();
                st.name = ingest::tag_or(sp.way->tags, sp.kind == Structure::Kind::tunnel ? "tunnel:name" : "bridge:name",
                                         ingest::tag_or(sp.way->tags, "name"));
                st.s = s0 - p.s0;
                st.length = s1 - s0;
                st.type = structure_type(sp);
                st.user_data.push_back({"osm", "way:" + std::to_string(sp.way->id)});
                ctx.build.map.roads[p.road].structures.push_back(std::move(st));
                ++ctx.build.structures;
            }
        }
    }
}

} // namespace railodd::xodr
