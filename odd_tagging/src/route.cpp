#include "railodd/odd/route.hpp"

#include "route_network.hpp"

#include "railodd/geometry/alignment.hpp"
#include "railodd/odd/profile_summary.hpp"
#include "railodd/util/errors.hpp"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdint>
#include <functional>
#include <limits>
#include <numbers>
#include <optional>
#include <queue>
#include <set>
#include <tuple>

namespace railodd::odd {

using namespace route_detail;

namespace {

std::string lower(std::string s) {
    std::transform(s.begin(), s.end(), s.begin(), [](unsigned char c) { return std::tolower(c); });
    return s;
}

bool is_stop(const std::string& kind) {
    return kind == "station" || kind == "halt" || kind == "stop" || kind == "tram_stop";
}

// The attached stations named `name`: exact matches, else matches ignoring case.
std::vector<const geometry::AttachedFeature*> stations_named(const geometry::Attachment& attachment,
                                                             const std::vector<ingest::Feature>& features,
                                                             const std::string& name, std::string& found) {
    std::vector<const geometry::AttachedFeature*> exact, folded;
    std::set<std::string> names;
    for (const auto& a : attachment.attached) {
        const auto& f = features.at(a.feature);
        const std::string n = ingest::tag_or(f.tags, "name");
        if (!is_stop(f.kind) || n.empty()) {
            continue;
        }
        names.insert(n);
        if (n == name) {
            exact.push_back(&a);
        } else if (lower(n) == lower(name)) {
            folded.push_back(&a);
        }
    }
    if (exact.empty() && folded.empty()) {
        std::string list;
        for (const auto& n : names) {
            list += (list.empty() ? "" : ", ") + n;
        }
        throw InputError("", "station '" + name + "' is not in the selection; stations are: " +
                                 (list.empty() ? "(none)" : list));
    }
    found = ingest::tag_or(features[(exact.empty() ? folded : exact).front()->feature].tags, "name");
    return exact.empty() ? folded : exact;
}

// The element's sampled line (evenly spaced from chainage_start to
// chainage_end) cut to the fractions [t0, t1] of its length.
std::vector<std::pair<double, double>> cut_line(const std::vector<std::pair<double, double>>& line, double t0,
                                                double t1) {
    if (line.size() < 2 || (t0 <= 0.0 && t1 >= 1.0)) {
        return line;
    }
    const double last = static_cast<double>(line.size() - 1);
    auto at = [&](double t) {
        const double x = std::clamp(t, 0.0, 1.0) * last;
        const std::size_t i = std::min(static_cast<std::size_t>(x), line.size() - 2);
        const double f = x - static_cast<double>(i);
        return std::pair{line[i].first + f * (line[i + 1].first - line[i].first),
                         line[i].second + f * (line[i + 1].second - line[i].second)};
    };
    std::vector<std::pair<double, double>> out{at(t0)};
    for (std::size_t i = 1; i + 1 < line.size(); ++i) {
        const double t = static_cast<double>(i) / last;
        if (t > t0 && t < t1) {
            out.push_back(line[i]);
        }
    }
    out.push_back(at(t1));
    return out;
}

// The element's part on one route piece, in route chainage; none if it is off the piece.
std::optional<TaggedElement> on_piece(const TaggedElement& e, const RoutePiece& p) {
    const double lo = std::min(p.s_from, p.s_to), hi = std::max(p.s_from, p.s_to);
    const double c0 = std::min(e.chainage_start, e.chainage_end), c1 = std::max(e.chainage_start, e.chainage_end);
    const double a = e.point ? c0 : std::max(c0, lo), b = e.point ? c0 : std::min(c1, hi);
    if (e.track != p.edge || (e.point ? (a < lo - 1e-6 || a > hi + 1e-6) : b - a <= 1e-6)) {
        return std::nullopt;
    }
    auto chainage = [&](double s) { return p.chainage_start + (p.reversed ? p.s_from - s : s - p.s_from); };
    TaggedElement out = e;
    if (!e.point) {
        // s runs with the edge's chainage on the element's road: move it in by what was cut.
        out.s_start = e.s_start + (a - c0);
        out.s_end = e.s_end - (c1 - b);
        out.lonlat = cut_line(e.lonlat, (a - c0) / (c1 - c0), (b - c0) / (c1 - c0));
    }
    out.chainage_start = std::min(chainage(a), chainage(b));
    out.chainage_end = std::max(chainage(a), chainage(b));
    out.reversed = e.reversed != p.reversed; // s now falls as the route's chainage grows
    return out;
}

bool names_any(const std::vector<std::string>& ids, const std::set<std::string>& known) {
    return std::any_of(ids.begin(), ids.end(), [&](const std::string& id) { return known.contains(id); });
}

} // namespace

Route find_route(const geometry::TrackGraph& graph, const geometry::FittedNetwork& fitted,
                 const geometry::Attachment& attachment, const std::vector<ingest::Feature>& features,
                 const std::string& from, const std::string& to) {
    Route route;
    const auto starts = stations_named(attachment, features, from, route.from);
    const auto ends = stations_named(attachment, features, to, route.to);
    const Network network = build_network(graph, fitted);
    Path best;
    for (const auto* a : starts) {
        for (const auto* b : ends) {
            Path p = shortest_path(network, {a->edge, a->s}, {b->edge, b->s});
            if (p.length < best.length) {
                best = std::move(p);
            }
        }
    }
    if (best.length == infinity) {
        throw InputError("", "no route from station '" + route.from + "' to station '" + route.to +
                                 "': no path over the track graph joins them (through routes and switch movements only)");
    }
    route.length_m = best.length;
    route.pieces = std::move(best.pieces);
    route.osm_ways = route_way_ids(graph, route.pieces);
    return route;
}

OddProfile along_route(const OddProfile& profile, const Route& route, const Taxonomy& taxonomy) {
    OddProfile out = profile;
    out.elements.clear();
    for (const auto& piece : route.pieces) {
        for (const auto& e : profile.elements) {
            if (auto part = on_piece(e, piece)) {
                out.elements.push_back(std::move(*part));
            }
        }
    }
    std::stable_sort(out.elements.begin(), out.elements.end(), [](const TaggedElement& a, const TaggedElement& b) {
        return std::tie(a.chainage_start, a.element, a.chainage_end) <
               std::tie(b.chainage_start, b.element, b.chainage_end);
    });
    // Unparsed values stay when they belong to the route: a way of an edge on
    // it, or an object behind a kept element.
    std::set<std::string> ids(route.osm_ways.begin(), route.osm_ways.end());
    for (const auto& e : out.elements) {
        ids.insert(e.osm_ids.begin(), e.osm_ids.end());
    }
    std::erase_if(out.unparsed, [&](const Unparsed& u) { return !names_any(u.osm_ids, ids); });
    out.route = route.description.empty() ? route.from + " -> " + route.to : route.description;
    out.length_m = route.length_m;
    out.tracks = route.pieces.size();
    out.along_route = true;
    out.track_ends.clear(); // chainage is the route's: one line
    out.summary = summarize(out, &taxonomy);
    return out;
}

nlohmann::ordered_json route_report(const Route& route) {
    nlohmann::ordered_json pieces = nlohmann::ordered_json::array();
    for (const auto& p : route.pieces) {
        pieces.push_back({{"edge", p.edge},
                          {"reversed", p.reversed},
                          {"s_from", p.s_from},
                          {"s_to", p.s_to},
                          {"chainage_start", p.chainage_start}});
    }
    nlohmann::ordered_json j{{"from", route.from}, {"to", route.to}, {"length_m", route.length_m}};
    if (route.relation != 0) {
        nlohmann::ordered_json gaps = nlohmann::ordered_json::array();
        for (const auto& g : route.gaps) {
            gaps.push_back({{"chainage", g.chainage},
                            {"after_way", g.after_way},
                            {"before_way", g.before_way},
                            {"distance_m", g.distance_m},
                            {"bridged", g.bridged},
                            {"bridge_length_m", g.bridge_length_m}});
        }
        j["relation"] = route.relation;
        j["name"] = route.name;
        j["member_ways"] = route.member_ways;
        j["ways_on_route"] = route.ways_on_route;
        j["gaps"] = std::move(gaps);
    }
    j["pieces"] = std::move(pieces);
    return j;
}

} // namespace railodd::odd
