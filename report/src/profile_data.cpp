// The profile's elements in table form: one row per element with its kind,
// road and attribute values by position, OSM id lists interned. On a
// national network (170k elements) this is the page's largest part, so no
// key is repeated per row, and the rows are printed as the elements come
// (ProfileSection): convert never holds the network's profile whole.
#include "railodd/report/report.hpp"

#include "parts.hpp"

#include <algorithm>
#include <map>
#include <stdexcept>
#include <unordered_map>
#include <variant>

namespace railodd::report {

using detail::ojson;

namespace {

struct Kind {
    std::string id;
    std::string path;
    bool point = true;
    std::vector<std::string> attrs;
};

// A track's pieces: per road, the s and chainage ranges its stretch elements
// span, in chainage order.
struct Piece {
    long road = -1;
    double s0 = 1e300, s1 = -1e300, ch0 = 1e300, ch1 = -1e300;
    bool reversed = false;
};

// To the decimetre, from the value as the profile file holds it (to the
// millimetre): rounded once from memory, a chainage of 34.3499 m was 34.3
// on the page built in memory and 34.4 on the one built from the files.
double dm(double v) { return std::round(std::round(v * 1000.0) / 100.0) / 10.0; }

void write_value(detail::JsonText& out, const odd::AttributeValue* v) {
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

} // namespace

struct ProfileSection::State {
    std::unordered_map<std::string, long> road_index;
    // Kinds in order of first appearance, each with the union of its
    // attribute names (in order of first appearance).
    std::vector<Kind> kinds;
    std::unordered_map<std::string, std::size_t> kind_of;
    std::vector<std::string> osm; // interned OSM id lists, in order of first appearance
    std::unordered_map<std::string, std::size_t> osm_of;
    std::string rows;
    detail::JsonText rows_out{rows};
    bool closed = false; // rows ends with its bracket
    std::vector<std::map<std::string, Piece>> pieces; // per track
    // Along a route chainage is the route's, not each track's own: a track
    // starts where the one before it ends.
    std::vector<double> start, end;

    Kind& kind(const odd::TaggedElement& e, std::size_t& index) {
        const auto [it, fresh] = kind_of.emplace(e.element_id, kinds.size());
        if (fresh) {
            kinds.push_back({e.element_id, e.element, true, {}});
        }
        index = it->second;
        Kind& k = kinds[index];
        k.point = k.point && e.point;
        for (const auto& a : e.attributes) {
            if (std::find(k.attrs.begin(), k.attrs.end(), a.name) == k.attrs.end()) {
                k.attrs.push_back(a.name);
            }
        }
        return k;
    }

    long road(const std::string& id) const {
        const auto it = road_index.find(id);
        return it == road_index.end() ? -1 : it->second;
    }

    void add_piece(const odd::TaggedElement& e) {
        if (e.track >= pieces.size()) {
            return;
        }
        start[e.track] = std::min(start[e.track], e.chainage_start);
        end[e.track] = std::max(end[e.track], e.chainage_end);
        if (e.point) {
            return;
        }
        Piece& p = pieces[e.track][e.road_id];
        p.road = road(e.road_id);
        p.s0 = std::min(p.s0, std::min(e.s_start, e.s_end));
        p.s1 = std::max(p.s1, std::max(e.s_start, e.s_end));
        p.ch0 = std::min(p.ch0, e.chainage_start);
        p.ch1 = std::max(p.ch1, e.chainage_end);
        p.reversed = p.reversed || e.reversed;
    }

    ojson tracks_json() const {
        detail::Array tracks;
        for (std::size_t t = 0; t < pieces.size(); ++t) {
            std::vector<Piece> list;
            for (const auto& [id, p] : pieces[t]) {
                if (p.road >= 0) {
                    list.push_back(p);
                }
            }
            std::sort(list.begin(), list.end(), [](const Piece& a, const Piece& b) { return a.ch0 < b.ch0; });
            ojson rows_of_track = ojson::array();
            for (const auto& p : list) {
                rows_of_track.push_back(
                    {p.road, detail::cm(p.s0), detail::cm(p.s1), detail::cm(p.ch0), detail::cm(p.ch1), p.reversed ? 1 : 0});
            }
            const double from = start[t] > end[t] ? end[t] : start[t];
            tracks.push_back(
                {{"start", detail::cm(from)}, {"length", detail::cm(end[t] - from)}, {"pieces", std::move(rows_of_track)}});
        }
        return ojson(std::move(tracks));
    }
};

ProfileSection::ProfileSection(const odd::OddProfile& head, const std::vector<std::string>& road_ids)
    : state_(std::make_unique<State>()) {
    State& s = *state_;
    for (std::size_t i = 0; i < road_ids.size(); ++i) {
        s.road_index.emplace(road_ids[i], static_cast<long>(i));
    }
    s.pieces.resize(head.tracks);
    s.start.assign(head.tracks, head.along_route ? 1e300 : 0.0);
    s.end.assign(head.tracks, 0.0);
    s.rows_out.open('[');
}

ProfileSection::~ProfileSection() = default;

void ProfileSection::add(const odd::TaggedElement& e) {
    State& s = *state_;
    if (s.closed) {
        throw std::logic_error("ProfileSection::add after write");
    }
    std::size_t kind = 0;
    const Kind& k = s.kind(e, kind);
    const std::string ids = joined(e.osm_ids);
    const auto [osm, fresh] = s.osm_of.emplace(ids, s.osm.size());
    if (fresh) {
        s.osm.push_back(ids);
    }
    // 0.1 m: an element's place is read, not computed with (the table's
    // largest part on a national network). The values follow the kind's
    // attributes as known so far: later rows of the kind may list more.
    auto& out = s.rows_out;
    out.open('[').integer(static_cast<long long>(kind)).integer(s.road(e.road_id));
    out.number(dm(e.s_start)).number(dm(e.s_end)).integer(static_cast<long long>(e.track));
    out.number(dm(e.chainage_start)).number(dm(e.chainage_end)).open('[');
    for (const auto& name : k.attrs) {
        write_value(out, e.find(name));
    }
    out.close(']').integer(static_cast<long long>(osm->second)).integer(e.reversed ? 1 : 0);
    out.close(']');
    s.add_piece(e);
}

void ProfileSection::write_kinds(detail::JsonText& out) const {
    const State& s = *state_;
    out.key("kinds").open('[');
    for (const auto& k : s.kinds) {
        out.value({{"id", k.id}, {"path", k.path}, {"point", k.point}, {"attrs", k.attrs}});
    }
    out.close(']');
    out.key("osm").open('[');
    for (const auto& ids : s.osm) {
        out.string(ids);
    }
    out.close(']');
}

std::string ProfileSection::take_rows() {
    State& s = *state_;
    if (!s.closed) {
        s.rows_out.close(']');
        s.closed = true;
    }
    return std::move(s.rows);
}

ojson ProfileSection::tracks_json() const { return state_->tracks_json(); }

} // namespace railodd::report
