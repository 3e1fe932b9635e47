// What the chainage charts run along. A profile along one route (--relation,
// --from/--to) is one track. A whole network's profile has a track per graph
// edge, switch to switch: the charts offer every track end to end (so the axis
// is the profile's length) when there are few, and long chains joined where a
// track ends at the node another starts, taking the straightest continuation,
// as a line is read on the ground.
#include "parts.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>
#include <numbers>
#include <numeric>
#include <optional>

namespace railodd::report::detail {

namespace {

constexpr std::size_t end_to_end_max_tracks = 60;
constexpr std::size_t max_chains = 100;
constexpr double max_deflection_rad = 0.35; // 20 degrees: sharper is not a continuation
constexpr double min_chain_m = 500.0;

struct Part {
    std::size_t track;
    bool reversed;
};

double wrap(double a) {
    while (a > std::numbers::pi) a -= 2 * std::numbers::pi;
    while (a <= -std::numbers::pi) a += 2 * std::numbers::pi;
    return a;
}

class ChainBuilder {
public:
    ChainBuilder(const odd::OddProfile& p, const std::vector<double>& length) : length_(length) {
        used_.assign(length.size(), false);
        for (const auto& e : p.track_ends) {
            if (e.track < length.size()) {
                ends_[e.track] = &e;
                at_node_[e.from_node].push_back(e.track);
                at_node_[e.to_node].push_back(e.track);
            }
        }
    }

    // The chain through `seed`: extended forward from its end, then backward
    // from its start (as forward runs of the reversed chain).
    std::vector<Part> chain(std::size_t seed) {
        used_[seed] = true;
        std::vector<Part> fwd{{seed, false}};
        extend(fwd);
        std::vector<Part> back{{seed, true}};
        extend(back);
        std::vector<Part> out;
        for (auto it = back.rbegin(); it != back.rend() - 1; ++it) {
            out.push_back({it->track, !it->reversed});
        }
        out.insert(out.end(), fwd.begin(), fwd.end());
        return out;
    }
    bool used(std::size_t t) const { return used_[t]; }

private:
    // Node and heading of travel where the part is left.
    bool exit_of(const Part& part, std::int64_t& node, double& hdg) const {
        const auto it = ends_.find(part.track);
        if (it == ends_.end()) {
            return false;
        }
        node = part.reversed ? it->second->from_node : it->second->to_node;
        hdg = part.reversed ? wrap(it->second->from_heading + std::numbers::pi) : it->second->to_heading;
        return true;
    }

    void extend(std::vector<Part>& parts) {
        std::int64_t node = 0;
        double hdg = 0.0;
        while (exit_of(parts.back(), node, hdg)) {
            double best = max_deflection_rad;
            std::optional<Part> next;
            for (std::size_t t : at_node_[node]) {
                const auto* e = ends_.at(t);
                for (bool rev : {false, true}) {
                    if (used_[t] || (rev ? e->to_node : e->from_node) != node) {
                        continue;
                    }
                    const double h = rev ? wrap(e->to_heading + std::numbers::pi) : e->from_heading;
                    const double d = std::abs(wrap(h - hdg));
                    if (d < best || (next && d == best && length_[t] > length_[next->track])) {
                        best = d;
                        next = Part{t, rev};
                    }
                }
            }
            if (!next) {
                return;
            }
            used_[next->track] = true;
            parts.push_back(*next);
        }
    }

    const std::vector<double>& length_;
    std::vector<bool> used_;
    std::map<std::size_t, const odd::TrackEnd*> ends_;
    std::map<std::int64_t, std::vector<std::size_t>> at_node_;
};

ojson chain_json(const std::string& label, const std::vector<Part>& parts, const std::vector<double>& length) {
    double total = 0.0;
    ojson list = ojson::array();
    for (const auto& p : parts) {
        total += length[p.track];
        list.push_back({p.track, p.reversed ? 1 : 0});
    }
    return {{"label", label}, {"length", cm(total)}, {"parts", std::move(list)}};
}

ojson with_length(ojson chain, double length) {
    chain["length"] = cm(length);
    return chain;
}

std::string km(double m) {
    char buf[32];
    std::snprintf(buf, sizeof buf, "%.2f km", m / 1000.0);
    return buf;
}

} // namespace

ojson chains_json(const odd::OddProfile& profile, const ojson& tracks) {
    std::vector<double> length;
    for (const auto& t : tracks) {
        length.push_back(t.at("length").get<double>());
    }
    ojson chains = ojson::array();
    std::vector<Part> all;
    for (std::size_t t = 0; t < length.size(); ++t) {
        all.push_back({t, false});
    }
    if (profile.along_route || length.size() <= end_to_end_max_tracks || profile.track_ends.empty()) {
        // Along a route the tracks follow each other on the route's chainage,
        // gaps (missing relation members) included.
        const double total = profile.along_route ? profile.length_m : std::accumulate(length.begin(), length.end(), 0.0);
        chains.push_back(with_length(chain_json(profile.along_route ? "the route, " + km(total)
                                                                    : "all tracks end to end, " + km(total),
                                                all, length),
                                     total));
    }
    if (profile.along_route || profile.track_ends.empty()) {
        return chains;
    }
    std::vector<std::size_t> by_length(length.size());
    std::iota(by_length.begin(), by_length.end(), 0);
    std::stable_sort(by_length.begin(), by_length.end(), [&](auto a, auto b) { return length[a] > length[b]; });
    ChainBuilder builder(profile, length);
    std::vector<std::vector<Part>> found;
    for (std::size_t seed : by_length) {
        if (!builder.used(seed)) {
            found.push_back(builder.chain(seed));
        }
    }
    const auto total = [&](const std::vector<Part>& c) {
        double s = 0.0;
        for (const auto& p : c) s += length[p.track];
        return s;
    };
    std::stable_sort(found.begin(), found.end(), [&](const auto& a, const auto& b) { return total(a) > total(b); });
    for (std::size_t i = 0; i < found.size() && i < max_chains; ++i) {
        const double t = total(found[i]);
        if (t < min_chain_m && !chains.empty()) {
            break;
        }
        chains.push_back(chain_json("chain " + std::to_string(i + 1) + ": " + std::to_string(found[i].size()) +
                                        (found[i].size() == 1 ? " track from track " : " tracks from track ") + std::to_string(found[i].front().track) + ", " + km(t),
                                    found[i], length));
    }
    return chains;
}

} // namespace railodd::report::detail
