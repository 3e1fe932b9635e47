// The profile's elements in table form: one row per element with its kind,
// road and attribute values by position, OSM id lists interned. On a
// national network (170k elements) this is the page's largest part, so no
// key is repeated per row.
#include "parts.hpp"

#include <algorithm>
#include <map>
#include <variant>

namespace railodd::report::detail {

namespace {

struct Kind {
    std::string id;
    std::string path;
    bool point = true;
    std::vector<std::string> attrs;
    std::size_t index = 0;
};

double dm(double v) { return std::round(v * 10.0) / 10.0; }

void write_value(JsonText& out, const odd::AttributeValue* v) {
    if (!v) {
        out.value(nullptr);
    } else if (const auto* d = std::get_if<double>(v)) {
        out.number(std::round(*d * 1e4) / 1e4);
    } else if (const auto* s = std::get_if<std::string>(v)) {
        out.string(*s);
    } else {
        out.boolean(std::get<bool>(*v));
    }
}

std::string joined(const std::vector<std::string>& ids) {
    std::string out;
    for (const auto& id : ids) {
        out += (out.empty() ? "" : ",") + id;
    }
    return out;
}

// Kinds in order of first appearance, each with the union of its attribute
// names (in order of first appearance).
std::vector<Kind> collect_kinds(const odd::OddProfile& profile, std::map<std::string, std::size_t>& by_id) {
    std::vector<Kind> kinds;
    for (const auto& e : profile.elements) {
        auto [it, fresh] = by_id.emplace(e.element_id, kinds.size());
        if (fresh) {
            kinds.push_back({e.element_id, e.element, true, {}, kinds.size()});
        }
        Kind& k = kinds[it->second];
        k.point = k.point && e.point;
        for (const auto& a : e.attributes) {
            if (std::find(k.attrs.begin(), k.attrs.end(), a.name) == k.attrs.end()) {
                k.attrs.push_back(a.name);
            }
        }
    }
    return kinds;
}

// A track's pieces: per road, the s and chainage ranges its stretch elements
// span, in chainage order.
struct Piece {
    long road = -1;
    double s0 = 1e300, s1 = -1e300, ch0 = 1e300, ch1 = -1e300;
    bool reversed = false;
};

ojson tracks_json(const odd::OddProfile& profile, const RoadData& roads) {
    std::vector<std::map<std::string, Piece>> pieces(profile.tracks);
    // Along a route chainage is the route's, not each track's own: a track
    // starts where the one before it ends.
    std::vector<double> start(profile.tracks, profile.along_route ? 1e300 : 0.0), end(profile.tracks, 0.0);
    for (const auto& e : profile.elements) {
        if (e.track >= profile.tracks) {
            continue;
        }
        start[e.track] = std::min(start[e.track], e.chainage_start);
        end[e.track] = std::max(end[e.track], e.chainage_end);
        if (e.point) {
            continue;
        }
        Piece& p = pieces[e.track][e.road_id];
        p.road = roads.index_of(e.road_id);
        p.s0 = std::min(p.s0, std::min(e.s_start, e.s_end));
        p.s1 = std::max(p.s1, std::max(e.s_start, e.s_end));
        p.ch0 = std::min(p.ch0, e.chainage_start);
        p.ch1 = std::max(p.ch1, e.chainage_end);
        p.reversed = p.reversed || e.reversed;
    }
    Array tracks;
    for (std::size_t t = 0; t < profile.tracks; ++t) {
        std::vector<Piece> list;
        for (auto& [id, p] : pieces[t]) {
            if (p.road >= 0) {
                list.push_back(p);
            }
        }
        std::sort(list.begin(), list.end(), [](const Piece& a, const Piece& b) { return a.ch0 < b.ch0; });
        ojson rows = ojson::array();
        for (const auto& p : list) {
            rows.push_back({p.road, cm(p.s0), cm(p.s1), cm(p.ch0), cm(p.ch1), p.reversed ? 1 : 0});
        }
        const double from = start[t] > end[t] ? end[t] : start[t];
        tracks.push_back({{"start", cm(from)}, {"length", cm(end[t] - from)}, {"pieces", std::move(rows)}});
    }
    return ojson(std::move(tracks));
}

} // namespace

void write_profile(JsonText& out, const odd::OddProfile& profile, const RoadData& roads, ojson& tracks_out) {
    std::map<std::string, std::size_t> kind_of;
    const std::vector<Kind> kinds = collect_kinds(profile, kind_of);
    out.key("kinds").open('[');
    for (const auto& k : kinds) {
        out.value({{"id", k.id}, {"path", k.path}, {"point", k.point}, {"attrs", k.attrs}});
    }
    out.close(']');
    std::map<std::string, std::size_t> osm_of;
    out.key("osm").open('[');
    for (const auto& e : profile.elements) {
        const std::string ids = joined(e.osm_ids);
        if (osm_of.emplace(ids, osm_of.size()).second) {
            out.string(ids);
        }
    }
    out.close(']').key("elements").open('[');
    for (const auto& e : profile.elements) {
        const Kind& k = kinds[kind_of.at(e.element_id)];
        // 0.1 m: an element's place is read, not computed with (the table's
        // largest part on a national network).
        out.open('[').integer(static_cast<long long>(k.index)).integer(roads.index_of(e.road_id));
        out.number(dm(e.s_start)).number(dm(e.s_end)).integer(static_cast<long long>(e.track));
        out.number(dm(e.chainage_start)).number(dm(e.chainage_end)).open('[');
        for (const auto& name : k.attrs) {
            write_value(out, e.find(name));
        }
        out.close(']').integer(static_cast<long long>(osm_of.at(joined(e.osm_ids)))).integer(e.reversed ? 1 : 0);
        out.close(']');
    }
    out.close(']');
    tracks_out = tracks_json(profile, roads);
}

} // namespace railodd::report::detail
