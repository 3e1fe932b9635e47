// Pairwise coverage is built greedily, one row at a time, around the first
// uncovered pair (AETG, Cohen et al. 1997, without the random candidates so
// that it is deterministic): each further dimension takes the valid value that
// covers most uncovered pairs with the values already chosen, backtracking
// where the constraints leave a later dimension no value. A pair no valid row
// can hold is counted as infeasible rather than left as a gap.
#include "railodd/scenario/strategies.hpp"

#include "index_draw.hpp"

#include <algorithm>
#include <array>
#include <optional>
#include <random>
#include <set>
#include <stdexcept>

namespace railodd::scenario {

namespace {

// Uncovered pairs of dimensions i < j as |Di| x |Dj| flags.
class PairTable {
public:
    PairTable(const std::vector<std::size_t>& sizes) : sizes_(sizes), n_(sizes.size()) {
        flags_.resize(n_ * n_);
        for (std::size_t i = 0; i < n_; ++i) {
            for (std::size_t j = i + 1; j < n_; ++j) {
                flags_[i * n_ + j].assign(sizes[i] * sizes[j], 1);
                left_ += sizes[i] * sizes[j];
            }
        }
    }
    bool open(std::size_t i, std::size_t vi, std::size_t j, std::size_t vj) const {
        return i < j ? flags_[i * n_ + j][vi * sizes_[j] + vj] : flags_[j * n_ + i][vj * sizes_[i] + vi];
    }
    void close(std::size_t i, std::size_t vi, std::size_t j, std::size_t vj) {
        auto& f = i < j ? flags_[i * n_ + j][vi * sizes_[j] + vj] : flags_[j * n_ + i][vj * sizes_[i] + vi];
        left_ -= f;
        f = 0;
    }
    void close_row(const Row& r) {
        for (std::size_t i = 0; i < n_; ++i) {
            for (std::size_t j = i + 1; j < n_; ++j) {
                close(i, r[i], j, r[j]);
            }
        }
    }
    std::size_t left() const { return left_; }
    // The first open pair in (i, j, vi, vj) order. Pairs never reopen, so the
    // search resumes where the last one stopped: linear over a whole run.
    bool first_open(std::size_t& i, std::size_t& vi, std::size_t& j, std::size_t& vj) {
        for (; ci_ < n_; ++ci_, cj_ = ci_ + 1, ck_ = 0) {
            for (; cj_ < n_; ++cj_, ck_ = 0) {
                const auto& f = flags_[ci_ * n_ + cj_];
                for (; ck_ < f.size(); ++ck_) {
                    if (f[ck_]) {
                        i = ci_;
                        j = cj_;
                        vi = ck_ / sizes_[j];
                        vj = ck_ % sizes_[j];
                        return true;
                    }
                }
            }
        }
        return false;
    }

    // Up to `max` open pairs {dimension i, value, dimension j, value} from
    // first_open's cursor on, without moving it.
    std::vector<std::array<std::size_t, 4>> next_open(std::size_t max) const {
        std::vector<std::array<std::size_t, 4>> out;
        std::size_t ci = ci_, cj = cj_, ck = ck_;
        for (; ci < n_ && out.size() < max; ++ci, cj = ci + 1, ck = 0) {
            for (; cj < n_ && out.size() < max; ++cj, ck = 0) {
                const auto& f = flags_[ci * n_ + cj];
                for (; ck < f.size() && out.size() < max; ++ck) {
                    if (f[ck]) {
                        out.push_back({ci, ck / sizes_[cj], cj, ck % sizes_[cj]});
                    }
                }
            }
        }
        return out;
    }
    // Open pairs a full row would close.
    std::size_t gain(const Row& r) const {
        std::size_t g = 0;
        for (std::size_t i = 0; i < n_; ++i) {
            for (std::size_t j = i + 1; j < n_; ++j) {
                g += open(i, r[i], j, r[j]) ? 1 : 0;
            }
        }
        return g;
    }

private:
    std::vector<std::size_t> sizes_;
    std::size_t n_;
    std::vector<std::vector<char>> flags_;
    std::size_t left_ = 0;
    std::size_t ci_ = 0, cj_ = 1, ck_ = 0; // first_open's cursor
};

// Completes `row` dimension by dimension, each time trying the valid values
// that close most open pairs first (lowest index on ties), and backtracking
// when a later dimension is left without a valid value. The search is bounded
// (`budget` rows tried) so that a pathological constraint set cannot stall a
// run; a pair whose completion runs out of budget counts as infeasible.
class Completion {
public:
    Completion(const std::vector<std::size_t>& sizes, const Validity& valid, const PairTable& open)
        : sizes_(sizes), valid_(valid), open_(open) {}

