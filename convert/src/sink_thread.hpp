#pragma once
// A profile sink run on a thread of its own (the profile's files,
// ProfileFilesOutput): the tagger hands each batch over and tags the next
// while the files print the last (on Cologne they were a third of the
// tagging phase's time, on the tagging thread). Batches arrive in order and
// at most `depth` wait, so memory stays that of a few batches. end()
// returns once everything is written; an exception from the sink comes back
// from the next add() or from end().
#include "railodd/odd/profile.hpp"

#include <condition_variable>
#include <deque>
#include <exception>
#include <mutex>
#include <thread>
#include <variant>

namespace railodd::convert {

class SinkThread final : public odd::ProfileSink {
public:
    explicit SinkThread(odd::ProfileSink& inner, std::size_t depth = 2);
    ~SinkThread() override;
    SinkThread(const SinkThread&) = delete;
    SinkThread& operator=(const SinkThread&) = delete;

    void begin(const odd::OddProfile& head) override;
    void add(std::deque<odd::TaggedElement>& batch) override;
    void end(const odd::OddProfile& tail) override;

private:
    struct Begin {
        odd::OddProfile head;
    };
    struct End {
        odd::OddProfile tail;
    };
    using Task = std::variant<Begin, std::deque<odd::TaggedElement>, End>;

    void push(Task task);
    void work();
    void rethrow();

    odd::ProfileSink& inner_;
    std::size_t depth_;
    std::mutex m_;
    std::condition_variable changed_;
    std::deque<Task> tasks_;
    bool stop_ = false;
    std::exception_ptr failed_;
    std::thread worker_;
};

} // namespace railodd::convert
