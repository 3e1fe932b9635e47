// Fitting the track graph chain by chain, through routes before the branches
// that leave them, so every branch can start with the exact pose of its switch.
#include "railodd/geometry/indexed_alignment.hpp"
#include "railodd/geometry/track_fit.hpp"
#include "chain_fit.hpp"
#include "tie_splice.hpp"

#include <algorithm>
#include <cmath>
#include <map>
#include <numbers>
#include <optional>

namespace railodd::geometry {

namespace {

struct ChainGeometry {
    std::vector<Point> points;
    std::vector<std::size_t> joints; // index in points of each interior joint vertex
};

ChainGeometry chain_points(const TrackGraph& g, const Chain& c) {
    ChainGeometry cg;
    for (std::size_t i = 0; i < c.items.size(); ++i) {
        const auto& nodes = g.edges[c.items[i].edge].nodes;
        const std::size_t n = nodes.size();
        for (std::size_t k = 0; k < n; ++k) {
            const auto& node = nodes[c.items[i].reversed ? n - 1 - k : k];
            if (k == 0 && i > 0) {
                cg.joints.push_back(cg.points.size() - 1); // shared with the previous edge's last node
                continue;
            }
            cg.points.push_back({node.xy.x, node.xy.y});
        }
    }
    return cg;
}

std::size_t distinct_points(const std::vector<Point>& p) {
    std::size_t n = p.empty() ? 0 : 1;
    for (std::size_t i = 1; i < p.size(); ++i) {
        n += std::hypot(p[i].x - p[0].x, p[i].y - p[0].y) > 1e-6 ? 1 : 0;
    }
    return std::min<std::size_t>(n, 2);
}

double chain_length(const ChainGeometry& cg) {
    double l = 0.0;
    for (std::size_t i = 1; i < cg.points.size(); ++i) {
        l += std::hypot(cg.points[i].x - cg.points[i - 1].x, cg.points[i].y - cg.points[i - 1].y);
    }
    return l;
}

struct FittedChain {
    bool done = false;
    Alignment alignment;
    std::vector<double> joint_s; // arc length of each interior joint
    std::map<std::size_t, double> vertex_s; // interior joint vertex -> arc length
};

class NetworkFitter {
public:
    NetworkFitter(const TrackGraph& g, const FitOptions& o) : g_(g), o_(o), chains_(build_chains(g)) {
        fitted_.resize(chains_.size());
        geometry_.reserve(chains_.size());
        for (std::size_t c = 0; c < chains_.size(); ++c) {
            geometry_.push_back(chain_points(g_, chains_[c]));
            const Chain& ch = chains_[c];
            for (std::size_t i = 1; i < ch.items.size(); ++i) {
                const GraphEdge& e = g_.edges[ch.items[i].edge];
                through_[ch.items[i].reversed ? e.to : e.from] = c;
            }
        }
    }

    FittedNetwork run() {
        std::vector<std::size_t> order(chains_.size());
        for (std::size_t i = 0; i < order.size(); ++i) {
            order[i] = i;
        }
        std::vector<double> len(chains_.size());
        for (std::size_t c = 0; c < chains_.size(); ++c) {
            len[c] = chain_length(geometry_[c]);
        }
        std::stable_sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return len[a] > len[b]; });
        for (std::size_t c : order) {
            fit_chain(c);
        }
        tie_cycles();
        return collect();
    }

private:
    // The pose a branch end at vertex v must take: the through chain's pose
    // there, turned round when the branch leaves the other way.
    std::optional<Pose> tie(std::size_t c, std::size_t v, bool at_start, ChainEnd& end) {
        const auto it = through_.find(v);
        if (it == through_.end() || it->second == c) {
            return std::nullopt;
        }
        const std::size_t t = it->second;
        if (!fitted_[t].done) {
            if (in_progress_[t]) {
                ++untied_;
                cycle_ends_.push_back({c, v, at_start});
                return std::nullopt; // a cycle of branches: free for now, see tie_cycles()
            }
            fit_chain(t);
        }
        end.tied = true;
        end.to_chain = t;
        return branch_pose(c, v, at_start, t);
    }

