#pragma once
// Work run beside the calling thread: on a thread of its own, or, where one
// thread is asked for, deferred until its result is taken (the same work in
// turn, so no result depends on the choice).
#include <future>

namespace railodd::util {

inline std::launch beside(bool two_threads) { return two_threads ? std::launch::async : std::launch::deferred; }

} // namespace railodd::util
