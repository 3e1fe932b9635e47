#pragma once
// Instantiation strategies over a template's parameter dimensions
// (docs/scenarios.md "Strategies"): full factorial, pairwise (every feasible
// pair of values in some row, with few rows), seeded random and cover (the
// anchors a set cover of the route's ODD chose, with pairwise coverage of the
// parameters). Rows are value indices per dimension, the anchor first; a
// validity predicate encodes the constraints.
#include <cstddef>
#include <cstdint>
#include <functional>
#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace railodd::scenario {

enum class Strategy { full, pairwise, random, cover };
const char* to_string(Strategy s);
Strategy strategy_from(const std::string& name); // throws std::invalid_argument

using Row = std::vector<std::size_t>;
// A row being built: kUnset where no value is chosen yet.
inline constexpr std::size_t kUnset = static_cast<std::size_t>(-1);
// Whether a (partial) row can still be valid: constraints whose dimensions are
// not all set must not refuse it.
using Validity = std::function<bool(const Row& partial)>;

struct PairStats {
    std::size_t feasible = 0;   // value pairs some valid row can hold
    std::size_t covered = 0;    // of them, pairs the rows hold
    std::size_t infeasible = 0; // pairs the constraints exclude
};

// All valid rows in lexicographic order. Throws std::length_error when the
// product exceeds `limit` rows.
std::vector<Row> full_factorial(const std::vector<std::size_t>& sizes, const Validity& valid,
                                std::size_t limit = 1000000);

// A greedy covering array of strength 2 (AETG-style, deterministic): every
// pair of values of two dimensions that a valid row can hold is in some row.
std::vector<Row> pairwise(const std::vector<std::size_t>& sizes, const Validity& valid);

// Rows for the cover strategy: pairwise over dimensions 1.. (the parameters;
// pairs with the anchor, dimension 0, are not sought) and every anchor of
// `anchors` in at least one row. Rows take the chosen anchors in turn; a row
// no chosen anchor admits takes the first anchor that does.
std::vector<Row> cover_rows(const std::vector<std::size_t>& sizes, const Validity& valid,
                            const std::vector<std::size_t>& anchors);

// The first valid complete row that extends `row` (its kUnset entries
// filled, lowest values first), by a bounded depth-first search; none if
// there is none within the bound.
std::optional<Row> completed(const std::vector<std::size_t>& sizes, const Validity& valid, Row row);
inline bool completable(const std::vector<std::size_t>& sizes, const Validity& valid, Row row) {
    return completed(sizes, valid, std::move(row)).has_value();
}

// Whether some anchor 0..anchors-1 admits the (partial) parameter row.
bool any_anchor(std::size_t anchors, const Validity& valid, const Row& params);

// The anchors to use, per template, so that every item (an ODD element or
// class, numbered 0..item_count-1) some anchor exercises is exercised by a
// chosen one: greedy set cover (the candidate adding most uncovered items
// first; ties in an order shuffled with `seed`). candidates[t][a] lists the
// items anchor a of template t exercises; the result lists anchor indices per
// template, ascending.
std::vector<std::vector<std::size_t>> choose_anchors(const std::vector<std::vector<std::vector<std::size_t>>>& candidates,
                                                     std::size_t item_count, std::uint64_t seed);

// `count` distinct valid rows drawn uniformly with a 64-bit Mersenne Twister
// seeded with `seed`; the same on every platform. Fewer when fewer exist: up
// to random_enumeration_limit combinations the valid rows are listed, the
// count is capped at them and `every_valid_row` tells when all were returned;
// beyond, at most random_attempt_limit draws are made. A shorter draw with the
// same seed is a prefix of a longer one.
inline constexpr std::size_t random_enumeration_limit = 1000000;
inline constexpr std::size_t random_attempt_limit = 20000000;
std::vector<Row> random_rows(const std::vector<std::size_t>& sizes, const Validity& valid, std::size_t count,
                             std::uint64_t seed, bool* every_valid_row = nullptr);

// The most scenarios per template `--count` may ask for.
inline constexpr std::size_t max_count_per_template = 100000;

// Pairs covered by `rows` against the feasible pairs.
PairStats pair_coverage(const std::vector<std::size_t>& sizes, const Validity& valid, const std::vector<Row>& rows);

} // namespace railodd::scenario
