// Criticality of a played scenario, from the recorded trajectories: how
// close each actor came to the train, when it entered the train's clearance
// and the time to collision then, the train's stopping distance at its speed
// and the sight distance to the hazard along the track, limited by the
// curve (and fog). A rail figure: a train cannot steer round, it can only
// stop within what it sees.
#include "play_geometry.hpp"

#include <algorithm>
#include <cmath>

namespace railodd::scenario::play {

namespace {

using json = nlohmann::json;

const Sample* at_time(const std::vector<Sample>& v, double t) {
    const auto it = std::lower_bound(v.begin(), v.end(), t - 1e-6, [](const Sample& s, double x) { return s.t < x; });
    return it != v.end() && std::abs(it->t - t) < 1e-6 ? &*it : nullptr;
}

Box box_of(const Sample& s, double length, double width) { return {s.x, s.y, s.h, length, width}; }

// The visual range of the run's fog (or dust, smoke) where a perturbation sets one.
std::optional<double> visibility(const json& sc) {
    for (const auto& p : sc.value("perturbations", json::array())) {
        if (p.value("attribute", "") == "visibility") {
            try {
                return std::stod(p.at("value").get<std::string>());
            } catch (const std::exception&) {
                return std::nullopt;
            }
        }
    }
    return std::nullopt;
}

// When the actor comes to its final place (within 0.3 m of it, after it
// last stood elsewhere), and how far short of it the ego's front is then.
void arrival(const std::vector<Sample>& v, const std::vector<Sample>& ego, const Path& path, double ego_length,
             ActorFigures& f) {
    const Sample& last = v.back();
    std::size_t i = v.size();
    while (i > 0 && std::hypot(v[i - 1].x - last.x, v[i - 1].y - last.y) <= 0.3) {
        --i;
    }
    if (i == 0) {
        return; // never away from its final place: it did not move
    }
    const Sample& at = v[i];
    const Sample* e = at_time(ego, at.t);
    if (!e) {
        return;
    }
    f.arrival_s = at.t;
    f.distance_at_arrival_m =
        path.project(at.x, at.y).chainage - (path.project(e->x, e->y).chainage + ego_length / 2.0);
}

ActorFigures figures(const json& actor, const std::vector<Sample>& ego, const std::vector<Sample>& v,
                     const Path& path, const json& sc, const Options& o) {
    ActorFigures f;
    f.name = actor.at("name");
    const double el = sc.at("ego").at("length_m"), ew = sc.at("ego").at("width_m");
    const double al = actor.at("length_m"), aw = actor.at("width_m");
    f.min_distance_m = std::numeric_limits<double>::infinity();
    const double reach = ew / 2.0 + o.clearance_margin_m + aw / 2.0;
    for (const Sample& s : v) {
        const Sample* e = at_time(ego, s.t);
        if (!e) {
            continue;
        }
        f.min_distance_m = std::min(f.min_distance_m, box_distance(box_of(*e, el, ew), box_of(s, al, aw)));
        if (f.onset_s || path.empty()) {
            continue;
        }
        const Path::Foot foot = path.project(s.x, s.y);
        if (foot.distance < reach && foot.chainage > 0.0 && foot.chainage < path.length()) {
            f.onset_s = s.t;
            f.distance_at_onset_m = foot.chainage - (path.project(e->x, e->y).chainage + el / 2.0);
            if (e->speed > 0.1) {
                f.ttc_at_onset_s = *f.distance_at_onset_m / e->speed;
            }
        }
    }
    if (actor.contains("target") && !path.empty()) {
        arrival(v, ego, path, el, f);
    }
    return f;
}

} // namespace

Criticality criticality(const json& sc, const Trajectories& tr, const Path& path, const Options& o) {
    Criticality c;
    const auto ego_it = tr.find("Ego");
    if (ego_it == tr.end() || ego_it->second.empty()) {
        return c;
    }
    const auto& ego = ego_it->second;
    for (const Sample& s : ego) {
        c.ego_speed_mps = std::max(c.ego_speed_mps, s.speed);
    }
    const double decel = sc.at("ego").value("max_deceleration", 0.0);
    c.stopping_distance_m = c.ego_speed_mps * o.reaction_time_s +
                            (decel > 0.0 ? c.ego_speed_mps * c.ego_speed_mps / (2.0 * decel)
                                         : std::numeric_limits<double>::infinity());
    // The hazard: where the first actor that enters the track ends up, else
    // where the first actor stands.
    const json* hazard = nullptr;
    for (const auto& a : sc.at("actors")) {
        if (!hazard || (a.value("move_to", "") == "on_track" && hazard->value("move_to", "") != "on_track")) {
            hazard = &a;
        }
    }
    for (const auto& a : sc.at("actors")) {
        if (const auto it = tr.find(a.at("name")); it != tr.end() && !it->second.empty()) {
            c.actors.push_back(figures(a, ego, it->second, path, sc, o));
        }
    }
    const auto h = hazard ? tr.find(hazard->at("name")) : tr.end();
    if (h == tr.end() || h->second.empty() || path.empty()) {
        c.sight_limited_by = "no hazard recorded";
        return c;
    }
    const Path::Foot at = path.project(h->second.back().x, h->second.back().y);
    bool curve = false;
    c.sight_distance_m = path.sight_back(at.chainage, o.sight_corridor_m, curve);
    c.sight_limited_by = curve ? "curve" : "recorded run-up";
    if (const auto fog = visibility(sc); fog && *fog < c.sight_distance_m) {
        c.sight_distance_m = *fog;
        c.sight_limited_by = "fog";
    }
    c.can_stop = c.stopping_distance_m < c.sight_distance_m;
    return c;
}

} // namespace railodd::scenario::play
