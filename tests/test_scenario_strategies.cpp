// Instantiation strategies (strategies.hpp): pairwise covers every feasible
// pair with far fewer rows than the full factorial and never breaks a
// constraint; full_factorial enumerates exactly the valid rows; random_rows is
// seeded, distinct and valid. Every claim is checked by enumeration.
#include "railodd/scenario/strategies.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <set>
#include <sstream>
#include <stdexcept>
#include <tuple>

using namespace railodd::scenario;

namespace {

using Pair = std::tuple<std::size_t, std::size_t, std::size_t, std::size_t>; // dim i, value, dim j > i, value

std::string show(const Row& r) {
    std::ostringstream s;
    s << "[";
    for (std::size_t k = 0; k < r.size(); ++k) {
        s << (k ? " " : "") << (r[k] == kUnset ? std::string("-") : std::to_string(r[k]));
    }
    return s.str() + "]";
}

std::string show(const Pair& p) {
    const auto [i, vi, j, vj] = p;
    return "dim" + std::to_string(i) + "=" + std::to_string(vi) + " & dim" + std::to_string(j) + "=" + std::to_string(vj);
}

std::set<Pair> all_pairs(const std::vector<std::size_t>& sizes) {
    std::set<Pair> out;
    for (std::size_t i = 0; i < sizes.size(); ++i)
        for (std::size_t j = i + 1; j < sizes.size(); ++j)
            for (std::size_t vi = 0; vi < sizes[i]; ++vi)
                for (std::size_t vj = 0; vj < sizes[j]; ++vj) out.insert({i, vi, j, vj});
    return out;
}

std::set<Pair> pairs_of(const std::vector<Row>& rows) {
    std::set<Pair> out;
    for (const auto& r : rows)
        for (std::size_t i = 0; i < r.size(); ++i)
            for (std::size_t j = i + 1; j < r.size(); ++j) out.insert({i, r[i], j, r[j]});
    return out;
}

// Every row is complete, in range and valid.
void expect_valid_rows(const std::vector<Row>& rows, const std::vector<std::size_t>& sizes, const Validity& valid) {
    for (const auto& r : rows) {
        ASSERT_EQ(r.size(), sizes.size()) << show(r);
        for (std::size_t k = 0; k < r.size(); ++k) {
            EXPECT_LT(r[k], sizes[k]) << "dimension " << k << " out of range in " << show(r);
        }
        EXPECT_TRUE(valid(r)) << "row breaks a constraint: " << show(r);
    }
}

// Pairs of the full factorial's valid rows: the pairs some valid row can hold.
std::set<Pair> feasible_pairs(const std::vector<std::size_t>& sizes, const Validity& valid) {
    return pairs_of(full_factorial(sizes, valid));
}

const Validity anything = [](const Row&) { return true; };

// dim0 = 0 together with dim1 = 1 is excluded (an exclusion of two parameters).
const Validity no_0_0_with_1_1 = [](const Row& r) { return !(r[0] == 0 && r[1] == 1); };

const std::vector<std::size_t> sizes_3425{3, 4, 2, 5};

} // namespace

TEST(ScenarioStrategies, NamesRoundTrip) {
    for (const auto s : {Strategy::full, Strategy::pairwise, Strategy::random, Strategy::cover}) {
        EXPECT_EQ(strategy_from(to_string(s)), s);
    }
    EXPECT_THROW(strategy_from("exhaustive"), std::invalid_argument);
}

