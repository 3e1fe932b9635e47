// Batches on real extracts (tag_network): a town's rails and roads with
// land use (Monaco) and a city's rail network (Lauf) give the same profile
// tagged a track at a time, 17 at a time and in one batch.
#include "odd_network_support.hpp"

using namespace railodd;
using namespace railodd::test;

namespace {

void expect_batch_independent(const char* extract) {
    const fs::path osm = shared_data() / "osm" / extract;
    const Network n = network_of(osm);
    const BatchRecorder whole = tag_in_batches(n, 1000000, false);
    ASSERT_GT(whole.whole.elements.size(), 200u) << extract;
    const std::string text = odd::to_json_text(whole.whole);
    for (const std::size_t batch : {std::size_t{1}, std::size_t{17}}) {
        EXPECT_EQ(odd::to_json_text(tag_in_batches(n, batch, batch == 17).whole), text) << extract << " batch " << batch;
    }
}

} // namespace

TEST(OddBatchesShared, RealExtractsGiveOneProfileWhateverTheBatches) {
    RAILODD_REQUIRE_SHARED_DATA();
    expect_batch_independent("osrm_monaco.osm.pbf");
    expect_batch_independent("gh_lauf-200115.osm.pbf");
}
