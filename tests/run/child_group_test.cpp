// Pieces of one group may share a child: fewer processes, each piece still with its own
// payload and console, and a piece that crashes or hangs in a shared child gets the outcome
// its own child gives it (the pieces not yet done run again, one child each).
#include <gtest/gtest.h>
#include <unistd.h>

#include <csignal>
#include <cstdio>
#include <map>
#include <set>
#include <string>

#include "run/child_batch.hpp"
#include "run/child_pool.hpp"

namespace bb {
namespace {

/// Each piece's outcome, by label.
using Outcomes = std::map<std::string, ChildOutcome>;

/// Submits piece `name` of `group`, which prints its name and returns it with its process id.
void submit_printing(ChildPool& pool, Outcomes& out, const std::string& name,
                     const std::string& group, double timeout = 30.0) {
  pool.submit(
      name,
      [name] {
        std::printf("printed by %s\n", name.c_str());
        return name + " " + std::to_string(getpid());
      },
      timeout, [&out, name](const ChildOutcome& o) { out[name] = o; }, 0.0, group);
}

std::string pid_of(const ChildOutcome& o) {
  return o.payload.substr(o.payload.find(' ') + 1);
}

TEST(ChildGroup, APieceKeepsItsOwnPayloadAndConsoleInASharedChild) {
  ChildPool pool(1, true);
  Outcomes out;
  for (const char* name : {"a", "b", "c", "d"}) submit_printing(pool, out, name, "g");
  pool.run();
  ASSERT_EQ(out.size(), 4u);
  std::set<std::string> children;
  for (const auto& [name, o] : out) {
    EXPECT_EQ(o.kind, ChildOutcome::Kind::Done);
    EXPECT_EQ(o.payload.substr(0, o.payload.find(' ')), name);
    EXPECT_EQ(o.console, "printed by " + name + "\n");
    EXPECT_NE(pid_of(o), std::to_string(getpid())) << "ran in a child";
    children.insert(pid_of(o));
  }
  EXPECT_EQ(children.size(), 1u) << "one slot: the group's four pieces share one child";
}

TEST(ChildGroup, PiecesWithoutAGroupOrOfTwoGroupsNeverShare) {
  ChildPool pool(1, true);
  Outcomes out;
  submit_printing(pool, out, "alone-1", "");
  submit_printing(pool, out, "alone-2", "");
  submit_printing(pool, out, "g-1", "g");
  submit_printing(pool, out, "h-1", "h");
  pool.run();
  std::set<std::string> children;
  for (const auto& [name, o] : out) children.insert(pid_of(o));
  EXPECT_EQ(children.size(), 4u);
}

TEST(ChildGroup, AGroupStillSpreadsOverTheSlots) {
  ChildPool pool(2, true);
  Outcomes out;
  for (int k = 0; k < 16; ++k) submit_printing(pool, out, "p" + std::to_string(k), "g");
  pool.run();
  std::set<std::string> children;
  for (const auto& [name, o] : out) children.insert(pid_of(o));
  EXPECT_GE(children.size(), 2u) << "both slots take part";
  EXPECT_LT(children.size(), 16u) << "and the pieces share children";
}

TEST(ChildGroup, ACrashInASharedChildIsThePiecesOwnAndTheOthersAreDone) {
  // The same piece alone, for the outcome its own child gives.
  const auto crashing = [] {
    std::printf("about to abort\n");
    std::fflush(stdout);
    std::abort();
    return std::string();
  };
  ChildOutcome alone;
  {
    ChildPool pool(1, true);
    pool.submit("crash", crashing, 30.0, [&](const ChildOutcome& o) { alone = o; });
    pool.run();
  }
  ChildPool pool(1, true);
  Outcomes out;
  submit_printing(pool, out, "before", "g");
  pool.submit(
      "crash", crashing, 30.0, [&](const ChildOutcome& o) { out["crash"] = o; }, 0.0, "g");
  submit_printing(pool, out, "after", "g");
  pool.run();
  ASSERT_EQ(out.size(), 3u);
  EXPECT_EQ(out["crash"].kind, ChildOutcome::Kind::Crashed);
  EXPECT_EQ(out["crash"].reason, alone.reason);
  EXPECT_EQ(out["crash"].console, alone.console);
  for (const char* name : {"before", "after"}) {
    EXPECT_EQ(out[name].kind, ChildOutcome::Kind::Done) << name;
    EXPECT_EQ(out[name].console, std::string("printed by ") + name + "\n");
  }
  EXPECT_NE(pid_of(out["before"]), pid_of(out["after"])) << "after the crash, its own child";
}

TEST(ChildGroup, AHangInASharedChildTimesOutAloneAndTheOthersAreDone) {
  ChildPool pool(1, true);
  Outcomes out;
  submit_printing(pool, out, "before", "g");
  pool.submit(
      "hang",
      [] {
        pause();
        return std::string();
      },
      0.3, [&](const ChildOutcome& o) { out["hang"] = o; }, 0.0, "g");
  submit_printing(pool, out, "after", "g");
  pool.run();
  EXPECT_EQ(out["hang"].kind, ChildOutcome::Kind::Timeout);
  EXPECT_EQ(out["before"].kind, ChildOutcome::Kind::Done);
  EXPECT_EQ(out["after"].kind, ChildOutcome::Kind::Done);
}

TEST(ChildGroup, AFrameComesOffTheStreamOnlyWhenWhole) {
  const ChildFrame frame{std::string("payload\0bytes", 13), "console", 1.25};
  std::string stream = encode_frame(frame) + encode_frame({"", "", 0.0});
  std::string part = stream.substr(0, 10);
  EXPECT_FALSE(take_frame(part));
  const auto first = take_frame(stream);
  ASSERT_TRUE(first);
  EXPECT_EQ(first->payload, frame.payload);
  EXPECT_EQ(first->console, frame.console);
  EXPECT_EQ(first->seconds, 1.25);
  ASSERT_TRUE(take_frame(stream));
  EXPECT_TRUE(stream.empty());
}

}  // namespace
}  // namespace bb
