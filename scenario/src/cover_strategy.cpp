// The cover strategy (docs/scenarios.md "Strategies"): a greedy set cover of
// the ODD items the anchors exercise, across templates, and per template a
// pairwise array of the parameters alone placed on the chosen anchors.
#include "railodd/scenario/strategies.hpp"

#include "index_draw.hpp"

#include <algorithm>
#include <optional>
#include <set>

namespace railodd::scenario {

namespace {

bool empty_domain(const std::vector<std::size_t>& sizes) {
    return std::find(sizes.begin(), sizes.end(), std::size_t{0}) != sizes.end();
}

bool fill(const std::vector<std::size_t>& sizes, const Validity& valid, Row& row, std::size_t k, std::size_t& budget) {
    while (k < sizes.size() && row[k] != kUnset) {
        ++k;
    }
    if (k == sizes.size()) {
        return valid(row);
    }
    for (std::size_t v = 0; v < sizes[k] && budget > 0; ++v, --budget) {
        row[k] = v;
        if (valid(row) && fill(sizes, valid, row, k + 1, budget)) {
            return true;
        }
    }
    row[k] = kUnset;
    return false;
}

} // namespace

std::optional<Row> completed(const std::vector<std::size_t>& sizes, const Validity& valid, Row row) {
    std::size_t budget = 20000; // as the pairwise completion: a pathological constraint set cannot stall a run
    if (row.size() == sizes.size() && !empty_domain(sizes) && valid(row) && fill(sizes, valid, row, 0, budget)) {
        return row;
    }
    return std::nullopt;
}

bool any_anchor(std::size_t anchors, const Validity& valid, const Row& params) {
    Row full{0};
    full.insert(full.end(), params.begin(), params.end());
    for (std::size_t a = 0; a < anchors; ++a) {
        full[0] = a;
        if (valid(full)) {
            return true;
        }
    }
    return false;
}

std::vector<Row> cover_rows(const std::vector<std::size_t>& sizes, const Validity& valid,
                            const std::vector<std::size_t>& anchors) {
    std::vector<Row> out;
    if (sizes.empty() || empty_domain(sizes) || anchors.empty()) {
        return out;
    }
    const std::vector<std::size_t> params(sizes.begin() + 1, sizes.end());
    const auto with = [](std::size_t anchor, const Row& r) {
        Row full{anchor};
        full.insert(full.end(), r.begin(), r.end());
        return full;
    };
    // A parameter row is valid where some anchor admits it (the speed limit
    // is the anchor's).
    const Validity valid_params = [&](const Row& r) { return any_anchor(sizes[0], valid, r); };
    const std::vector<Row> rows = params.size() < 2 ? full_factorial(params, valid_params) : pairwise(params, valid_params);
    std::set<std::size_t> used;
    std::size_t turn = 0;
    for (const Row& r : rows) {
        std::optional<std::size_t> pick;
        for (std::size_t k = 0; k < anchors.size() && !pick; ++k) {
            const std::size_t a = anchors[(turn + k) % anchors.size()];
            pick = valid(with(a, r)) ? std::optional<std::size_t>(a) : std::nullopt;
        }
        for (std::size_t a = 0; a < sizes[0] && !pick; ++a) {
            pick = valid(with(a, r)) ? std::optional<std::size_t>(a) : std::nullopt;
        }
        if (pick) {
            out.push_back(with(*pick, r));
            used.insert(*pick);
            ++turn;
        }
    }
    // Chosen anchors no row took: the first row valid there, else any valid
    // row of that anchor.
    for (const std::size_t a : anchors) {
        if (used.contains(a)) {
            continue;
        }
        bool placed = false;
        for (std::size_t i = 0; i < rows.size() && !placed; ++i) {
            if (valid(with(a, rows[i]))) {
                out.push_back(with(a, rows[i]));
                placed = true;
            }
        }
        Row at_a(sizes.size(), kUnset);
        at_a[0] = a;
        if (auto r = placed ? std::nullopt : completed(sizes, valid, at_a)) {
            out.push_back(std::move(*r));
        }
    }
    return out;
}

std::vector<std::vector<std::size_t>> choose_anchors(const std::vector<std::vector<std::vector<std::size_t>>>& candidates,
                                                     std::size_t item_count, std::uint64_t seed) {
    struct Candidate {
        std::size_t tmpl, anchor;
        const std::vector<std::size_t>* items;
    };
    std::vector<Candidate> all;
    for (std::size_t t = 0; t < candidates.size(); ++t) {
        for (std::size_t a = 0; a < candidates[t].size(); ++a) {
            all.push_back({t, a, &candidates[t][a]});
        }
    }
    IndexDraw draw(seed);
    for (std::size_t i = 0; i + 1 < all.size(); ++i) { // Fisher-Yates: the tie order
        std::swap(all[i], all[i + draw(all.size() - i)]);
    }
    std::vector<char> covered(item_count, 0);
    std::vector<std::vector<std::size_t>> chosen(candidates.size());
    std::vector<char> taken(all.size(), 0);
    while (true) {
        std::size_t best = all.size(), best_gain = 0;
        for (std::size_t i = 0; i < all.size(); ++i) {
            if (taken[i]) {
                continue;
            }
            std::size_t gain = 0;
            for (const auto item : *all[i].items) {
                gain += covered[item] ? 0 : 1;
            }
            if (gain > best_gain) {
                best = i;
                best_gain = gain;
            }
        }
        if (best == all.size()) {
            break;
        }
        taken[best] = 1;
        for (const auto item : *all[best].items) {
            covered[item] = 1;
        }
        chosen[all[best].tmpl].push_back(all[best].anchor);
    }
    for (auto& c : chosen) {
        std::sort(c.begin(), c.end());
    }
    return chosen;
}

} // namespace railodd::scenario