    // The through chain t's pose at v, turned round when the branch c leaves
    // the other way.
    Pose branch_pose(std::size_t c, std::size_t v, bool at_start, std::size_t t) const {
        const Pose through = evaluate(fitted_[t].alignment, fitted_[t].vertex_s.at(v));
        const ChainGeometry& cg = geometry_[c];
        // The direction the branch runs at v, in its own chain's order.
        const Point a = at_start ? cg.points.front() : cg.points[cg.points.size() - 2];
        const Point b = at_start ? cg.points[1] : cg.points.back();
        const double dir = std::atan2(b.y - a.y, b.x - a.x);
        Pose p = through;
        if (std::cos(dir - through.hdg) < 0) {
            p.hdg += std::numbers::pi;
            p.curvature = -p.curvature;
        }
        return p;
    }

    // Branches in a cycle (each tied to a chain that is tied back to it) were
    // fitted with one end free. Once every chain is fitted, that end's last
    // stretch is spliced onto its switch's pose, unless a joint of the chain
    // (where an edge ends or another branch is tied) lies in the stretch:
    // moving it would break those links instead.
    void tie_cycles() {
        constexpr double tail_m = 40.0;  // as chain_fit's splices
        constexpr double margin_m = 5.0;
        for (const CycleEnd& ce : cycle_ends_) {
            FittedChain& f = fitted_[ce.chain];
            const std::size_t t = through_.at(ce.vertex);
            const double len = length(f.alignment);
            const auto in_tail = [&](double s) { return ce.at_start ? s < tail_m + margin_m : s > len - tail_m - margin_m; };
            if (!fitted_[t].done || len < 2.0 * (tail_m + margin_m) ||
                std::any_of(f.joint_s.begin(), f.joint_s.end(), in_tail)) {
                continue;
            }
            const Pose p = branch_pose(ce.chain, ce.vertex, ce.at_start, t);
            const std::vector<Point>& pts = geometry_[ce.chain].points;
            const CornerFitOptions corners{1000.0, 0.25};
            Alignment a = ce.at_start ? splice_start(f.alignment, pts, p, tail_m, corners)
                                      : splice_end(f.alignment, pts, p, tail_m, corners);
            if (ce.at_start) {
                // Only the head changed: everything after it moved by the length difference.
                const double delta = length(a) - len;
                for (double& s : f.joint_s) {
                    s += delta;
                }
                for (auto& [v, s] : f.vertex_s) {
                    s += delta;
                }
            }
            f.alignment = std::move(a);
            ChainEnd& end = ce.at_start ? chains_[ce.chain].start : chains_[ce.chain].end;
            end.tied = true;
            end.to_chain = t;
            --untied_;
            ++spliced_;
        }
    }

    void fit_chain(std::size_t c) {
        if (fitted_[c].done || in_progress_[c]) {
            return;
        }
        in_progress_[c] = true;
        Chain& ch = chains_[c];
        const std::optional<Pose> start = tie(c, ch.start.vertex, true, ch.start);
        const std::optional<Pose> end = tie(c, ch.end.vertex, false, ch.end);
        const ChainGeometry& cg = geometry_[c];
        Alignment a;
        if (distinct_points(cg.points) < 2) {
            // All nodes at one spot (a way drawn onto itself): a zero-length line
            // keeps the edge, its ids and its links in the output.
            a.start = start.value_or(Pose{cg.points.front().x, cg.points.front().y, 0.0, 0.0});
            a.primitives.push_back(make_line(0.0));
            ++degenerate_;
        } else {
            ChainFit fit = fit_chain_points(cg.points, start, end, o_);
            if (fit.method == ChainMethod::corners) {
                fallback_.push_back(c);
            }
            spliced_ += fit.spliced_ends;
            a = std::move(fit.alignment);
        }
        FittedChain& f = fitted_[c];
        const IndexedAlignment ia(a, 2.0);
        // Joints are searched near where the mapped polyline puts them: a
        // chain that loops back past itself must not hand a joint to the
        // wrong pass.
        std::vector<double> t(cg.points.size(), 0.0);
        for (std::size_t i = 1; i < t.size(); ++i) {
            t[i] = t[i - 1] + std::hypot(cg.points[i].x - cg.points[i - 1].x, cg.points[i].y - cg.points[i - 1].y);
        }
        const double scale = t.back() > 0 ? ia.length() / t.back() : 1.0;
        double prev = 0.0;
        for (std::size_t j = 0; j < cg.joints.size(); ++j) {
            const Point& q = cg.points[cg.joints[j]];
            const double expected = t[cg.joints[j]] * scale;
            const double s = std::max(prev, ia.project_within(q.x, q.y, expected - 100.0, expected + 100.0).s);
            f.joint_s.push_back(s);
            const GraphEdge& e = g_.edges[ch.items[j + 1].edge];
            f.vertex_s[ch.items[j + 1].reversed ? e.to : e.from] = s;
            prev = s;
        }
        f.alignment = std::move(a);
        f.done = true;
        in_progress_[c] = false;
    }

