#include "railodd/geometry/dump.hpp"

#include "railodd/geometry/design_summary.hpp"

#include "railodd/util/beside.hpp"
#include "railodd/util/json_text.hpp"

#include <algorithm>
#include <future>
#include <cmath>
#include <ostream>
#include <sstream>

namespace railodd::geometry {

using nlohmann::ordered_json;

namespace {

std::vector<std::int64_t> way_ids(const GraphEdge& e) {
    std::vector<std::int64_t> ids;
    for (const auto& w : e.ways) {
        if (std::find(ids.begin(), ids.end(), w.way_id) == ids.end()) {
            ids.push_back(w.way_id);
        }
    }
    return ids;
}

ordered_json primitive_counts(const Alignment& a) {
    std::size_t n[3] = {0, 0, 0};
    for (const auto& p : a.primitives) {
        ++n[static_cast<int>(p.kind)];
    }
    return {{"line", n[0]}, {"arc", n[1]}, {"spiral", n[2]}};
}

double round_to(double v, double unit) { return std::round(v / unit) * unit; }

struct Totals {
    std::vector<double> d;
    // Node distances in units of their chain's noise estimate, except on the
    // chains reported beyond their limit (nodes only corners tighter than a
    // track turns would follow: a chain's tie against its nodes): their
    // misses are no scatter, and their noise estimate as likely 0.09 m as
    // the 10 m cap (Munich chain 17, its tram junction ends 5 m off either
    // way). Those nodes are counted apart.
    std::vector<double> d_over_noise;
    std::size_t beyond_limit_nodes = 0;
    double length = 0.0;
    std::size_t fallback = 0;
};

ordered_json track_entry(const GraphEdge& e, const FittedEdge& f, const IndexedAlignment* indexed, bool beyond_limit,
                         Totals& t) {
    std::vector<Point> pts;
    for (const auto& n : e.nodes) {
        pts.push_back({n.xy.x, n.xy.y});
    }
    const std::vector<double> d = indexed ? distances(*indexed, pts) : distances(f.alignment, pts);
    t.d.insert(t.d.end(), d.begin(), d.end());
    t.beyond_limit_nodes += beyond_limit ? d.size() : 0;
    if (f.quality.noise_sigma_m > 0.0 && !beyond_limit) {
        for (const double x : d) {
            t.d_over_noise.push_back(x / f.quality.noise_sigma_m);
        }
    }
    t.length += length(f.alignment);
    ordered_json entry = {{"edge", e.id},
                          {"osm_ways", way_ids(e)},
                          {"from_node", e.nodes.front().id},
                          {"to_node", e.nodes.back().id},
                          {"reversed", f.reversed},
                          {"length_m", round_to(length(f.alignment), 1e-3)},
                          {"primitives", primitive_counts(f.alignment)},
                          {"nodes", f.quality.points},
                          {"rms_m", round_to(f.quality.rms_m, 1e-4)},
                          {"p95_m", round_to(f.quality.p95_m, 1e-4)},
                          {"max_m", round_to(f.quality.max_m, 1e-4)}};
    if (f.quality.noise_sigma_m > 0.0) {
        entry["noise_sigma_m"] = round_to(f.quality.noise_sigma_m, 1e-4);
    }
    return entry;
}

// The q quantile of ascending values (0 for none): the value at floor(q (n - 1)).
double quantile(const std::vector<double>& sorted, double q) {
    return sorted.empty() ? 0.0 : sorted[static_cast<std::size_t>(std::floor(q * static_cast<double>(sorted.size() - 1)))];
}

// The node scatter the fit assumed per chain and whether the node distances
// agree with it (p95 within about 2 sigma where the fit reads the design).
ordered_json noise_entry(const FittedNetwork& net, std::vector<double> d_over_noise, std::size_t beyond_limit_nodes) {
    std::vector<double> s;
    for (const double x : net.chain_noise_sigma_m) {
        if (x > 0.0) {
            s.push_back(x);
        }
    }
    std::sort(s.begin(), s.end());
    std::sort(d_over_noise.begin(), d_over_noise.end());
    return {{"chain_sigma_p50_m", round_to(quantile(s, 0.5), 1e-4)},
            {"chain_sigma_p95_m", round_to(quantile(s, 0.95), 1e-4)},
            {"chain_sigma_max_m", round_to(quantile(s, 1.0), 1e-4)},
            {"outlier_nodes", net.outlier_nodes},
            {"node_distance_p95_sigmas", round_to(quantile(d_over_noise, 0.95), 1e-3)},
            {"node_distance_max_sigmas", round_to(quantile(d_over_noise, 1.0), 1e-3)},
            {"beyond_limit_chain_nodes", beyond_limit_nodes}};
}

ordered_json links_entry(const FittedNetwork& net) {
    double gap = 0, hdg = 0, curv = 0;
    for (const auto& l : net.branch_links) {
        gap = std::max(gap, l.gap_m);
        hdg = std::max(hdg, l.heading_rad);
        curv = std::max(curv, l.curvature);
    }
    return {{"branch_links", net.branch_links.size()},
            {"untied_branch_ends", net.untied_branch_ends},
            {"degenerate_chains", net.degenerate_chains},
            {"corner_chains", net.corner_chains.size()},
            {"beyond_limit_chains", net.beyond_limit_chains.size()},
            {"spliced_ends", net.spliced_ends},
            {"patched_stretches", net.patched_stretches},
            {"reversed_chains", net.reversed_chains},
            {"reversing_links", net.reversing_links},
            {"max_gap_m", gap},
            {"max_heading_jump_rad", hdg},
            {"max_curvature_jump", curv}};
}

// How much the network reads like a railway design (design_summary.hpp),
// on the tracks' indexes where they are built already.
ordered_json design_entry(const FittedNetwork& net, const std::vector<IndexedAlignment>* indexed, bool two_threads) {
    DesignSummary d;
    if (indexed) {
        d = summarise_design(*indexed, two_threads);
    } else {
        std::vector<Alignment> alignments;
        alignments.reserve(net.edges.size());
        for (const FittedEdge& f : net.edges) {
            alignments.push_back(f.alignment);
        }
        d = summarise_design(alignments, two_threads);
    }
    return {{"spiral_share", round_to(d.spiral_share, 1e-4)},
            {"arc_share", round_to(d.arc_share, 1e-4)},
            {"elements_per_km", round_to(d.elements_per_km, 1e-3)},
            {"joints_per_km", round_to(d.joints_per_km, 1e-3)},
            {"short_element_share", round_to(d.short_element_share, 1e-4)},
            {"sign_changes_per_km", round_to(d.sign_changes_per_km, 1e-3)},
            {"parallel_pairs", d.parallel_pairs},
            {"parallel_curvature_difference_p50", round_to(d.parallel_difference_p50, 1e-4)},
            {"parallel_curvature_difference_p95", round_to(d.parallel_difference_p95, 1e-4)},
            {"parallel_share_over_10pct", round_to(d.parallel_share_over_10pct, 1e-4)}};
}

} // namespace

ordered_json report_section(const TrackGraph& graph, const FittedNetwork& net,
                            const std::vector<IndexedAlignment>* indexed, bool two_threads) {
    Totals t;
    ordered_json tracks = ordered_json::array();
    const bool prebuilt = indexed && indexed->size() == net.edges.size();
    std::vector<std::size_t> beyond_limit = net.beyond_limit_chains;
    std::sort(beyond_limit.begin(), beyond_limit.end());
    // The design summary reads the fits only: beside the per-track figures.
    std::future<ordered_json> design =
        std::async(util::beside(two_threads), [&] { return design_entry(net, prebuilt ? indexed : nullptr, two_threads); });
    for (std::size_t i = 0; i < net.edges.size(); ++i) {
        const FittedEdge& f = net.edges[i];
        const bool beyond = std::binary_search(beyond_limit.begin(), beyond_limit.end(), f.chain);
        tracks.push_back(track_entry(graph.edges[f.edge], f, prebuilt ? &(*indexed)[i] : nullptr, beyond, t));
    }
    std::sort(t.d.begin(), t.d.end());
    std::size_t switches = 0, crossings = 0;
    for (const auto& v : graph.vertices) {
        switches += v.kind == VertexKind::switch_ ? 1 : 0;
        crossings += v.kind == VertexKind::crossing ? 1 : 0;
    }
    ordered_json summary = {{"edges", graph.edges.size()},
                            {"chains", net.chains.size()},
                            {"switch_vertices", switches},
                            {"crossing_vertices", crossings},
                            {"length_km", round_to(t.length / 1000.0, 1e-6)},
                            {"nodes", t.d.size()},
                            {"node_distance_p50_m", round_to(quantile(t.d, 0.5), 1e-4)},
                            {"node_distance_p95_m", round_to(quantile(t.d, 0.95), 1e-4)},
                            {"node_distance_max_m", round_to(quantile(t.d, 1.0), 1e-4)},
                            {"links", links_entry(net)},
                            {"design", design.get()}};
    if (!net.chain_noise_sigma_m.empty()) {
        summary["node_noise"] = noise_entry(net, std::move(t.d_over_noise), t.beyond_limit_nodes);
    }
    return {{"summary", summary}, {"tracks", tracks}};
}

namespace {

void append_point(std::string& out, const Pose& p, const ingest::LocalProjection& proj, bool first) {
    const ingest::LonLat ll = proj.inverse({p.x, p.y});
    out += first ? "[" : ",[";
    append_json_number(out, std::round(ll.lon * 1e8) / 1e8);
    out += ',';
    append_json_number(out, std::round(ll.lat * 1e8) / 1e8);
    out += ']';
}

// Lines need their ends only; curves a point every 5 m.
void append_samples(std::string& out, const Alignment& a, const ingest::LocalProjection& proj) {
    Pose at = a.start;
    append_point(out, at, proj, true);
    for (const auto& p : a.primitives) {
        const int n = p.kind == PrimitiveKind::line ? 1 : std::max(1, static_cast<int>(std::ceil(p.length / 5.0)));
        for (int i = 1; i <= n; ++i) {
            append_point(out, evaluate(at, p, p.length * i / n), proj, false);
        }
        at = evaluate(at, p, p.length);
    }
}

} // namespace

void write_geojson(const TrackGraph& graph, const FittedNetwork& net, const ingest::LocalProjection& proj,
                   const char* layer, std::ostream& os) {
    // Printed feature by feature: a network's dump is never whole in memory.
    os << "{\"type\":\"FeatureCollection\",\"features\":[\n";
    std::string out;
    for (std::size_t i = 0; i < net.edges.size(); ++i) {
        const FittedEdge& f = net.edges[i];
        const GraphEdge& e = graph.edges[f.edge];
        out = i ? ",\n" : "";
        out += "{\"type\":\"Feature\",\"geometry\":{\"type\":\"LineString\",\"coordinates\":[";
        append_samples(out, f.alignment, proj);
        out += "]},\"properties\":{\"layer\":\"";
        out += layer;
        out += "\",\"edge\":";
        append_json_number(out, static_cast<std::int64_t>(e.id));
        out += ",\"osm_ways\":[";
        const auto ids = way_ids(e);
        for (std::size_t k = 0; k < ids.size(); ++k) {
            out += k ? "," : "";
            append_json_number(out, ids[k]);
        }
        out += "],\"primitives\":\"";
        for (const auto& p : f.alignment.primitives) {
            out += p.kind == PrimitiveKind::line ? 'L' : p.kind == PrimitiveKind::arc ? 'A' : 'S';
        }
        out += "\",\"rms_m\":";
        append_json_number(out, std::round(f.quality.rms_m * 1e4) / 1e4);
        out += ",\"max_m\":";
        append_json_number(out, std::round(f.quality.max_m * 1e4) / 1e4);
        out += "}}";
        os << out;
    }
    os << "\n]}\n";
}

std::string to_geojson(const TrackGraph& graph, const FittedNetwork& net, const ingest::LocalProjection& proj,
                       const char* layer) {
    std::ostringstream os;
    write_geojson(graph, net, proj, layer, os);
    return os.str();
}

} // namespace railodd::geometry
