#include "chain_orientation.hpp"

#include "railodd/geometry/vertex_legs.hpp"

#include <algorithm>
#include <numeric>
#include <utility>

namespace railodd::geometry {

namespace {

// Union-find whose links carry a parity: flip[a] ^ flip[b] = parity.
class ParityForest {
public:
    explicit ParityForest(std::size_t n) : parent_(n), parity_(n, 0) { std::iota(parent_.begin(), parent_.end(), 0); }

    std::pair<std::size_t, int> find(std::size_t a) {
        int p = 0;
        std::size_t r = a;
        while (parent_[r] != r) {
            p ^= parity_[r];
            r = parent_[r];
        }
        // Path compression keeps each node's parity to the root.
        int q = p;
        while (parent_[a] != r) {
            const std::size_t next = parent_[a];
            const int pa = parity_[a];
            parent_[a] = r;
            parity_[a] = q;
            q ^= pa;
            a = next;
        }
        return {r, p};
    }

    // False when the constraint contradicts the ones joined before.
    bool join(std::size_t a, std::size_t b, int parity) {
        const auto [ra, pa] = find(a);
        const auto [rb, pb] = find(b);
        if (ra == rb) {
            return (pa ^ pb) == parity;
        }
        // The lower root stays the root: the result does not depend on join order details.
        const auto [root, child] = std::minmax(ra, rb);
        parent_[child] = root;
        parity_[child] = pa ^ pb ^ parity;
        return true;
    }

private:
    std::vector<std::size_t> parent_;
    std::vector<int> parity_;
};

void reverse_chain(Chain& chain, FittedNetwork& net) {
    std::reverse(chain.items.begin(), chain.items.end());
    for (ChainItem& item : chain.items) {
        item.reversed = !item.reversed;
        FittedEdge& fe = net.edges[item.edge];
        fe.alignment = reversed(fe.alignment);
        fe.reversed = !fe.reversed;
    }
    std::swap(chain.start, chain.end);
}

// Per chain, whether to reverse it: each component of the constraint graph
// reverses whichever class holds less track, so most of it keeps the
// direction the data gave it.
std::vector<char> choose_flips(ParityForest& forest, const FittedNetwork& net) {
    const std::size_t n = net.chains.size();
    std::vector<double> len(n, 0.0);
    for (std::size_t c = 0; c < n; ++c) {
        for (const ChainItem& item : net.chains[c].items) {
            len[c] += length(net.edges[item.edge].alignment);
        }
    }
    std::vector<double> odd(n, 0.0), even(n, 0.0); // per root: track length at parity 1 / 0
    for (std::size_t c = 0; c < n; ++c) {
        const auto [root, p] = forest.find(c);
        (p ? odd : even)[root] += len[c];
    }
    std::vector<char> flip(n, 0);
    for (std::size_t c = 0; c < n; ++c) {
        const auto [root, p] = forest.find(c);
        const bool flip_odd = odd[root] <= even[root];
        flip[c] = static_cast<char>(p == (flip_odd ? 1 : 0));
    }
    return flip;
}

// flip[a] ^ flip[b] must equal parity for a movement between chains a and b.
struct Constraint {
    std::size_t a, b;
    int parity;
};

std::vector<Constraint> constraints_of(const TrackGraph& graph, const FittedNetwork& net) {
    std::vector<Constraint> out;
    for (const auto& at : legs_by_vertex(graph, net)) {
        for (std::size_t i = 0; i < at.size(); ++i) {
            for (std::size_t j = i + 1; j < at.size(); ++j) {
                if (g2_mismatch(at[i], at[j]).empty()) {
                    // After the flips exactly one of the two legs must start at the vertex.
                    out.push_back({net.edges[at[i].edge].chain, net.edges[at[j].edge].chain,
                                   1 ^ static_cast<int>(at[i].at_start) ^ static_cast<int>(at[j].at_start)});
                }
            }
        }
    }
    return out;
}

std::size_t violated(const std::vector<Constraint>& cs, const std::vector<char>& flip) {
    return static_cast<std::size_t>(std::count_if(cs.begin(), cs.end(), [&](const Constraint& c) {
        return (flip[c.a] ^ flip[c.b]) != c.parity;
    }));
}

// The forest satisfies a spanning set of constraints; where odd cycles
// overlap, which others break depends on the order they came in. Flipping a
// chain whenever that breaks fewer of its own constraints than it mends
// brings the count down to (near) one per independent cycle.
void improve(const std::vector<Constraint>& cs, std::vector<char>& flip) {
    std::vector<std::vector<std::size_t>> of(flip.size());
    for (std::size_t i = 0; i < cs.size(); ++i) {
        if (cs[i].a != cs[i].b) {
            of[cs[i].a].push_back(i);
            of[cs[i].b].push_back(i);
        }
    }
    for (bool changed = true; changed;) {
        changed = false;
        for (std::size_t c = 0; c < flip.size(); ++c) {
            long gain = 0; // constraints mended minus broken by flipping c
            for (const std::size_t i : of[c]) {
                gain += (flip[cs[i].a] ^ flip[cs[i].b]) != cs[i].parity ? 1 : -1;
            }
            if (gain > 0) {
                flip[c] ^= 1;
                changed = true;
            }
        }
    }
}

} // namespace

Orientation orient_chains(const TrackGraph& graph, FittedNetwork& net) {
    const std::vector<Constraint> cs = constraints_of(graph, net);
    ParityForest forest(net.chains.size());
    for (const Constraint& c : cs) {
        forest.join(c.a, c.b, c.parity);
    }
    std::vector<char> flip = choose_flips(forest, net);
    improve(cs, flip);
    Orientation o;
    o.reversing_links = violated(cs, flip);
    for (std::size_t c = 0; c < net.chains.size(); ++c) {
        if (flip[c]) {
            reverse_chain(net.chains[c], net);
            ++o.reversed_chains;
        }
    }
    return o;
}

} // namespace railodd::geometry
