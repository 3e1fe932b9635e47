// Fitting the track graph chain by chain, through routes before the branches
// that leave them, so every branch can start with the exact pose of its switch.
#include "railodd/geometry/indexed_alignment.hpp"
#include "railodd/geometry/track_fit.hpp"

#include "chain_orientation.hpp"
#include "chain_fit.hpp"
#include "parallel_chains.hpp"
#include "tie_splice.hpp"

#include <algorithm>
#include <cmath>
#include <condition_variable>
#include <exception>
#include <map>
#include <mutex>
#include <numbers>
#include <optional>
#include <set>
#include <thread>

namespace railodd::geometry {

namespace {

// A joint (switch, diamond crossing, join) within switch_snap_m of a knot of
// its through track's design is taken at the knot: the turnout's curve starts
// at the switch, and the mapped node is no nearer than that to the true
// switch; cut off that close, the element's piece on one side is a sliver no
// design has (VDE 8.2: 45 track elements under a metre, Cologne about 300;
// at crossings and joins Munich 6 of its 9). A crossing's point is read off
// the mapped nodes, not the cut, so the cut may move.
constexpr double switch_snap_m = 1.0;

double at_knot_near(const std::vector<double>& knots, double s) {
    // knots[0] is the chain's start, no knot.
    if (knots.size() < 2) {
        return s;
    }
    const auto it = std::lower_bound(knots.begin() + 1, knots.end(), s);
    double best = s, gap = switch_snap_m;
    for (const auto k : {it, it - 1}) {
        if (k > knots.begin() && k < knots.end() && std::abs(*k - s) < gap) {
            gap = std::abs(*k - s);
            best = *k;
        }
    }
    return best;
}

struct ChainGeometry {
    std::vector<Point> points;
    std::vector<std::size_t> joints; // index in points of each interior joint vertex
    std::vector<std::size_t> held;   // those joints at a switch (fit_alignment.hpp)
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
                const GraphEdge& e = g.edges[c.items[i].edge];
                if (g.vertices[c.items[i].reversed ? e.to : e.from].kind == VertexKind::switch_) {
                    cg.held.push_back(cg.points.size() - 1);
                }
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
        planned_.assign(chains_.size(), 0);
        in_progress_.assign(chains_.size(), 0);
        depends_.resize(chains_.size());
        corner_chain_.assign(chains_.size(), 0);
        beyond_limit_.assign(chains_.size(), 0);
        chain_degenerate_.assign(chains_.size(), 0);
        chain_spliced_.assign(chains_.size(), 0);
        chain_patched_.assign(chains_.size(), 0);
        chain_noise_.assign(chains_.size(), 0.0);
        chain_outliers_.assign(chains_.size(), 0);
        guide_.resize(chains_.size());
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
        // Which end is tied to which chain depends on the graph only: decide
        // all ties first, then fit in parallel, each chain once the chains it
        // is tied to are done. Results do not depend on the thread count.
        for (std::size_t c : order) {
            plan_chain(c);
        }
        plan_guides(order);
        execute();
        for (std::size_t c : completion_) {
            if (corner_chain_[c]) {
                fallback_.push_back(c);
            }
            if (beyond_limit_[c]) {
                beyond_.push_back(c);
            }
            spliced_ += chain_spliced_[c];
            patched_ += chain_patched_[c];
            degenerate_ += chain_degenerate_[c];
        }
        tie_cycles();
        FittedNetwork net = collect();
        const Orientation o = orient_chains(g_, net);
        net.reversed_chains = o.reversed_chains;
        net.reversing_links = o.reversing_links;
        return net;
    }

private:
    // Decides whether the end of chain c at vertex v is tied to the chain
    // passing through v, planning that chain first (depth first, as the
    // sequential fit did) unless it is waiting on c: a cycle of branches,
    // left free for now (see tie_cycles()).
    void plan_tie(std::size_t c, std::size_t v, bool at_start, ChainEnd& end) {
        const auto it = through_.find(v);
        if (it == through_.end() || it->second == c) {
            return;
        }
        const std::size_t t = it->second;
        if (!planned_[t]) {
            if (in_progress_[t]) {
                ++untied_;
                cycle_ends_.push_back({c, v, at_start});
                return;
            }
            plan_chain(t);
        }
        end.tied = true;
        end.to_chain = t;
        depends_[c].push_back(t);
    }

