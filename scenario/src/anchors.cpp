// Anchors come from the ODD profile rather than from the map: the profile
// already says, with chainage and OSM ids, where each element lies, so a
// scenario's place is traceable to the same data the route's ODD is.
#include "railodd/scenario/anchors.hpp"

#include <algorithm>
#include <cmath>

namespace railodd::scenario {

namespace {

constexpr const char* horizontal = "Scenery/Track geometry/Horizontal/";
constexpr const char* speed_limit = "Operational Conditions/Speed/Speed limit";
constexpr double min_overrun_m = 20.0; // past the anchor: the stop trigger's 5 m and a step of a fast train, with room
constexpr double eps = 1e-6;

bool under(const std::string& path, const std::string& element) {
    return path == element || (path.size() > element.size() && path.compare(0, element.size(), element) == 0 &&
                               path[element.size()] == '/');
}

bool holds(const odd::AttributeValue& v, const AttributeCondition& c) {
    if (const double* x = std::get_if<double>(&v)) {
        if (!c.values.empty()) {
            return false;
        }
        return (!c.min || *x >= *c.min) && (!c.max || *x <= *c.max);
    }
    const std::string text = std::holds_alternative<bool>(v) ? (std::get<bool>(v) ? "true" : "false")
                                                             : std::get<std::string>(v);
    return !c.min && !c.max && std::find(c.values.begin(), c.values.end(), text) != c.values.end();
}

double anchor_point(const odd::TaggedElement& e, AnchorAt at) {
    switch (at) {
    case AnchorAt::start: return e.chainage_start;
    case AnchorAt::middle: return 0.5 * (e.chainage_start + e.chainage_end);
    case AnchorAt::end: return e.chainage_end;
    }
    return e.chainage_start;
}

// The context element nearest before the anchor within reach; none if there is none.
using LineElements = std::map<std::size_t, std::vector<std::size_t>>;

std::optional<std::size_t> context_before(const odd::OddProfile& p, const std::vector<std::size_t>& on_line,
                                          double chainage, const ContextRequirement& c) {
    std::optional<std::size_t> best;
    for (const std::size_t i : on_line) {
        const auto& e = p.elements[i];
        if (e.chainage_end > chainage + eps || e.chainage_end < chainage - c.within_m || !matches(e, c)) {
            continue;
        }
        if (!best || e.chainage_end > p.elements[*best].chainage_end) {
            best = i;
        }
    }
    return best;
}

double limit_at(const odd::OddProfile& p, const std::vector<std::size_t>& on_line, double chainage) {
    for (const std::size_t i : on_line) {
        const auto& e = p.elements[i];
        if (e.element == speed_limit && e.chainage_start <= chainage + eps &&
            e.chainage_end >= chainage - eps) {
            if (const auto* v = e.find("maxspeed"); v && std::holds_alternative<double>(*v)) {
                return std::get<double>(*v);
            }
        }
    }
    return std::numeric_limits<double>::quiet_NaN();
}

// The run-up a template's timed hazards need: the train's front must start
// further from each conflict point (the anchor, moved along_m) than the
// distance the hazard is timed at.
double hazard_run_up(const Template& t, double ego_half_length_m) {
    double need = 0.0;
    for (const auto& a : t.actors) {
        if (a.move_to && a.hazard_before_m) {
            need = std::max(need, *a.hazard_before_m + ego_half_length_m - a.along_m + 1.0);
        }
    }
    return need;
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

bool matches(const odd::TaggedElement& e, const ElementMatch& match) {
    if (!under(e.element, match.element)) {
        return false;
    }
    for (const auto& c : match.where) {
        const auto* v = e.find(c.attribute);
        if (!v || !holds(*v, c)) {
            return false;
        }
    }
    return true;
}

Anchoring find_anchors(const odd::OddProfile& profile, const LineIndex& lines, const Template& t,
                       double ego_half_length_m) {
    Anchoring out;
    LineElements by_line;
    for (std::size_t i = 0; i < profile.elements.size(); ++i) {
        by_line[lines.line_of(profile.elements[i])].push_back(i);
    }
    for (std::size_t i = 0; i < profile.elements.size(); ++i) {
        const auto& e = profile.elements[i];
        if (!matches(e, t.anchor)) {
            continue;
        }
        const auto& on_line = by_line[lines.line_of(e)];
        Anchor a;
        a.element = i;
        a.line = lines.line_of(e);
        a.chainage = anchor_point(e, t.anchor.at);
        bool complete = true;
        for (const auto& c : t.context) {
            const auto found = context_before(profile, on_line, a.chainage, c);
            complete = complete && found.has_value();
            a.context.push_back(found.value_or(0));
        }
        if (!complete) {
            continue; // not a place for this template; only places that match are reported
        }
        const auto place = lines.at(a.line, a.chainage);
        const double run_up = a.chainage - lines.start(a.line);
        if (!place) {
            out.skipped.push_back({i, "no track geometry at chainage " + std::to_string(a.chainage)});
            continue;
        }
        if (run_up < t.ego.min_run_up_m) {
            out.skipped.push_back({i, "only " + std::to_string(static_cast<long>(run_up)) +
                                          " m of track before the anchor, the template needs " +
                                          std::to_string(static_cast<long>(t.ego.min_run_up_m)) + " m"});
            continue;
        }
        if (const double need = hazard_run_up(t, ego_half_length_m); run_up < need) {
            out.skipped.push_back({i, "only " + std::to_string(static_cast<long>(run_up)) +
                                          " m of track before the anchor, the hazard's timing (hazard_before_m) needs " +
                                          std::to_string(static_cast<long>(std::ceil(need))) + " m"});
            continue;
        }
        // The train must pass the anchor (and every actor placed after it)
        // before its run ends: the stop trigger fires a few metres short of
        // the end.
        double past = min_overrun_m;
        for (const auto& actor : t.actors) {
            past = std::max(past, actor.along_m + min_overrun_m);
        }
        if (lines.end(a.line) - a.chainage < past) {
            out.skipped.push_back({i, "only " + std::to_string(static_cast<long>(lines.end(a.line) - a.chainage)) +
                                          " m of track after the anchor, the train needs " +
                                          std::to_string(static_cast<long>(past)) + " m to run past it"});
            continue;
        }
        a.place = *place;
        a.start_chainage = std::max(lines.start(a.line), a.chainage - t.ego.run_up_m);
        a.end_chainage = std::min(lines.end(a.line), a.chainage + t.ego.overrun_m);
        a.speed_limit_kmh = limit_at(profile, on_line, a.chainage);
        out.anchors.push_back(std::move(a));
    }
    std::stable_sort(out.anchors.begin(), out.anchors.end(), [](const Anchor& x, const Anchor& y) {
        return x.line != y.line ? x.line < y.line : x.chainage < y.chainage;
    });
    return out;
}

} // namespace railodd::scenario
