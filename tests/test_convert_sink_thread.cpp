// The profile writer's thread (convert/src/sink_thread.hpp): what the tagger
// hands it arrives at the sink in order and whole, end() returns once all is
// written, and a failing sink's error reaches the tagger.
#include "sink_thread.hpp"

#include <gtest/gtest.h>

#include <stdexcept>
#include <string>
#include <vector>

using namespace railodd;

namespace {

class Recorder final : public odd::ProfileSink {
public:
    void begin(const odd::OddProfile& head) override { log.push_back("begin " + head.route); }
    void add(std::deque<odd::TaggedElement>& batch) override {
        if (fail_at && log.size() == fail_at) {
            throw std::runtime_error("disk full");
        }
        std::string ids;
        for (const auto& e : batch) {
            ids += (ids.empty() ? "" : ",") + e.road_id;
        }
        log.push_back("add " + ids);
    }
    void end(const odd::OddProfile& tail) override { log.push_back("end " + tail.route); }
    std::vector<std::string> log;
    std::size_t fail_at = 0;
};

std::deque<odd::TaggedElement> batch_of(int first, int n) {
    std::deque<odd::TaggedElement> b;
    for (int i = first; i < first + n; ++i) {
        odd::TaggedElement e;
        e.road_id = std::to_string(i);
        b.push_back(e);
    }
    return b;
}

} // namespace

TEST(ConvertSinkThread, BatchesArriveInOrderAndEndWaitsForThem) {
    Recorder r;
    odd::OddProfile head, tail;
    head.route = "h";
    tail.route = "t";
    {
        convert::SinkThread t(r, 1);
        t.begin(head);
        for (int k = 0; k < 50; ++k) {
            auto b = batch_of(3 * k, 3);
            t.add(b);
            EXPECT_TRUE(b.empty()); // moved to the writer
        }
        t.end(tail);
        ASSERT_EQ(r.log.size(), 52u); // everything written when end() returns
    }
    EXPECT_EQ(r.log.front(), "begin h");
    EXPECT_EQ(r.log[1], "add 0,1,2");
    EXPECT_EQ(r.log[50], "add 147,148,149");
    EXPECT_EQ(r.log.back(), "end t");
}

TEST(ConvertSinkThread, TheSinksErrorReachesTheTagger) {
    Recorder r;
    r.fail_at = 3; // begin and two batches written, then the third fails
    convert::SinkThread t(r, 2);
    t.begin({});
    bool thrown = false;
    try {
        for (int k = 0; k < 20; ++k) {
            auto b = batch_of(k, 1);
            t.add(b);
        }
        t.end({});
    } catch (const std::runtime_error& e) {
        thrown = true;
        EXPECT_STREQ(e.what(), "disk full");
    }
    EXPECT_TRUE(thrown);
    EXPECT_EQ(r.log.size(), 3u);
}

TEST(ConvertSinkThread, AbandonedMidwayItStopsWithoutWritingMore) {
    Recorder r;
    {
        convert::SinkThread t(r, 2);
        t.begin({});
        auto b = batch_of(0, 2);
        t.add(b);
        // The tagger failed here: no end(); the destructor must not hang.
    }
    EXPECT_LE(r.log.size(), 2u);
}
