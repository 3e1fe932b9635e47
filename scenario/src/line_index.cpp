// Chainage to lane positions along one track, run on across its ends. A
// track of a whole network ends at every switch, so a scenario anchored on a
// switch, a short siding or a buffer stop would have no run-up: the line is
// continued through the track ends of the profile (`track_ends`), at each end
// onto the track that continues this one most smoothly (heading change under
// max_turn_rad), as a train would run through the switch. The continuation
// lies at chainages below the track's start and beyond its end, so the
// track's own chainages (and every element on it) keep their values.
#include "railodd/scenario/anchors.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <set>
#include <stdexcept>
#include <string>
#include <tuple>
#include <utility>
#include <variant>

namespace railodd::scenario {

namespace {

constexpr const char* horizontal = "Scenery/Track geometry/Horizontal/";
constexpr double eps = 1e-6;
constexpr double max_extension_m = 2000.0; // beyond the longest run-up and overrun a template asks for
constexpr double max_turn_rad = 0.35;      // ~20 deg: through a switch, never back along the other branch
constexpr std::size_t diverging_base = std::size_t{1} << 40; // diverging lines' numbers, above every track

double turn(double a, double b) {
    const double d = std::remainder(a - b, 2.0 * std::numbers::pi);
    return std::abs(d);
}

// A track entered at `node` heading `heading`: the one to run onto, and
// whether it is run against its chainage.
struct Next {
    std::size_t track = 0;
    bool against = false;
};

std::optional<Next> continuation(const std::vector<odd::TrackEnd>& ends, std::int64_t node, double heading,
                                 bool forward, const std::set<std::size_t>& used) {
    std::optional<Next> best;
    double best_turn = max_turn_rad;
    for (const auto& t : ends) {
        if (used.contains(t.track)) {
            continue;
        }
        // Running forward (beyond the end) a track is entered at its start
        // with its own direction, or at its end against it; backwards (before
        // the start) the other way round.
        for (const bool against : {false, true}) {
            const bool at_from = forward != against;
            if ((at_from ? t.from_node : t.to_node) != node) {
                continue;
            }
            const double h = (at_from ? t.from_heading : t.to_heading) + (against ? std::numbers::pi : 0.0);
            if (const double d = turn(h, heading); d < best_turn - 1e-9) {
                best_turn = d;
                best = Next{t.track, against};
            }
        }
    }
    return best;
}

const odd::TrackEnd* end_of(const std::vector<odd::TrackEnd>& ends, std::size_t track) {
    const auto it = std::find_if(ends.begin(), ends.end(), [&](const odd::TrackEnd& t) { return t.track == track; });
    return it == ends.end() ? nullptr : &*it;
}

// Where a track entered at one end is left (its other end) and the heading of
// travel there: run along its chainage or against it, forward or backwards.
std::pair<std::int64_t, double> exit_of(const odd::TrackEnd& t, bool against, bool forward) {
    const bool at_to = forward != against;
    return {at_to ? t.to_node : t.from_node, (at_to ? t.to_heading : t.from_heading) + (against ? std::numbers::pi : 0.0)};
}

bool trailing(const odd::TaggedElement& e) {
    const auto* d = e.find("direction");
    return d && std::holds_alternative<std::string>(*d) && std::get<std::string>(*d) == "trailing";
}

// The OSM node of a switch element ("node:123"), if it is one.
std::optional<std::int64_t> switch_node(const odd::TaggedElement& e) {
    if (!e.point || e.element.rfind("Scenery/Track layout/Switch", 0) != 0) {
        return std::nullopt;
    }
    for (const auto& id : e.osm_ids) {
        if (id.rfind("node:", 0) == 0) {
            try {
                return std::stoll(id.substr(5));
            } catch (const std::exception&) {
                return std::nullopt;
            }
        }
    }
    return std::nullopt;
}

// A track with an end at `node` other than those taken, entered there and
// run forward: the one turning least from `heading` (within max_turn_rad),
// or without a heading the lowest track number.
std::optional<Next> branch_at(const std::vector<odd::TrackEnd>& ends, std::int64_t node,
                              std::optional<double> heading, const std::set<std::size_t>& taken) {
    std::optional<Next> best;
    double best_turn = max_turn_rad;
    for (const auto& t : ends) {
        if (taken.contains(t.track) || (t.from_node != node && t.to_node != node)) {
            continue;
        }
        const bool against = t.from_node != node;
        const double h = against ? t.to_heading + std::numbers::pi : t.from_heading;
        const double d = heading ? turn(h, *heading) : 0.0;
        if (d < best_turn - 1e-9 || (!heading && !best)) {
            best_turn = heading ? d : best_turn;
            best = Next{t.track, against};
        }
    }
    return best;
}

} // namespace

LineIndex::LineIndex(const odd::OddProfile& profile) : along_route_(profile.along_route) {
    for (const auto& e : profile.elements) {
        if (e.point || e.element.rfind(horizontal, 0) != 0) {
            continue;
        }
        lines_[line_of(e)].push_back({e.chainage_start, e.chainage_end, e.road_id, e.s_start, e.s_end, e.reversed});
    }
    for (auto& [line, pieces] : lines_) {
        std::stable_sort(pieces.begin(), pieces.end(), [](const Piece& a, const Piece& b) { return a.c0 < b.c0; });
    }
    if (along_route_ || profile.track_ends.empty()) {
        return;
    }
    for (std::size_t i = 0; i < profile.elements.size(); ++i) {
        if (auto b = branch_of(profile, i)) {
            branches_.emplace(i, *b);
        }
    }
    std::map<std::size_t, std::vector<Piece>> extended;
    for (const auto& t : profile.track_ends) {
        if (lines_.contains(t.track)) {
            extended[t.track] = extend(profile.track_ends, t);
        }
    }
    // Diverging lines: the run-up of their track's extended line, then the
    // tracks' own pieces. Numbered above every track.
    for (const auto& [i, branch] : branches_) {
        if (!branch.trailing) { // a trailing switch's other track lies behind the train
            diverging_[i] = diverging_base + i;
            extended[diverging_base + i] = diverging_line(profile, i, extended);
        }
    }
    lines_ = std::move(extended);
}

std::optional<std::size_t> LineIndex::diverging(std::size_t switch_element) const {
    const auto it = diverging_.find(switch_element);
    return it == diverging_.end() ? std::nullopt : std::optional<std::size_t>(it->second);
}

// The pieces of track `track`, entered at one end (against its chainage when
// `against`), placed beyond `at` (forward) or before it; returns its length.
double LineIndex::append(std::vector<Piece>& out, std::size_t track, bool against, bool forward, double at) const {
    const double c_start = start(track), c_end = end(track);
    // Distance from the joining end, along the continued line's direction.
    const bool from_start = forward != against;
    for (const Piece& p : lines_.at(track)) {
        const double d0 = from_start ? p.c0 - c_start : c_end - p.c1;
        const double d1 = from_start ? p.c1 - c_start : c_end - p.c0;
        Piece q = p;
        q.reversed = p.reversed != against;
        q.c0 = forward ? at + d0 : at - d1;
        q.c1 = forward ? at + d1 : at - d0;
        out.push_back(q);
    }
    return c_end - c_start;
}

// From `node`, travelling `heading`, onto the smoothest continuing track
// again and again, up to max_extension_m, beyond `at` (forward) or before it.
// Not onto a track that leads back to a node the line passes already
// (`passed`, and those it passes on the way): round a tram's turning loop a
// line came back to the switch it had started from, and esmini, routed
// over one junction twice, took the loop again (Munich: the train never
// reached its anchor).
void LineIndex::run_on(std::vector<Piece>& out, const std::vector<odd::TrackEnd>& ends, std::int64_t node,
                       double heading, bool forward, double at, std::set<std::size_t> used,
                       std::set<std::int64_t> passed) const {
    double added = 0.0;
    passed.insert(node);
    while (added < max_extension_m) {
        const auto next = continuation(ends, node, heading, forward, used);
        if (!next || !lines_.contains(next->track)) {
            break;
        }
        const auto [exit, exit_heading] = exit_of(*end_of(ends, next->track), next->against, forward);
        if (passed.contains(exit)) {
            break;
        }
        used.insert(next->track);
        const double len = append(out, next->track, next->against, forward, at);
        at += forward ? len : -len;
        added += len;
        node = exit;
        heading = exit_heading;
        passed.insert(node);
    }
}

// The pieces of `own` continued before its start and beyond its end.
std::vector<LineIndex::Piece> LineIndex::extend(const std::vector<odd::TrackEnd>& ends,
                                                const odd::TrackEnd& own) const {
    std::vector<Piece> out = lines_.at(own.track);
    run_on(out, ends, own.from_node, own.from_heading, false, start(own.track), {own.track}, {own.to_node});
    run_on(out, ends, own.to_node, own.to_heading, true, end(own.track), {own.track}, {own.from_node});
    std::stable_sort(out.begin(), out.end(), [](const Piece& a, const Piece& b) { return a.c0 < b.c0; });
    return out;
}

// A switch's track up to the switch point, then the track at the switch's
// node that the line does not run on: not the switch's own track, not the
// track the line came from or continues on at that node, and leaving the
// node within max_turn_rad of the line's heading where that is known (at a
// track end). Where several remain (a slip), the lowest track number.
// The switch's other track: at the switch's node, not the switch's own track
// nor the track its line came from or runs on to there, leaving the node
// ahead (facing) or behind (trailing) within max_turn_rad of the line's
// heading where that is known (at a track end); mid-track the other track at
// the node. Where several remain (a slip), the lowest track number.
std::optional<LineIndex::Branch> LineIndex::branch_of(const odd::OddProfile& profile, std::size_t element) const {
    const auto& e = profile.elements[element];
    const auto node = switch_node(e);
    const odd::TrackEnd* own = end_of(profile.track_ends, e.track);
    if (!node || !own || !lines_.contains(e.track)) {
        return std::nullopt;
    }
    const bool behind = trailing(e);
    const double c = e.chainage_start;
    const bool at_start = own->from_node == *node && std::abs(c - start(e.track)) < 1.0;
    const bool at_end = own->to_node == *node && std::abs(c - end(e.track)) < 1.0;
    std::set<std::size_t> taken{e.track};
    std::optional<double> heading;
    if (at_start) {
        heading = own->from_heading;
        if (const auto stem = continuation(profile.track_ends, *node, own->from_heading, false, taken)) {
            taken.insert(stem->track);
        }
    } else if (at_end) {
        heading = own->to_heading;
        if (const auto through = continuation(profile.track_ends, *node, own->to_heading, true, taken)) {
            taken.insert(through->track);
        }
    }
    if (heading && behind) {
        *heading += std::numbers::pi;
    }
    const auto next = branch_at(profile.track_ends, *node, heading, taken);
    if (!next || !lines_.contains(next->track)) {
        return std::nullopt;
    }
    return Branch{next->track, next->against, behind, start(next->track), end(next->track)};
}

std::optional<LanePlacement> LineIndex::branch_place(std::size_t switch_element, double distance) const {
    const auto b = branches_.find(switch_element);
    if (b == branches_.end() || distance > b->second.c_end - b->second.c_start) {
        return std::nullopt;
    }
    const Branch& br = b->second;
    return at(br.track, br.against ? br.c_end - distance : br.c_start + distance);
}

std::vector<LineIndex::Piece> LineIndex::diverging_line(const odd::OddProfile& profile, std::size_t element,
                                                       const std::map<std::size_t, std::vector<Piece>>& extended) const {
    const auto& e = profile.elements[element];
    const Branch& branch = branches_.at(element);
    const double c = e.chainage_start;
    std::vector<Piece> out;
    for (Piece p : extended.at(e.track)) {
        if (p.c0 >= c - eps) {
            continue;
        }
        if (p.c1 > c) { // the piece the switch lies in ends there
            (p.reversed ? p.s0 : p.s1) = p.reversed ? p.s1 - (c - p.c0) : p.s0 + (c - p.c0);
            p.c1 = c;
        }
        out.push_back(p);
    }
    const double len = append(out, branch.track, branch.against, true, c);
    const auto [far, far_heading] = exit_of(*end_of(profile.track_ends, branch.track), branch.against, true);
    run_on(out, profile.track_ends, far, far_heading, true, c + len, {e.track, branch.track}, {*switch_node(e)});
    std::stable_sort(out.begin(), out.end(), [](const Piece& a, const Piece& b) { return a.c0 < b.c0; });
    return out;
}

double LineIndex::start(std::size_t line) const {
    const auto it = lines_.find(line);
    return it == lines_.end() ? 0.0 : it->second.front().c0;
}

double LineIndex::end(std::size_t line) const {
    const auto it = lines_.find(line);
    double c = 0.0;
    if (it != lines_.end()) {
        for (const auto& p : it->second) {
            c = std::max(c, p.c1);
        }
    }
    return c;
}

const LineIndex::Piece* LineIndex::piece(std::size_t line, double chainage) const {
    const auto it = lines_.find(line);
    if (it == lines_.end()) {
        return nullptr;
    }
    const auto& v = it->second;
    auto p = std::upper_bound(v.begin(), v.end(), chainage, [](double c, const Piece& q) { return c < q.c0; });
    if (p == v.begin()) {
        return chainage >= v.front().c0 - eps ? &v.front() : nullptr;
    }
    --p;
    return chainage <= p->c1 + eps ? &*p : nullptr;
}

double LineIndex::road_entry(std::size_t line, double chainage) const {
    const Piece* p = piece(line, chainage);
    if (!p) {
        return chainage;
    }
    const auto& v = lines_.at(line);
    auto i = static_cast<std::size_t>(p - v.data());
    while (i > 0 && v[i - 1].road_id == p->road_id && std::abs(v[i - 1].c1 - v[i].c0) < 1e-3) {
        --i;
    }
    return v[i].c0;
}

std::optional<LanePlacement> LineIndex::at(std::size_t line, double chainage) const {
    const Piece* p = piece(line, chainage);
    if (!p) {
        return std::nullopt;
    }
    // A centimetre inside the piece: at a road's very end the written s can
    // round past the road's length, which players truncate with an error.
    const double len = p->c1 - p->c0, inside = std::min(0.01, 0.5 * len);
    const double d = std::clamp(chainage - p->c0, inside, len - inside);
    LanePlacement out;
    out.road_id = p->road_id;
    out.lane_id = -1; // rail roads carry one rail lane, right of the reference line (docs/xodr.md)
    out.s = p->reversed ? p->s1 - d : p->s0 + d;
    out.reversed = p->reversed;
    return out;
}

std::vector<LanePlacement> LineIndex::waypoints(std::size_t line, double c0, double c1) const {
    std::vector<LanePlacement> out;
    if (auto a = at(line, c0)) {
        out.push_back(*a);
    }
    const auto it = lines_.find(line);
    if (it != lines_.end()) {
        // Runs of one road strictly between the ends: the router needs one point on each.
        std::string road = out.empty() ? "" : out.front().road_id;
        double run0 = c0;
        for (const auto& p : it->second) {
            if (p.c1 <= c0 + eps || p.c0 >= c1 - eps || p.road_id == road) {
                continue;
            }
            run0 = std::max(p.c0, c0);
            double run1 = run0;
            for (const auto& q : it->second) {
                if (q.road_id == p.road_id && q.c0 >= run0 - eps && q.c0 < c1) {
                    run1 = std::max(run1, std::min(q.c1, c1));
                }
            }
            road = p.road_id;
            if (auto w = at(line, 0.5 * (run0 + run1)); w && w->road_id == road) {
                out.push_back(*w);
            }
        }
    }
    if (auto b = at(line, c1)) {
        if (out.empty() || b->road_id != out.back().road_id || std::abs(b->s - out.back().s) > eps) {
            out.push_back(*b);
        }
    }
    return out;
}

} // namespace railodd::scenario