TEST(ScenarioStrategies, PairwiseCoversEveryPairWithFewRows) {
    const auto rows = pairwise(sizes_3425, anything);
    expect_valid_rows(rows, sizes_3425, anything);
    const auto held = pairs_of(rows);
    const auto wanted = all_pairs(sizes_3425);
    EXPECT_EQ(wanted.size(), 71u);
    for (const auto& p : wanted) {
        EXPECT_TRUE(held.contains(p)) << "pair not covered: " << show(p);
    }
    EXPECT_GE(rows.size(), 20u) << "4 x 5 pairs of the two largest dimensions need 20 rows";
    EXPECT_LE(rows.size(), 25u) << "pairwise should need far fewer rows than the 120 of the full factorial";
    EXPECT_EQ(std::set<Row>(rows.begin(), rows.end()).size(), rows.size()) << "a row is repeated";
    EXPECT_EQ(pairwise(sizes_3425, anything), rows) << "pairwise must be deterministic";

    const PairStats stats = pair_coverage(sizes_3425, anything, rows);
    EXPECT_EQ(stats.feasible, 71u);
    EXPECT_EQ(stats.covered, 71u);
    EXPECT_EQ(stats.infeasible, 0u);
}

TEST(ScenarioStrategies, PairwiseRespectsConstraintsAndCountsTheExcludedPair) {
    const auto rows = pairwise(sizes_3425, no_0_0_with_1_1);
    expect_valid_rows(rows, sizes_3425, no_0_0_with_1_1);
    const auto held = pairs_of(rows);
    for (const auto& p : all_pairs(sizes_3425)) {
        if (p == Pair{0, 0, 1, 1}) {
            EXPECT_FALSE(held.contains(p)) << "the excluded pair is in a row";
        } else {
            EXPECT_TRUE(held.contains(p)) << "feasible pair not covered: " << show(p);
        }
    }
    EXPECT_LE(rows.size(), 25u);
    const PairStats stats = pair_coverage(sizes_3425, no_0_0_with_1_1, rows);
    EXPECT_EQ(stats.feasible, 70u);
    EXPECT_EQ(stats.covered, stats.feasible);
    EXPECT_EQ(stats.infeasible, 1u);

    // Rows missing pairs are reported as such.
    const std::vector<Row> few(rows.begin(), rows.begin() + 3);
    const PairStats partial = pair_coverage(sizes_3425, no_0_0_with_1_1, few);
    EXPECT_EQ(partial.feasible, 70u);
    EXPECT_EQ(partial.covered, pairs_of(few).size());
    EXPECT_LT(partial.covered, partial.feasible);
}

// Pairwise rows hold every pair that some valid row holds, and pair_coverage
// counts exactly those as feasible.
void expect_exact_pair_coverage(const std::vector<std::size_t>& sizes, const Validity& valid) {
    const auto rows = pairwise(sizes, valid);
    expect_valid_rows(rows, sizes, valid);
    const auto feasible = feasible_pairs(sizes, valid);
    const auto held = pairs_of(rows);
    for (const auto& p : feasible) {
        EXPECT_TRUE(held.contains(p)) << "feasible pair not covered: " << show(p);
    }
    const PairStats stats = pair_coverage(sizes, valid, rows);
    EXPECT_EQ(stats.feasible, feasible.size()) << "pair_coverage must count the pairs a valid row can hold";
    EXPECT_EQ(stats.covered, feasible.size());
    EXPECT_EQ(stats.infeasible, all_pairs(sizes).size() - feasible.size());
}

// A greedy completion without backtracking closes such pairs as "infeasible"
// although another value of an earlier dimension would have worked, and
// pair_coverage (same completion) would agree: full coverage of too few pairs.
TEST(ScenarioStrategies, PairwiseCoversPairsThatNeedBacktracking) {
    // dim2 = 0 is refused with every value of dim3 (two exclusions), so no
    // valid row has dim2 = 0; the pairs of dim0 x dim1 are all feasible
    // (with dim2 = 1), but the greedy fill tries dim2 = 0 first.
    expect_exact_pair_coverage({2, 2, 2, 2}, [](const Row& r) { return !(r[2] == 0 && r[3] != kUnset); });
    // The generator's shape: dimension 0 the anchors, 1 the ego speed, then
    // an actor asset and a perturbation. Anchor 0's speed limit is below every
    // ego speed (speed_within_limit), so no row has anchor 0; the pairs of
    // actor x perturbation are feasible with anchors 1 and 2.
    expect_exact_pair_coverage({3, 3, 4, 5}, [](const Row& r) { return !(r[0] == 0 && r[1] != kUnset); });
}

