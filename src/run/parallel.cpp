#include "run/parallel.hpp"

#include <atomic>
#include <thread>
#include <vector>

namespace bb {

void parallel_for(int count, int threads, const std::function<void(int)>& job) {
  if (threads <= 1 || count <= 1) {
    for (int i = 0; i < count; ++i) job(i);
    return;
  }
  std::atomic<int> next{0};
  std::vector<std::thread> pool;
  for (int t = 0; t < std::min(threads, count); ++t)
    pool.emplace_back([&] {
      for (int i = next++; i < count; i = next++) job(i);
    });
  for (std::thread& t : pool) t.join();
}

}  // namespace bb