    FittedNetwork collect() {
        FittedNetwork net;
        net.edges.resize(g_.edges.size());
        for (std::size_t c = 0; c < chains_.size(); ++c) {
            const std::vector<Alignment> parts = split_alignment(fitted_[c].alignment, fitted_[c].joint_s);
            for (std::size_t i = 0; i < chains_[c].items.size(); ++i) {
                const ChainItem& item = chains_[c].items[i];
                FittedEdge& fe = net.edges[item.edge];
                fe.edge = item.edge;
                fe.chain = c;
                fe.reversed = item.reversed;
                fe.alignment = parts[i];
                std::vector<Point> pts;
                for (const auto& n : g_.edges[item.edge].nodes) {
                    pts.push_back({n.xy.x, n.xy.y});
                }
                fe.quality = measure_fit(fe.alignment, pts);
            }
            report_links(c, net);
        }
        net.chains = chains_;
        net.untied_branch_ends = untied_;
        net.degenerate_chains = degenerate_;
        net.corner_chains = fallback_;
        net.spliced_ends = spliced_;
        return net;
    }

    void report_links(std::size_t c, FittedNetwork& net) {
        const Chain& ch = chains_[c];
        const Alignment& a = fitted_[c].alignment;
        auto report = [&](const ChainEnd& e, const Pose& own, bool at_start) {
            if (!e.tied) {
                return;
            }
            Pose other = evaluate(fitted_[e.to_chain].alignment, fitted_[e.to_chain].vertex_s.at(e.vertex));
            const double turn = std::remainder(own.hdg - other.hdg, 2 * std::numbers::pi);
            const bool flipped = std::abs(turn) > std::numbers::pi / 2;
            const double dh = flipped ? std::remainder(turn - std::numbers::pi, 2 * std::numbers::pi) : turn;
            const double dk = flipped ? own.curvature + other.curvature : own.curvature - other.curvature;
            net.branch_links.push_back({e.vertex, c, e.to_chain, at_start ? "branch_start" : "branch_end",
                                        std::hypot(own.x - other.x, own.y - other.y), std::abs(dh), std::abs(dk)});
        };
        report(ch.start, evaluate(a, 0.0), true);
        report(ch.end, evaluate(a, length(a)), false);
    }

    const TrackGraph& g_;
    const FitOptions& o_;
    std::vector<Chain> chains_;
    std::vector<ChainGeometry> geometry_;
    std::vector<FittedChain> fitted_;
    std::map<std::size_t, std::size_t> through_; // interior joint vertex -> chain passing through
    std::map<std::size_t, bool> in_progress_;
    std::size_t untied_ = 0;
    std::size_t degenerate_ = 0;
    std::vector<std::size_t> fallback_;
    std::size_t spliced_ = 0;
    struct CycleEnd {
        std::size_t chain;
        std::size_t vertex;
        bool at_start;
    };
    std::vector<CycleEnd> cycle_ends_;
};

} // namespace

FittedNetwork fit_track_graph(const TrackGraph& graph, const FitOptions& options) {
    return NetworkFitter(graph, options).run();
}

} // namespace railodd::geometry