TEST(ScenarioStrategies, PairwiseEdgeCases) {
    EXPECT_TRUE(pairwise({3, 0, 2}, anything).empty()) << "an empty dimension leaves no row";
    const auto one = pairwise({4}, anything);
    EXPECT_EQ(one, (std::vector<Row>{{0}, {1}, {2}, {3}})) << "one dimension: every value";
    EXPECT_EQ(pairwise({2, 3}, anything).size(), 6u) << "two dimensions: the full factorial";
}

TEST(ScenarioStrategies, FullFactorialReturnsExactlyTheValidRows) {
    const auto all = full_factorial(sizes_3425, anything);
    EXPECT_EQ(all.size(), 120u);
    EXPECT_TRUE(std::is_sorted(all.begin(), all.end())) << "rows are in lexicographic order";
    EXPECT_EQ(std::set<Row>(all.begin(), all.end()).size(), 120u);

    const auto valid = full_factorial(sizes_3425, no_0_0_with_1_1);
    EXPECT_EQ(valid.size(), 120u - 2 * 5) << "the 10 rows with dim0=0 and dim1=1 are dropped";
    expect_valid_rows(valid, sizes_3425, no_0_0_with_1_1);
    std::vector<Row> expected;
    std::copy_if(all.begin(), all.end(), std::back_inserter(expected), no_0_0_with_1_1);
    EXPECT_EQ(valid, expected);

    EXPECT_THROW(full_factorial(sizes_3425, anything, 100), std::length_error);
    EXPECT_EQ(full_factorial(sizes_3425, anything, 120).size(), 120u);
    EXPECT_TRUE(full_factorial({2, 0}, anything).empty());
}

TEST(ScenarioStrategies, RandomRowsAreSeededDistinctAndValid) {
    const auto a = random_rows(sizes_3425, no_0_0_with_1_1, 30, 7);
    ASSERT_EQ(a.size(), 30u);
    expect_valid_rows(a, sizes_3425, no_0_0_with_1_1);
    EXPECT_EQ(std::set<Row>(a.begin(), a.end()).size(), a.size()) << "rows must be distinct";
    EXPECT_EQ(random_rows(sizes_3425, no_0_0_with_1_1, 30, 7), a) << "the same seed must give the same rows";
    EXPECT_NE(random_rows(sizes_3425, no_0_0_with_1_1, 30, 8), a) << "another seed should give other rows";
    // A shorter draw with the same seed is a prefix of the longer one.
    const auto b = random_rows(sizes_3425, no_0_0_with_1_1, 10, 7);
    EXPECT_TRUE(std::equal(b.begin(), b.end(), a.begin()));
    EXPECT_TRUE(random_rows(sizes_3425, anything, 0, 7).empty());
}

TEST(ScenarioStrategies, RandomRowsReturnsFewerWhenFewerExist) {
    const std::vector<std::size_t> sizes{2, 3};
    const Validity valid = [](const Row& r) { return !(r[0] == 1 && r[1] == 2); }; // 5 valid rows
    const auto rows = random_rows(sizes, valid, 10, 3);
    EXPECT_EQ(rows.size(), 5u);
    expect_valid_rows(rows, sizes, valid);
    std::vector<Row> sorted = rows;
    std::sort(sorted.begin(), sorted.end());
    EXPECT_EQ(sorted, full_factorial(sizes, valid)) << "all valid rows, each once";
    EXPECT_TRUE(random_rows(sizes, [](const Row&) { return false; }, 4, 3).empty());
}

