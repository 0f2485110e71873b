// Run independent jobs on a few threads; results keep the jobs' order.
#pragma once

#include <functional>

namespace bb {

/// Calls job(i) for i in [0, count) on up to `threads` threads and returns when all are done.
void parallel_for(int count, int threads, const std::function<void(int)>& job);

}  // namespace bb