    bool operator()(Row& row) {
        budget_ = 20000;
        return fill(row, 0);
    }

private:
    const std::vector<std::size_t>& sizes_;
    const Validity& valid_;
    const PairTable& open_;
    std::size_t budget_ = 0;

    bool fill(Row& row, std::size_t k) {
        while (k < sizes_.size() && row[k] != kUnset) {
            ++k;
        }
        if (k == sizes_.size()) {
            return valid_(row);
        }
        std::vector<std::pair<std::size_t, std::size_t>> order; // (-gain, value) of the valid values
        for (std::size_t v = 0; v < sizes_[k]; ++v) {
            row[k] = v;
            if (budget_ == 0) {
                break;
            }
            --budget_;
            if (!valid_(row)) {
                continue;
            }
            std::size_t gain = 0;
            for (std::size_t m = 0; m < sizes_.size(); ++m) {
                gain += m != k && row[m] != kUnset && open_.open(k, v, m, row[m]) ? 1 : 0;
            }
            order.emplace_back(static_cast<std::size_t>(-1) - gain, v);
        }
        std::sort(order.begin(), order.end());
        for (const auto& [rank, v] : order) {
            row[k] = v;
            if (fill(row, k + 1)) {
                return true;
            }
        }
        row[k] = kUnset;
        return false;
    }
};

constexpr std::size_t pairwise_candidates = 24;

// Of the row `r` (complete, valid) and rows grown from the next open pairs,
// the one closing most open pairs (AETG's candidates, deterministic).
Row best_candidate(Row r, const PairTable& open, Completion& complete, const Validity& valid) {
    std::size_t best = open.gain(r);
    for (const auto& pair : open.next_open(pairwise_candidates)) {
        Row c(r.size(), kUnset);
        c[pair[0]] = pair[1];
        c[pair[2]] = pair[3];
        if (valid(c) && complete(c)) {
            if (const std::size_t g = open.gain(c); g > best) {
                best = g;
                r = std::move(c);
            }
        }
    }
    return r;
}

bool empty_domain(const std::vector<std::size_t>& sizes) {
    for (const auto s : sizes) {
        if (s == 0) {
            return true;
        }
    }
    return false;
}

} // namespace

const char* to_string(Strategy s) {
    switch (s) {
    case Strategy::full: return "full";
    case Strategy::pairwise: return "pairwise";
    case Strategy::random: return "random";
    case Strategy::cover: return "cover";
    }
    return "?";
}

namespace {

double combinations(const std::vector<std::size_t>& sizes) {
    double product = 1.0;
    for (const auto n : sizes) {
        product *= static_cast<double>(n);
    }
    return product;
}

} // namespace

Strategy strategy_from(const std::string& name) {
    if (name == "full") return Strategy::full;
    if (name == "pairwise") return Strategy::pairwise;
    if (name == "random") return Strategy::random;
    if (name == "cover") return Strategy::cover;
    throw std::invalid_argument("unknown strategy '" + name + "' (cover, pairwise, full or random)");
}

std::vector<Row> full_factorial(const std::vector<std::size_t>& sizes, const Validity& valid, std::size_t limit) {
    std::vector<Row> rows;
    if (empty_domain(sizes)) {
        return rows;
    }
    const double product = combinations(sizes);
    if (product > static_cast<double>(limit)) {
        throw std::length_error("the full factorial has " + std::to_string(static_cast<long long>(product)) +
                                " rows, more than " + std::to_string(limit));
    }
    Row r(sizes.size(), 0);
    while (true) {
        if (valid(r)) {
            rows.push_back(r);
        }
        std::size_t k = sizes.size();
        while (k > 0 && ++r[k - 1] == sizes[k - 1]) {
            r[--k] = 0;
        }
        if (k == 0) {
            return rows;
        }
    }
}

std::vector<Row> pairwise(const std::vector<std::size_t>& sizes, const Validity& valid) {
    std::vector<Row> rows;
    if (empty_domain(sizes)) {
        return rows;
    }
    if (sizes.size() < 2) {
        return full_factorial(sizes, valid);
    }
    PairTable open(sizes);
    Completion complete(sizes, valid, open);
    std::size_t i = 0, vi = 0, j = 0, vj = 0;
    while (open.first_open(i, vi, j, vj)) {
        Row r(sizes.size(), kUnset);
        r[i] = vi;
        r[j] = vj;
        if (!valid(r) || !complete(r)) {
            open.close(i, vi, j, vj); // no valid row holds it: infeasible, not a gap
            continue;
        }
        r = best_candidate(std::move(r), open, complete, valid);
        open.close_row(r);
        rows.push_back(std::move(r));
    }
    return rows;
}

namespace {

// Appends valid rows not in `seen`, in seeded order, until `rows` holds `count`.
void complete_from(const std::vector<Row>& all, const std::set<Row>& seen, std::size_t count, IndexDraw& draw,
                   std::vector<Row>& rows) {
    std::vector<Row> rest;
    for (const auto& r : all) {
        if (!seen.contains(r)) {
            rest.push_back(r);
        }
    }
    for (std::size_t i = 0; i < rest.size() && rows.size() < count; ++i) {
        std::swap(rest[i], rest[i + draw(rest.size() - i)]);
        rows.push_back(std::move(rest[i]));
    }
}

} // namespace

std::vector<Row> random_rows(const std::vector<std::size_t>& sizes, const Validity& valid, std::size_t count,
                             std::uint64_t seed, bool* every_valid_row) {
    std::vector<Row> rows;
    if (every_valid_row) {
        *every_valid_row = false;
    }
    if (empty_domain(sizes) || count == 0) {
        return rows;
    }
    // Where the request comes near the number of combinations, rejection
    // draws mostly collide: the valid rows are listed first, so the count is
    // capped at them and the draw completed from them (never unbounded).
    const double product = combinations(sizes);
    const bool enumerable = product <= static_cast<double>(random_enumeration_limit);
    std::optional<std::vector<Row>> all;
    if (enumerable && static_cast<double>(count) * 8.0 >= product) {
        all = full_factorial(sizes, valid, random_enumeration_limit);
        count = std::min(count, all->size());
    }
    IndexDraw draw(seed);
    std::set<Row> seen;
    const std::size_t attempts = count > random_attempt_limit / 1000 ? random_attempt_limit : 1000 * count;
    for (std::size_t a = 0; a < attempts && rows.size() < count; ++a) {
        Row r(sizes.size());
        for (std::size_t k = 0; k < sizes.size(); ++k) {
            r[k] = draw(sizes[k]);
        }
        if (valid(r) && seen.insert(r).second) {
            rows.push_back(std::move(r));
        }
    }
    if (rows.size() < count && enumerable) {
        if (!all) {
            all = full_factorial(sizes, valid, random_enumeration_limit);
        }
        complete_from(*all, seen, count, draw, rows); // the draws fell short
    }
    if (every_valid_row && all) {
        *every_valid_row = rows.size() == all->size();
    }
    return rows;
}

PairStats pair_coverage(const std::vector<std::size_t>& sizes, const Validity& valid, const std::vector<Row>& rows) {
    PairStats stats;
    if (empty_domain(sizes) || sizes.size() < 2) {
        return stats;
    }
    PairTable held(sizes);
    for (const auto& r : rows) {
        held.close_row(r);
    }
    // Feasibility of each pair: the pairwise builder's test, a valid completion.
    PairTable probe(sizes);
    Completion complete(sizes, valid, probe);
    for (std::size_t i = 0; i < sizes.size(); ++i) {
        for (std::size_t j = i + 1; j < sizes.size(); ++j) {
            for (std::size_t vi = 0; vi < sizes[i]; ++vi) {
                for (std::size_t vj = 0; vj < sizes[j]; ++vj) {
                    Row r(sizes.size(), kUnset);
                    r[i] = vi;
                    r[j] = vj;
                    const bool covered = !held.open(i, vi, j, vj);
                    if (covered || (valid(r) && complete(r))) {
                        ++stats.feasible;
                        stats.covered += covered ? 1 : 0;
                    } else {
                        ++stats.infeasible;
                    }
                }
            }
        }
    }
    return stats;
}

} // namespace railodd::scenario
