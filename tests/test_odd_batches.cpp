// The network tagged a batch of tracks at a time (tag_network): the embedded
// sample route (switches, crossings, tunnel, bridge, stations, signals, a
// parallel road) gives the same profile whatever the batch size and whether
// or not the tracks' indexes come prebuilt, and each batch holds only its
// own tracks, in profile order.
#include "railodd/sample/sample_route.hpp"
#include "odd_network_support.hpp"

#include <tuple>

#include <unistd.h> // getpid: one folder per test process

using namespace railodd;
using namespace railodd::test;

namespace {

const Network& network() {
    static const Network n = [] {
        const auto dir = fs::temp_directory_path() / "railodd-tests" / ("odd-batches-" + std::to_string(::getpid()));
        return network_of(sample::write_sample_route(dir).osm);
    }();
    return n;
}

} // namespace

TEST(OddBatches, ProfileDoesNotDependOnTheBatchSize) {
    const Network& n = network();
    const BatchRecorder reference = tag_in_batches(n, odd::default_tracks_per_batch, true);
    const std::string text = odd::to_json_text(reference.whole);
    ASSERT_GT(reference.whole.elements.size(), 100u);
    ASSERT_GE(n.fitted.edges.size(), 5u);
    for (const std::size_t batch : {std::size_t{1}, std::size_t{2}, std::size_t{3}, std::size_t{7}}) {
        for (const bool prebuilt : {true, false}) {
            const BatchRecorder r = tag_in_batches(n, batch, prebuilt);
            EXPECT_EQ(r.begins, 1);
            EXPECT_EQ(r.ends, 1);
            EXPECT_EQ(r.tail_elements, 0u);
            EXPECT_EQ(r.batches.size(), (n.fitted.edges.size() + batch - 1) / batch);
            EXPECT_EQ(odd::to_json_text(r.whole), text) << "batch " << batch << " prebuilt " << prebuilt;
        }
    }
}

TEST(OddBatches, EachBatchHoldsItsOwnTracksInProfileOrder) {
    const std::size_t batch = 2;
    const BatchRecorder r = tag_in_batches(network(), batch, false);
    for (std::size_t b = 0; b < r.batches.size(); ++b) {
        for (std::size_t i = 0; i < r.batches[b].size(); ++i) {
            const auto& e = r.batches[b][i];
            EXPECT_GE(e.track, b * batch);
            EXPECT_LT(e.track, (b + 1) * batch);
            if (i > 0) {
                const auto& p = r.batches[b][i - 1];
                EXPECT_LE(std::tie(p.track, p.chainage_start), std::tie(e.track, e.chainage_start));
            }
        }
    }
}

TEST(OddBatches, ABatchOfNoTracksIsRefused) {
    EXPECT_THROW(tag_in_batches(network(), 0, false), std::invalid_argument);
}