// A count far above the combinations (2^31 asked, 5 exist) returns at once with
// every valid row, and says so; the rows are those of the same seed's draws.
TEST(ScenarioStrategies, RandomRowsCapsAHugeCountAtTheValidRows) {
    const std::vector<std::size_t> sizes{2, 3};
    const Validity valid = [](const Row& r) { return !(r[0] == 1 && r[1] == 2); };
    bool all = false;
    const auto rows = random_rows(sizes, valid, 2147483647u, 3, &all);
    EXPECT_TRUE(all);
    std::vector<Row> sorted = rows;
    std::sort(sorted.begin(), sorted.end());
    EXPECT_EQ(sorted, full_factorial(sizes, valid));
    EXPECT_EQ(random_rows(sizes, valid, 2147483647u, 3), rows) << "deterministic";
    bool some = true;
    EXPECT_EQ(random_rows(sizes, valid, 3, 3, &some).size(), 3u);
    EXPECT_FALSE(some) << "3 of 5: not every valid row";
}

// Valid rows so sparse that rejection draws rarely hit them (3 of 200,000):
// the draw is completed from the listed valid rows, not left short.
TEST(ScenarioStrategies, RandomRowsCompletesSparseDrawsFromTheValidRows) {
    const std::vector<std::size_t> sizes{200, 1000};
    const Validity valid = [](const Row& r) {
        return r.size() == 2 && r[0] != kUnset && r[1] != kUnset && r[0] == 7 && r[1] < 3;
    };
    bool all = false;
    const auto rows = random_rows(sizes, valid, 2, 11, &all);
    ASSERT_EQ(rows.size(), 2u);
    expect_valid_rows(rows, sizes, valid);
    EXPECT_FALSE(all);
    EXPECT_EQ(random_rows(sizes, valid, 50, 11, &all).size(), 3u);
    EXPECT_TRUE(all);
}

// --- cover: a set cover of the route's ODD, pairwise over the parameters ----

// Every item some candidate exercises is exercised by a chosen one, and the
// greedy choice is no larger than needed on sets where the optimum is known.
TEST(ScenarioStrategies, ChooseAnchorsCoversEveryReachableItem) {
    // Template 0: anchors {0,1}, {1,2}, {3}; template 1: {0,1,2,3}, {4}, {}.
    const std::vector<std::vector<std::vector<std::size_t>>> candidates = {
        {{0, 1}, {1, 2}, {3}},
        {{0, 1, 2, 3}, {4}, {}},
    };
    for (std::uint64_t seed : {1u, 2u, 3u, 99u}) {
        const auto chosen = choose_anchors(candidates, 6, seed); // item 5: no anchor exercises it
        ASSERT_EQ(chosen.size(), 2u);
        std::set<std::size_t> covered;
        std::size_t n = 0;
        for (std::size_t t = 0; t < chosen.size(); ++t) {
            EXPECT_TRUE(std::is_sorted(chosen[t].begin(), chosen[t].end()));
            for (const auto a : chosen[t]) {
                covered.insert(candidates[t][a].begin(), candidates[t][a].end());
                ++n;
            }
        }
        EXPECT_EQ(covered, (std::set<std::size_t>{0, 1, 2, 3, 4})) << "seed " << seed;
        EXPECT_EQ(n, 2u) << "the four-item anchor and the one with item 4 suffice";
        EXPECT_EQ(chosen, choose_anchors(candidates, 6, seed)) << "deterministic for a seed";
    }
}

TEST(ScenarioStrategies, ChooseAnchorsTiesFollowTheSeed) {
    // Ten anchors that each exercise the same single item: one is chosen,
    // which one depends on the seed only.
    const std::vector<std::vector<std::vector<std::size_t>>> candidates = {std::vector<std::vector<std::size_t>>(10, {0})};
    std::set<std::size_t> picked;
    for (std::uint64_t seed = 1; seed <= 40; ++seed) {
        const auto chosen = choose_anchors(candidates, 1, seed);
        ASSERT_EQ(chosen[0].size(), 1u);
        picked.insert(chosen[0][0]);
    }
    EXPECT_GT(picked.size(), 3u) << "ties are broken in a seeded order, not always the first";
    EXPECT_TRUE(choose_anchors({{}}, 0, 1)[0].empty());
}

