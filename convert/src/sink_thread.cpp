#include "sink_thread.hpp"

namespace railodd::convert {

SinkThread::SinkThread(odd::ProfileSink& inner, std::size_t depth)
    : inner_(inner), depth_(depth), worker_([this] { work(); }) {}

SinkThread::~SinkThread() {
    {
        const std::lock_guard<std::mutex> lock(m_);
        stop_ = true;
    }
    changed_.notify_all();
    worker_.join();
}

void SinkThread::begin(const odd::OddProfile& head) { push(Begin{head}); }

void SinkThread::add(std::deque<odd::TaggedElement>& batch) { push(std::move(batch)); }

void SinkThread::end(const odd::OddProfile& tail) {
    push(End{tail});
    std::unique_lock<std::mutex> lock(m_);
    changed_.wait(lock, [this] { return tasks_.empty() || failed_; });
    lock.unlock();
    rethrow();
}

void SinkThread::push(Task task) {
    std::unique_lock<std::mutex> lock(m_);
    changed_.wait(lock, [this] { return tasks_.size() < depth_ || failed_; });
    if (failed_) {
        lock.unlock();
        rethrow();
    }
    tasks_.push_back(std::move(task));
    lock.unlock();
    changed_.notify_all();
}

void SinkThread::rethrow() {
    const std::lock_guard<std::mutex> lock(m_);
    if (failed_) {
        std::rethrow_exception(failed_);
    }
}

// Takes the tasks in order; a task leaves the queue only once done, so that
// end() sees an empty queue when the last is written.
void SinkThread::work() {
    for (;;) {
        std::unique_lock<std::mutex> lock(m_);
        changed_.wait(lock, [this] { return !tasks_.empty() || stop_; });
        if (stop_ || failed_) {
            return; // stopped: done, or the tagging failed and nothing more is wanted
        }
        Task& task = tasks_.front();
        lock.unlock();
        try {
            if (auto* b = std::get_if<Begin>(&task)) {
                inner_.begin(b->head);
            } else if (auto* batch = std::get_if<std::deque<odd::TaggedElement>>(&task)) {
                inner_.add(*batch);
            } else {
                inner_.end(std::get<End>(task).tail);
            }
        } catch (...) {
            lock.lock();
            failed_ = std::current_exception();
            lock.unlock();
            changed_.notify_all();
            return;
        }
        lock.lock();
        tasks_.pop_front();
        lock.unlock();
        changed_.notify_all();
    }
}

} // namespace railodd::convert
