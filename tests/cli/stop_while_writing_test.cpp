// A signal while a command writes its outputs stops it at once and rolls the write back:
// a cached report's pages and a merge's (whose runs all come from kept results, so writing
// is most of their time) stop within a fraction of a second, leaving no report, no empty
// --out and no temporaries; a killed merge leaves nothing in $TMPDIR (it copies nothing
// there); and a file past `ulimit -f` stops a run as a signal does, saying so.
#include <gtest/gtest.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <filesystem>
#include <optional>
#include <sstream>

#include "support/program.hpp"
#include "support/test_support.hpp"

namespace bb {
namespace {

namespace fs = std::filesystem;

/// Whether a report's pages are being written under `parent`: a batch's staging folder in
/// the folder built beside the report.
bool writing_pages(const std::string& parent) {
  std::error_code ec;
  for (const auto& beside : fs::directory_iterator(parent, ec)) {
    if (beside.path().filename().string().rfind(".beachball-report-", 0) != 0) continue;
    std::error_code inner_ec;
    for (const auto& inner : fs::directory_iterator(beside.path(), inner_ec))
      if (inner.path().filename().string().rfind(".beachball-staging-", 0) == 0) return true;
  }
  return false;
}

struct Stopped {
  int exit_code = -1;
  double seconds = -1.0;  ///< from the signal to the exit; -1: it ended before the signal
};

/// Sends `signal` to `pid` as soon as its report's pages are being written under `parent`.
Stopped stop_while_writing(pid_t pid, const std::string& parent, int signal) {
  int status = 0;
  while (!writing_pages(parent)) {
    if (waitpid(pid, &status, WNOHANG) == pid)
      return {WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status), -1.0};
    usleep(200);
  }
  kill(pid, signal);
  const auto sent = std::chrono::steady_clock::now();
  const int code = test::wait_for(pid);
  return {code, std::chrono::duration<double>(std::chrono::steady_clock::now() - sent).count()};
}

/// $TMPDIR set to `value` while it lives (a failed assertion returns early: it is unset).
struct TmpdirAs {
  explicit TmpdirAs(const std::string& value) { setenv("TMPDIR", value.c_str(), 1); }
  ~TmpdirAs() { unsetenv("TMPDIR"); }
};

/// Three cases: two minimal ones and the stacked balls (no reference: the fallback).
std::string three_cases(const std::string& dir) {
  return test::write_case(dir, "a.toml", test::minimal_case("a")) + " " +
         test::write_case(dir, "b.toml", test::minimal_case("b")) + " " +
         test::write_case(dir, "stack.toml", test::kStackedBalls);
}

std::vector<std::string> words(const std::string& text) {
  std::vector<std::string> out;
  std::istringstream in(text);
  for (std::string w; in >> w;) out.push_back(w);
  return out;
}

TEST(StopWhileWriting, ACachedReportStopsAtOnceAndWritesNothing) {
  const std::string dir = test::fresh_dir("stop_cached_report");
  const std::string cases = three_cases(dir);
  const std::string cache = dir + "/cache";
  const test::Outcome first = test::beachball("report " + cases + " --no-cost --cache " + cache +
                                              " --out " + dir + "/first");
  ASSERT_EQ(first.exit_code, 0) << first.out;
  std::vector<std::string> args = {"report"};
  for (const std::string& c : words(cases)) args.push_back(c);
  for (const char* a : {"--no-cost", "--cache"}) args.push_back(a);
  args.push_back(cache);
  args.push_back("--out");
  args.push_back(dir + "/second");
  const std::string log = dir + "/second.log";
  const Stopped s = stop_while_writing(test::start_beachball(args, log), dir, SIGTERM);
  ASSERT_GE(s.seconds, 0.0) << "the report ended before its pages were written: "
                            << test::bytes(log);
  EXPECT_EQ(s.exit_code, 128 + SIGTERM) << test::bytes(log);
  EXPECT_LT(s.seconds, 5.0);
  EXPECT_NE(test::bytes(log).find("interrupted by signal 15"), std::string::npos)
      << test::bytes(log);
  EXPECT_FALSE(fs::exists(dir + "/second")) << "a report, or an empty --out, was left";
  EXPECT_EQ(test::temporaries_in(dir), "");
}

TEST(StopWhileWriting, AMergeStopsAtOnceAndLeavesNothingBehind) {
  const std::string dir = test::fresh_dir("stop_merge");
  const std::string cases = three_cases(dir);
  for (int i = 1; i <= 2; ++i) {
    const test::Outcome o =
        test::beachball("report " + cases + " --no-cost --shard " + std::to_string(i) +
                        "/2 --out " + dir + "/shard" + std::to_string(i));
    ASSERT_EQ(o.exit_code, 0) << o.out;
  }
  // Its temporary folders, if it made any, would go to $TMPDIR.
  const std::string tmp = dir + "/tmp";
  fs::create_directories(tmp);
  std::optional<TmpdirAs> tmpdir(tmp);
  const auto merge = [&](const std::string& out) {
    std::vector<std::string> args = {"merge", dir + "/shard1", dir + "/shard2", "--cases"};
    for (const std::string& c : words(cases)) args.push_back(c);
    args.push_back("--out");
    args.push_back(dir + "/" + out);
    return test::start_beachball(args, dir + "/" + out + ".log");
  };
  const Stopped term = stop_while_writing(merge("merged"), dir, SIGTERM);
  ASSERT_GE(term.seconds, 0.0) << test::bytes(dir + "/merged.log");
  EXPECT_EQ(term.exit_code, 128 + SIGTERM) << test::bytes(dir + "/merged.log");
  EXPECT_LT(term.seconds, 5.0);
  EXPECT_FALSE(fs::exists(dir + "/merged"));
  EXPECT_EQ(test::temporaries_in(dir), "");
  // Killed outright, it leaves nothing in $TMPDIR either (the next merge would clear what
  // it leaves beside its --out).
  const Stopped killed = stop_while_writing(merge("killed"), dir, SIGKILL);
  ASSERT_GE(killed.seconds, 0.0) << test::bytes(dir + "/killed.log");
  EXPECT_EQ(killed.exit_code, 128 + SIGKILL);
  EXPECT_TRUE(fs::is_empty(tmp)) << test::temporaries_in(tmp);
  // Without a usable $TMPDIR a merge works all the same.
  tmpdir.emplace(dir + "/no such folder");
  const pid_t whole = merge("whole");
  EXPECT_EQ(test::wait_for(whole), 0) << test::bytes(dir + "/whole.log");
  EXPECT_TRUE(fs::exists(dir + "/whole/README.md"));
}

TEST(StopWhileWriting, AFilePastTheSizeLimitStopsARunAsASignalDoes) {
  const std::string dir = test::fresh_dir("file_size_limit");
  const std::string a = test::write_case(dir, "a.toml", test::minimal_case("a"));
  // 1 KiB: far less than the case's results (its output is a pipe, not limited).
  const test::Outcome o =
      test::beachball("run " + a + " --no-cost --out " + dir + "/out", "ulimit -f 2;");
  EXPECT_EQ(o.exit_code, 128 + SIGXFSZ) << o.out;
  EXPECT_NE(o.out.find("file size limit reached"), std::string::npos) << o.out;
  EXPECT_FALSE(fs::exists(dir + "/out")) << "files, or an empty --out, were left";
}

}  // namespace
}  // namespace bb