    void plan_chain(std::size_t c) {
        if (planned_[c] || in_progress_[c]) {
            return;
        }
        in_progress_[c] = true;
        Chain& ch = chains_[c];
        plan_tie(c, ch.start.vertex, true, ch.start);
        plan_tie(c, ch.end.vertex, false, ch.end);
        planned_[c] = true;
        in_progress_[c] = false;
        completion_.push_back(c);
    }

    // Parallel tracks: each chain is offered the designs of the longer chains
    // it runs beside (parallel_chains.hpp), which it then waits for, unless
    // such a chain waits on it already.
    void plan_guides(const std::vector<std::size_t>& order) {
        if (!o_.parallel_guides) {
            return;
        }
        std::vector<std::size_t> rank(chains_.size());
        for (std::size_t i = 0; i < order.size(); ++i) {
            rank[order[i]] = i;
        }
        std::vector<std::vector<Point>> points;
        for (const ChainGeometry& cg : geometry_) {
            points.push_back(cg.points);
        }
        const std::vector<std::vector<std::size_t>> guides = parallel_guides(points, rank);
        for (std::size_t c : order) {
            for (const std::size_t g : guides[c]) {
                if (!waits_on(g, c)) {
                    guide_[c].push_back(g);
                    depends_[c].push_back(g);
                } else if (!waits_on(c, g)) {
                    // The longer track waits on this one (through its
                    // ties) already: this one, fitted first, guides it.
                    guide_[g].push_back(c);
                }
            }
        }
    }

    // Does chain a wait, through ties and guides, on chain b?
    bool waits_on(std::size_t a, std::size_t b) const {
        std::vector<std::size_t> stack{a};
        std::vector<char> seen(chains_.size(), 0);
        while (!stack.empty()) {
            const std::size_t x = stack.back();
            stack.pop_back();
            if (x == b) {
                return true;
            }
            if (!seen[x]) {
                seen[x] = 1;
                stack.insert(stack.end(), depends_[x].begin(), depends_[x].end());
            }
        }
        return false;
    }

    std::optional<Pose> tie_pose(std::size_t c, const ChainEnd& end, bool at_start) const {
        if (!end.tied) {
            return std::nullopt;
        }
        return branch_pose(c, end.vertex, at_start, end.to_chain);
    }

