// The child pool starts the queued piece of the highest priority first and says how many
// children could start with nothing queued for them.
#include "run/child_pool.hpp"

#include <gtest/gtest.h>
#include <unistd.h>

#include <cstdio>
#include <filesystem>
#include <string>
#include <vector>

namespace bb {
namespace {

TEST(ChildPool, AFreeSlotTakesTheHighestPriorityFirstAndTheFirstOfEquals) {
  ChildPool pool(1, true);
  std::vector<std::string> order;
  const auto piece = [&](const std::string& name, double priority) {
    pool.submit(
        name, [name] { return name; }, 10.0,
        [&order](const ChildOutcome& o) { order.push_back(o.payload); }, priority);
  };
  piece("low", 0.0);
  piece("high-1", 2.0);
  piece("middle", 1.0);
  piece("high-2", 2.0);
  pool.run();
  EXPECT_EQ(order, (std::vector<std::string>{"high-1", "high-2", "middle", "low"}));
}

TEST(ChildPool, FreeSlotsCountWhatCouldStartWithNothingQueued) {
  ChildPool pool(2, true);
  EXPECT_EQ(pool.free_slots(), 2);
  int seen_while_running = -1;
  pool.submit(
      "one", [] { return std::string("1"); }, 10.0,
      [&](const ChildOutcome&) { seen_while_running = pool.free_slots(); });
  EXPECT_EQ(pool.free_slots(), 1);
  pool.run();
  EXPECT_EQ(seen_while_running, 2) << "a finished child frees its slot before its callback";
  EXPECT_EQ(ChildPool(2, false).free_slots(), 0) << "in this process, one piece at a time";
}

TEST(ChildPool, AChildsWallTimeIsMeasured) {
  ChildPool pool(1, true);
  double seconds = 0.0;
  pool.submit(
      "sleep",
      [] {
        usleep(20000);
        return std::string();
      },
      10.0, [&](const ChildOutcome& o) { seconds = o.seconds; });
  pool.run();
  EXPECT_GE(seconds, 0.02);
}

}  // namespace
}  // namespace bb

namespace bb {
namespace {

// A cancelled piece never calls back: queued, it never runs; running, its child is stopped
// before it ends (it would have left a file behind).
TEST(ChildPool, ACancelledPieceNeverEndsNorCallsBack) {
  const std::string mark = ::testing::TempDir() + "/beachball_cancelled_piece";
  std::remove(mark.c_str());
  ChildPool pool(2, true);
  std::vector<std::string> called;
  const auto record = [&](const ChildOutcome& o) { called.push_back(o.payload); };
  const long slow = pool.submit(
      "slow",
      [mark] {
        sleep(3);
        std::FILE* f = std::fopen(mark.c_str(), "w");
        if (f) std::fclose(f);
        return std::string("slow");
      },
      30.0, record);
  pool.submit(
      "quick", [] { return std::string("quick"); }, 30.0,
      [&](const ChildOutcome& o) {
        record(o);
        pool.cancel(slow);
      });
  const long queued = pool.submit(
      "queued", [] { return std::string("queued"); }, 30.0, record);
  pool.cancel(queued);
  pool.run();
  EXPECT_EQ(called, std::vector<std::string>{"quick"});
  EXPECT_FALSE(std::filesystem::exists(mark)) << "the slow child ran to its end";
}

}  // namespace
}  // namespace bb
