#include "railodd/geometry/profiles.hpp"

#include "profile_ties.hpp"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <map>
#include <optional>

namespace railodd::geometry {

namespace {

bool is_structure(const ingest::Tags& tags) {
    for (const char* key : {"tunnel", "bridge"}) {
        const std::string v = ingest::tag_or(tags, key, "no");
        if (v != "no") {
            return true;
        }
    }
    return false;
}

// s-ranges of the edge's tunnel and bridge ways along its alignment.
std::vector<std::pair<double, double>> structures_of(const GraphEdge& e, const IndexedAlignment& ia,
                                                     const std::map<std::int64_t, const ingest::Way*>& ways) {
    std::vector<std::pair<double, double>> out;
    for (const auto& span : e.ways) {
        const auto it = ways.find(span.way_id);
        if (it == ways.end() || !is_structure(it->second->tags)) {
            continue;
        }
        const auto& a = e.nodes[span.first].xy;
        const auto& b = e.nodes[span.last].xy;
        const double sa = ia.project(a.x, a.y).s, sb = ia.project(b.x, b.y).s;
        out.emplace_back(std::min(sa, sb), std::max(sa, sb));
    }
    std::sort(out.begin(), out.end());
    return out;
}

// OSM `ele` of the edge's nodes, interpolated along s at the samples.
std::vector<double> osm_ele_at(const GraphEdge& e, const IndexedAlignment& ia, const std::vector<double>& s) {
    std::vector<std::pair<double, double>> known;
    for (const auto& n : e.nodes) {
        if (!std::isnan(n.ele)) {
            known.emplace_back(ia.project(n.xy.x, n.xy.y).s, n.ele);
        }
    }
    std::vector<double> out(s.size(), std::numeric_limits<double>::quiet_NaN());
    if (known.empty()) {
        return out;
    }
    std::sort(known.begin(), known.end());
    for (std::size_t i = 0; i < s.size(); ++i) {
        auto it = std::lower_bound(known.begin(), known.end(), std::make_pair(s[i], -1e300));
        if (it == known.begin()) {
            out[i] = known.front().second;
        } else if (it == known.end()) {
            out[i] = known.back().second;
        } else {
            const auto& [s1, z1] = *it;
            const auto& [s0, z0] = *(it - 1);
            out[i] = s1 > s0 ? z0 + (z1 - z0) * (s[i] - s0) / (s1 - s0) : z0;
        }
    }
    return out;
}

} // namespace

std::vector<VerticalProfile> fit_profiles(const TrackGraph& graph, const FittedNetwork& net,
                                          const std::vector<ingest::Way>& ways, const ingest::LocalProjection& projection,
                                          const ElevationModel* dem) {
    std::map<std::int64_t, const ingest::Way*> by_id;
    for (const auto& w : ways) {
        by_id[w.id] = &w;
    }
    std::vector<VerticalProfile> out;
    out.reserve(net.edges.size());
    for (const auto& f : net.edges) {
        const GraphEdge& e = graph.edges[f.edge];
        const IndexedAlignment ia(f.alignment, 2.0);
        ProfileInput in = sample_alignment(ia, projection, 10.0, structures_of(e, ia, by_id));
        in.osm_ele = osm_ele_at(e, ia, in.s);
        out.push_back(fit_vertical_profile(in, dem, ProfileOptions{}));
    }
    tie_profiles(graph, net, out);
    return out;
}

namespace {

std::optional<double> number_tag(const ingest::Tags& tags, const char* key) {
    const std::string v = ingest::tag_or(tags, key);
    char* end = nullptr;
    const double d = std::strtod(v.c_str(), &end);
    return (!v.empty() && end != v.c_str()) ? std::optional<double>(d) : std::nullopt;
}

} // namespace

std::vector<std::vector<CantStretch>> fit_cants(const TrackGraph& graph, const FittedNetwork& net,
                                                const std::vector<ingest::Way>& ways, const CantOptions& options) {
    std::map<std::int64_t, const ingest::Way*> by_id;
    for (const auto& w : ways) {
        by_id[w.id] = &w;
    }
    std::vector<std::vector<CantStretch>> out;
    for (const auto& f : net.edges) {
        const GraphEdge& e = graph.edges[f.edge];
        const IndexedAlignment ia(f.alignment, 2.0);
        std::vector<CantTagSpan> spans;
        for (const auto& span : e.ways) {
            const auto it = by_id.find(span.way_id);
            if (it == by_id.end()) {
                continue;
            }
            const auto& a = e.nodes[span.first].xy;
            const auto& b = e.nodes[span.last].xy;
            const double sa = ia.project(a.x, a.y).s, sb = ia.project(b.x, b.y).s;
            // maxspeed is km/h unless it says otherwise; odd values are left to the ODD tagger.
            spans.push_back({std::min(sa, sb), std::max(sa, sb), number_tag(it->second->tags, "railway:cant"),
                             number_tag(it->second->tags, "maxspeed")});
        }
        std::sort(spans.begin(), spans.end(), [](const CantTagSpan& x, const CantTagSpan& y) { return x.s_start < y.s_start; });
        out.push_back(compute_cant(f.alignment, spans, options));
    }
    return out;
}

nlohmann::ordered_json cants_report(const std::vector<std::vector<CantStretch>>& cants) {
    std::size_t tagged = 0, estimated = 0;
    double max_mm = 0.0;
    for (const auto& track : cants) {
        for (const auto& c : track) {
            if (c.cant_start_m == c.cant_end_m && c.cant_start_m > 0) {
                (c.estimated ? estimated : tagged) += 1;
            }
            max_mm = std::max({max_mm, c.cant_start_m * 1000, c.cant_end_m * 1000});
        }
    }
    return {{"curves_with_tagged_cant", tagged}, {"curves_with_estimated_cant", estimated},
            {"max_cant_mm", std::round(max_mm * 10) / 10}};
}

nlohmann::ordered_json profiles_report(const TrackGraph& graph, const std::vector<VerticalProfile>& profiles) {
    std::map<std::string, std::size_t> sources;
    double max_grad = 0.0;
    nlohmann::ordered_json steep = nlohmann::ordered_json::array();
    for (std::size_t i = 0; i < profiles.size(); ++i) {
        const VerticalProfile& p = profiles[i];
        ++sources[to_string(p.source)];
        max_grad = std::max(max_grad, p.max_gradient_permille);
        for (const auto& st : p.steep) {
            steep.push_back({{"edge", graph.edges[i].id},
                             {"s_start", std::round(st.s_start * 10) / 10},
                             {"s_end", std::round(st.s_end * 10) / 10},
                             {"gradient_permille", std::round(st.gradient_permille * 100) / 100}});
        }
    }
    nlohmann::ordered_json src = nlohmann::ordered_json::object();
    for (const auto& [k, v] : sources) {
        src[k] = v;
    }
    return {{"sources", src},
            {"max_gradient_permille", std::round(max_grad * 100) / 100},
            {"steep_threshold_permille", ProfileOptions{}.steep_permille},
            {"steep", steep}};
}

} // namespace railodd::geometry