// Rows hold every chosen anchor and every feasible pair of the parameters,
// never a row the validity refuses, with far fewer rows than pairwise over
// the anchors too.
TEST(ScenarioStrategies, CoverRowsHoldTheChosenAnchorsAndEveryParameterPair) {
    const std::vector<std::size_t> sizes = {30, 3, 4, 2, 5}; // 30 anchors, four parameters
    // Anchors 0-9 allow only parameter 0's values 0-1 (a low speed limit).
    const Validity valid = [](const Row& r) { return r[0] == kUnset || r[1] == kUnset || r[0] >= 10 || r[1] < 2; };
    const std::vector<std::size_t> chosen = {2, 11, 17};
    const auto rows = cover_rows(sizes, valid, chosen);
    expect_valid_rows(rows, sizes, valid);
    std::set<std::size_t> anchors;
    std::vector<Row> params;
    for (const auto& r : rows) {
        anchors.insert(r[0]);
        params.emplace_back(r.begin() + 1, r.end());
    }
    for (const auto a : chosen) {
        EXPECT_TRUE(anchors.contains(a)) << "chosen anchor " << a << " in no row";
    }
    const std::vector<std::size_t> psizes(sizes.begin() + 1, sizes.end());
    const auto covered = pairs_of(params);
    for (const auto& p : all_pairs(psizes)) {
        EXPECT_TRUE(covered.contains(p)) << show(p);
    }
    const std::size_t pairwise_rows = pairwise(sizes, valid).size();
    EXPECT_LE(3 * rows.size(), pairwise_rows) << rows.size() << " cover rows, " << pairwise_rows << " pairwise";
    // A parameter value no chosen anchor admits still gets a row, at an anchor that does.
    const auto low = cover_rows(sizes, valid, {2});
    bool high_speed = false;
    for (const auto& r : low) {
        high_speed = high_speed || r[1] == 2;
    }
    EXPECT_TRUE(high_speed);
    EXPECT_TRUE(any_anchor(30, valid, {2, 0, 0, 0}));
    EXPECT_FALSE(any_anchor(10, valid, {2, 0, 0, 0}));
    EXPECT_TRUE(cover_rows(sizes, valid, {}).empty());
}

TEST(ScenarioStrategies, CoverRowsWithOneParameterTakeEachValue) {
    const std::vector<std::size_t> sizes = {4, 3};
    const Validity anything = [](const Row&) { return true; };
    const auto rows = cover_rows(sizes, anything, {1, 3});
    std::set<std::size_t> values, anchors;
    for (const auto& r : rows) {
        values.insert(r[1]);
        anchors.insert(r[0]);
    }
    EXPECT_EQ(values, (std::set<std::size_t>{0, 1, 2}));
    EXPECT_EQ(anchors, (std::set<std::size_t>{1, 3}));
    EXPECT_EQ(rows.size(), 3u);
}

// A chosen anchor that admits none of the parameter rows (a combination
// pairwise did not need) still gets a row of its own.
TEST(ScenarioStrategies, CoverRowsPlaceAChosenAnchorNoParameterRowFits) {
    const std::vector<std::size_t> params = {2, 2, 2};
    const auto rows = pairwise(params, anything);
    ASSERT_LT(rows.size(), 8u);
    Row missing;
    for (const auto& r : full_factorial(params, anything)) {
        if (std::find(rows.begin(), rows.end(), r) == rows.end()) {
            missing = r;
            break;
        }
    }
    ASSERT_EQ(missing.size(), 3u);
    const std::vector<std::size_t> sizes = {4, 2, 2, 2};
    // Anchor 0 admits only the missing combination; the others admit anything.
    const Validity valid = [&](const Row& r) {
        if (r[0] != 0) {
            return true;
        }
        for (std::size_t k = 0; k < 3; ++k) {
            if (r[k + 1] != kUnset && r[k + 1] != missing[k]) {
                return false;
            }
        }
        return true;
    };
    const auto out = cover_rows(sizes, valid, {0, 3});
    expect_valid_rows(out, sizes, valid);
    const Row want{0, missing[0], missing[1], missing[2]};
    EXPECT_NE(std::find(out.begin(), out.end(), want), out.end());
}