    // Runs fit_chain over all chains on the worker threads, a chain as soon
    // as the chains its ends are tied to are fitted; ready chains go in the
    // planned order.
    void execute() {
        const std::size_t n = chains_.size();
        unsigned threads = o_.threads > 0 ? o_.threads : std::max(1u, std::thread::hardware_concurrency());
        threads = static_cast<unsigned>(std::min<std::size_t>(threads, std::max<std::size_t>(1, n)));
        std::vector<std::size_t> rank(n), pending(n, 0);
        std::vector<std::vector<std::size_t>> dependents(n);
        for (std::size_t i = 0; i < completion_.size(); ++i) {
            rank[completion_[i]] = i;
        }
        std::set<std::pair<std::size_t, std::size_t>> ready; // (rank, chain)
        for (std::size_t c = 0; c < n; ++c) {
            for (std::size_t t : depends_[c]) {
                dependents[t].push_back(c);
                ++pending[c];
            }
            if (pending[c] == 0) {
                ready.insert({rank[c], c});
            }
        }
        if (threads <= 1) {
            while (!ready.empty()) {
                const std::size_t c = ready.begin()->second;
                ready.erase(ready.begin());
                fit_chain(c);
                for (std::size_t d : dependents[c]) {
                    if (--pending[d] == 0) {
                        ready.insert({rank[d], d});
                    }
                }
            }
            return;
        }
        std::mutex m;
        std::condition_variable cv;
        std::size_t finished = 0;
        std::exception_ptr error;
        auto worker = [&] {
            std::unique_lock lock(m);
            while (true) {
                cv.wait(lock, [&] { return !ready.empty() || finished == n || error; });
                if (finished == n || error) {
                    return;
                }
                const std::size_t c = ready.begin()->second;
                ready.erase(ready.begin());
                lock.unlock();
                try {
                    fit_chain(c);
                } catch (...) {
                    lock.lock();
                    error = std::current_exception();
                    cv.notify_all();
                    return;
                }
                lock.lock();
                ++finished;
                for (std::size_t d : dependents[c]) {
                    if (--pending[d] == 0) {
                        ready.insert({rank[d], d});
                    }
                }
                cv.notify_all();
            }
        };
        std::vector<std::thread> pool;
        for (unsigned i = 0; i < threads; ++i) {
            pool.emplace_back(worker);
        }
        for (auto& t : pool) {
            t.join();
        }
        if (error) {
            std::rethrow_exception(error);
        }
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
        constexpr double margin_m = 5.0;
        for (const CycleEnd& ce : cycle_ends_) {
            FittedChain& f = fitted_[ce.chain];
            const std::size_t t = through_.at(ce.vertex);
            const double len = length(f.alignment);
            const auto in_tail = [&](double s) {
                return ce.at_start ? s < cycle_tail_m + margin_m : s > len - cycle_tail_m - margin_m;
            };
            if (!fitted_[t].done || len < 2.0 * (cycle_tail_m + margin_m) ||
                std::any_of(f.joint_s.begin(), f.joint_s.end(), in_tail)) {
                continue;
            }
            const Pose p = branch_pose(ce.chain, ce.vertex, ce.at_start, t);
            const std::vector<Point>& pts = geometry_[ce.chain].points;
            const CornerFitOptions corners{1000.0, 0.25};
            constexpr double design_m = 2.0; // as a chain's fit must follow its nodes (chain_fit.cpp)
            Alignment a = ce.at_start ? splice_start(f.alignment, pts, p, cycle_tail_m, corners, design_m)
                                      : splice_end(f.alignment, pts, p, cycle_tail_m, corners, design_m);
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

    // Where chain c's joints lie on its alignment a. Joints are searched near
    // where the mapped polyline puts them: a chain that loops back past
    // itself must not hand a joint to the wrong pass.
    void place_joints(std::size_t c, const Alignment& a) {
        const ChainGeometry& cg = geometry_[c];
        const IndexedAlignment ia(a, 2.0);
        const std::vector<double> t = polyline_chainage(cg.points);
        const double scale = t.back() > 0 ? ia.length() / t.back() : 1.0;
        const std::vector<double> knots = primitive_s(a);
        const auto [snap_from, snap_to] = snap_span(c, t);
        FittedChain& f = fitted_[c];
        double prev = 0.0;
        for (std::size_t j = 0; j < cg.joints.size(); ++j) {
            const Point& q = cg.points[cg.joints[j]];
            const double at = t[cg.joints[j]];
            const GraphEdge& e = g_.edges[chains_[c].items[j + 1].edge];
            const std::size_t v = chains_[c].items[j + 1].reversed ? e.to : e.from;
            double s = std::max(prev, ia.project_within(q.x, q.y, at * scale - 100.0, at * scale + 100.0).s);
            if (at > snap_from && at < snap_to) {
                s = std::max(prev, at_knot_near(knots, s));
            }
            f.joint_s.push_back(s);
            f.vertex_s[v] = s;
            prev = s;
        }
    }

    // The chainage (along the mapped nodes t) within which chain c's joints
    // may be taken at a knot: all of it, but where a cycle end is spliced
    // once all are fitted (tie_cycles), which rebuilds the fit up to the
    // splice's node and a metre past its foot; a joint taken at a knot there
    // could lie on the rebuilt stretch, away from the pose its branch was
    // tied to (Cologne: 19 of its 21 pieces under a metre cut off at a switch).
    std::pair<double, double> snap_span(std::size_t c, const std::vector<double>& t) const {
        constexpr double clear_m = 3.0 * switch_snap_m; // the cut's move, the snap's and the feet's spread
        double from = -1.0, to = t.back() + 1.0;
        for (const CycleEnd& ce : cycle_ends_) {
            if (ce.chain == c && ce.at_start) {
                from = t[splice_start_node(t, cycle_tail_m)] + clear_m;
            } else if (ce.chain == c) {
                to = t[splice_end_node(t, cycle_tail_m)] - clear_m;
            }
        }
        return {from, to};
    }

    // Fits chain c; only reads the chains it is tied to and writes its own
    // slots, so chains run in parallel.
    void fit_chain(std::size_t c) {
        const Chain& ch = chains_[c];
        const std::optional<Pose> start = tie_pose(c, ch.start, true);
        const std::optional<Pose> end = tie_pose(c, ch.end, false);
        const ChainGeometry& cg = geometry_[c];
        Alignment a;
        if (distinct_points(cg.points) < 2) {
            // All nodes at one spot (a way drawn onto itself): a zero-length line
            // keeps the edge, its ids and its links in the output.
            a.start = start.value_or(Pose{cg.points.front().x, cg.points.front().y, 0.0, 0.0});
            a.primitives.push_back(make_line(0.0));
            chain_degenerate_[c] = 1;
        } else {
            std::vector<IndexedAlignment> guides;
            for (const std::size_t g : guide_[c]) {
                guides.emplace_back(fitted_[g].alignment, 2.0);
            }
            ChainFit fit = fit_chain_points(cg.points, start, end, o_, guides, cg.held);
            corner_chain_[c] = fit.method == ChainMethod::corners ? 1 : 0;
            beyond_limit_[c] = fit.beyond_limit ? 1 : 0;
            chain_spliced_[c] = fit.spliced_ends;
            chain_patched_[c] = fit.patched_stretches;
            chain_noise_[c] = fit.noise_sigma_m;
            chain_outliers_[c] = fit.outliers;
            a = std::move(fit.alignment);
        }
        place_joints(c, a);
        FittedChain& f = fitted_[c];
        f.alignment = std::move(a);
        f.done = true;
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
                fe.quality.noise_sigma_m = chain_noise_[c];
            }
            report_links(c, net);
        }
        net.chains = chains_;
        net.untied_branch_ends = untied_;
        net.degenerate_chains = degenerate_;
        net.corner_chains = fallback_;
        net.beyond_limit_chains = beyond_;
        net.spliced_ends = spliced_;
        net.patched_stretches = patched_;
        net.chain_noise_sigma_m = chain_noise_;
        for (const std::size_t k : chain_outliers_) {
            net.outlier_nodes += k;
        }
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
    // Planning: ties decided, and the order the sequential fit finished chains in.
    std::vector<char> planned_;
    std::vector<char> in_progress_;
    std::vector<std::vector<std::size_t>> depends_; // chains each chain's ties read
    std::vector<std::size_t> completion_;
    // Per chain, written by the thread fitting it.
    std::vector<char> corner_chain_;
    std::vector<char> beyond_limit_;
    std::vector<char> chain_degenerate_;
    std::vector<std::size_t> chain_spliced_;
    std::vector<std::size_t> chain_patched_;
    std::vector<double> chain_noise_;
    std::vector<std::size_t> chain_outliers_;
    std::vector<std::vector<std::size_t>> guide_; // the parallel chains each chain is guided by
    std::size_t untied_ = 0;
    std::size_t degenerate_ = 0;
    std::vector<std::size_t> fallback_;
    std::vector<std::size_t> beyond_;
    std::size_t spliced_ = 0;
    std::size_t patched_ = 0;
    static constexpr double cycle_tail_m = 40.0; // as chain_fit's splices
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
