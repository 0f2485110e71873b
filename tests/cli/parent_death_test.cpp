// What a SIGKILLed beachball leaves running: nothing. Its pool's children and its gnuplot
// die with it (PR_SET_PDEATHSIG), however long they had left.
#include <gtest/gtest.h>
#include <signal.h>
#include <sys/prctl.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <filesystem>
#include <fstream>
#include <set>
#include <sstream>
#include <thread>

#include "run/child_pool.hpp"
#include "support/program.hpp"
#include "support/test_support.hpp"

namespace bb {
namespace {

namespace fs = std::filesystem;
using Clock = std::chrono::steady_clock;

/// State and parent of a process from /proc/<pid>/stat; state 0 when there is none.
std::pair<char, pid_t> state_and_parent(pid_t pid) {
  std::ifstream stat("/proc/" + std::to_string(pid) + "/stat");
  std::string line;
  if (!std::getline(stat, line)) return {0, 0};
  // The command name in brackets may hold spaces: read after its closing bracket.
  std::istringstream rest(line.substr(line.rfind(')') + 2));
  char state = 0;
  pid_t parent = 0;
  rest >> state >> parent;
  return {state, parent};
}

/// True while `pid` exists and is not a zombie waiting for its reaper.
bool alive(pid_t pid) {
  const char state = state_and_parent(pid).first;
  return state != 0 && state != 'Z';
}

/// The living children of `parent`.
std::set<pid_t> children_of(pid_t parent) {
  std::set<pid_t> out;
  for (const auto& entry : fs::directory_iterator("/proc")) {
    const std::string name = entry.path().filename().string();
    if (name.find_first_not_of("0123456789") != std::string::npos) continue;
    const pid_t pid = std::stoi(name);
    if (state_and_parent(pid).second == parent && alive(pid)) out.insert(pid);
  }
  return out;
}

/// Polls `condition` every 10 ms for up to `seconds`; whether it became true.
template <class Condition>
bool within(double seconds, Condition condition) {
  const auto give_up = Clock::now() + std::chrono::duration<double>(seconds);
  while (!condition()) {
    if (Clock::now() > give_up) return false;
    std::this_thread::sleep_for(std::chrono::milliseconds(10));
  }
  return true;
}

/// While it lives, orphans of the test's processes become the test's children, so it can
/// reap them rather than leave zombies to an init that may not reap.
struct Subreaper {
  Subreaper() { prctl(PR_SET_CHILD_SUBREAPER, 1); }
  ~Subreaper() { prctl(PR_SET_CHILD_SUBREAPER, 0); }
};

/// Kills `parent` with SIGKILL and expects every one of `children` gone within 2 s (the
/// kernel takes microseconds; without PR_SET_PDEATHSIG they would run on).
void kill_and_expect_children_gone(pid_t parent, const std::set<pid_t>& children) {
  kill(parent, SIGKILL);
  test::wait_for(parent);
  for (const pid_t child : children) {
    const bool gone = within(2.0, [&] { return !alive(child); });
    if (!gone) kill(child, SIGKILL);
    EXPECT_TRUE(gone) << "child " << child << " outlived its SIGKILLed parent by 2 s";
    waitpid(child, nullptr, 0);
  }
}

TEST(ParentDeath, AHangingChildOfThePoolDiesWithItsParent) {
  const Subreaper reaper;
  const pid_t parent = fork();
  if (parent == 0) {
    // A "beachball" with one isolated piece of work that hangs under a 600 s limit.
    ChildPool pool(1, true);
    pool.submit(
        "hang",
        [] {
          for (;;) pause();
          return std::string();
        },
        600.0, [](const ChildOutcome&) {});
    pool.run();
    _exit(0);
  }
  std::set<pid_t> children;
  ASSERT_TRUE(within(5.0, [&] { return !(children = children_of(parent)).empty(); }))
      << "the child never started";
  kill_and_expect_children_gone(parent, children);
}

TEST(ParentDeath, TheRunsOfAKilledBeachballStop) {
  const Subreaper reaper;
  // Each run's child works for seconds, far beyond the 2 s the test allows after the kill.
  const std::string dir = test::fresh_dir("parent_death_run");
  const std::string long_case = test::write_case(dir, "long.toml", test::slow_case("long"));
  const pid_t beachball = test::start_beachball(
      {"run", long_case, "--backends", "course/rk4", "--no-cost", "--out", dir + "/out"},
      dir + "/log.txt");
  // Wait for a child that has lived 300 ms: one in the middle of its work.
  std::set<pid_t> children;
  const bool settled = within(10.0, [&] {
    const std::set<pid_t> before = children_of(beachball);
    std::this_thread::sleep_for(std::chrono::milliseconds(300));
    children.clear();
    for (const pid_t child : children_of(beachball))
      if (before.count(child)) children.insert(child);
    return !children.empty();
  });
  if (!settled) kill(beachball, SIGKILL);
  ASSERT_TRUE(settled) << test::bytes(dir + "/log.txt");
  kill_and_expect_children_gone(beachball, children);
}

TEST(ParentDeath, AHangingGnuplotDiesWithAKilledReport) {
  const Subreaper reaper;
  const std::string dir = test::fresh_dir("parent_death_gnuplot");
  const std::string gnuplot = test::write_case(
      dir + "/bin", "gnuplot", "#!/bin/sh\n[ \"$1\" = --version ] && exit 0\nexec sleep 60\n");
  chmod(gnuplot.c_str(), 0755);
  const std::string kept = test::write_case(dir, "kept.toml", test::minimal_case("kept"));
  const pid_t beachball = fork();
  if (beachball == 0) {
    const char* path = getenv("PATH");
    setenv("PATH", (dir + "/bin:" + (path ? path : "/usr/bin:/bin")).c_str(), 1);
    execl(BEACHBALL_PROGRAM, BEACHBALL_PROGRAM, "report", kept.c_str(), "--no-cost", "--out",
          (dir + "/out").c_str(), static_cast<char*>(nullptr));
    _exit(127);
  }
  // The sleeping gnuplot is the only child left once the runs are done.
  std::set<pid_t> children;
  const bool plotting = within(10.0, [&] {
    children = children_of(beachball);
    if (children.size() != 1) return false;
    std::ifstream comm("/proc/" + std::to_string(*children.begin()) + "/comm");
    std::string name;
    return std::getline(comm, name) && name == "sleep";
  });
  if (!plotting) kill(beachball, SIGKILL);
  ASSERT_TRUE(plotting) << "gnuplot never started";
  kill_and_expect_children_gone(beachball, children);
}

}  // namespace
}  // namespace bb
