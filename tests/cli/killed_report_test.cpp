// A report SIGKILLed at any moment, the write phase included, leaves either the previous
// report byte for byte or the complete new one, never a mix: the new report is built in a
// folder of beachball's own beside the old one and exchanged with it in one renameat2.
// Whatever the killed report left behind goes at the next run, and only that.
#include <gtest/gtest.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <filesystem>
#include <fstream>
#include <map>
#include <set>
#include <thread>

#include "files/file_batch.hpp"
#include "files/folder_manifest.hpp"
#include "support/program.hpp"
#include "support/temporaries.hpp"
#include "support/test_support.hpp"

namespace bb {
namespace {

namespace fs = std::filesystem;
using Clock = std::chrono::steady_clock;

/// Whether `pid` has ended (it stays waitable).
bool ended(pid_t pid) {
  siginfo_t info{};
  return waitid(P_PID, pid, &info, WEXITED | WNOHANG | WNOWAIT) == 0 && info.si_pid == pid;
}

/// Whether a report writing under `dir` has begun to write: a file waiting in the "new"
/// folder of one of its batches.
bool writing(const fs::path& dir) {
  std::error_code ec;
  for (auto it = fs::recursive_directory_iterator(dir, ec); !ec && it != fs::end(it);
       it.increment(ec))
    if (it->path().parent_path().filename() == "new" &&
        test::beachball_temporary(it->path().parent_path().parent_path().filename().string()))
      return true;
  return false;
}

/// Waits until report `pid` begins to write under `dir`; false when it ended first or did
/// not begin within 10 s.
bool wait_for_writing(pid_t pid, const fs::path& dir) {
  for (const Clock::time_point give_up = Clock::now() + std::chrono::seconds(10);
       Clock::now() < give_up && !ended(pid);) {
    if (writing(dir)) return true;
    std::this_thread::sleep_for(std::chrono::microseconds(500));
  }
  return false;
}

/// An old report as a report folder may hold it: the pages of a case "gone" and, under the
/// names the new report writes, other bytes; and its record of them.
void write_old_report(const fs::path& folder, const std::map<std::string, std::string>& fresh) {
  fs::create_directories(folder);
  std::set<std::string> names;
  for (const auto& [name, bytes] : fresh)
    if (name != kManifestName) names.insert(name);
  for (const char* name : {"gone.md", "gone.json", "gone.csv", "gone-energy.svg"})
    names.insert(name);
  for (const std::string& name : names) std::ofstream(folder / name) << "old " << name << "\n";
  std::ofstream(folder / kManifestName) << manifest_text(names);
}

TEST(KilledReport, SigkillAtAnyMomentLeavesTheOldOrTheNewReportAndTheNextRunClearsUp) {
  const fs::path dir = test::fresh_dir("killed_report");
  const std::string kept = test::write_case(dir, "kept.toml", test::minimal_case("kept"));
  const std::string log = (dir / "log.txt").string();
  const auto report = [&](const fs::path& out) {
    return test::start_beachball({"report", kept, "--no-cost", "--out", out.string()}, log);
  };
  // One report unkilled: the new report, and how long its write phase takes.
  const pid_t first = report(dir / "new");
  ASSERT_TRUE(wait_for_writing(first, dir)) << test::bytes(log);
  const Clock::time_point writing = Clock::now();
  ASSERT_EQ(test::wait_for(first), 0) << test::bytes(log);
  const Clock::duration write_phase = Clock::now() - writing;
  const auto new_report = test::snapshot(dir / "new");
  write_old_report(dir / "old", new_report);
  const auto old_report = test::snapshot(dir / "old");

  const fs::path out = dir / "out";
  int old_seen = 0, new_seen = 0, left_temporaries = 0;
  const auto kill_and_look = [&](pid_t pid, const std::string& when) {
    kill(pid, SIGKILL);
    test::wait_for(pid);
    const auto now = test::snapshot(out);
    const bool is_old = now == old_report, is_new = now == new_report;
    EXPECT_TRUE(is_old || is_new) << "killed " << when << ": a mix of old and new";
    // Which files are neither the old report's nor the new one's, to tell a mix from a
    // report whose bytes changed between runs.
    if (!is_old && !is_new)
      for (const auto& [name, bytes] : now) {
        const auto o = old_report.find(name), n = new_report.find(name);
        if ((o == old_report.end() || o->second != bytes) &&
            (n == new_report.end() || n->second != bytes))
          ADD_FAILURE() << name << " is neither the old report's nor the new one's";
      }
    old_seen += is_old;
    new_seen += is_new;
    left_temporaries += !test::temporaries_in(dir).empty();
  };
  // Kills while the cases run, then at quarters of the write phase from its first file on,
  // until one comes too late to stop the report.
  for (const int ms : {0, 100}) {
    fs::remove_all(out);
    fs::copy(dir / "old", out);
    const pid_t pid = report(out);
    std::this_thread::sleep_for(std::chrono::milliseconds(ms));
    kill_and_look(pid, "after " + std::to_string(ms) + " ms");
  }
  for (int quarter = 0; quarter < 40 && (quarter <= 5 || new_seen == 0); ++quarter) {
    fs::remove_all(out);
    fs::copy(dir / "old", out);
    const pid_t pid = report(out);
    wait_for_writing(pid, dir);
    std::this_thread::sleep_for(write_phase * quarter / 4);
    kill_and_look(pid, std::to_string(quarter) + " quarters into writing");
  }
  // Both ends were reached, and kills during writing left temporaries behind.
  EXPECT_GT(old_seen, 0);
  EXPECT_GT(new_seen, 0);
  EXPECT_GT(left_temporaries, 0);

  // One more run clears what dead processes left, inside and beside the folder, and
  // nothing else: a folder beside it whose name only looks like a temporary is the user's.
  const std::string dead_staging = test::abandoned_temporary(out.string(), kStagingPrefix);
  const std::string dead_beside = test::abandoned_temporary(dir.string(), ".beachball-report-");
  ASSERT_TRUE(fs::exists(dead_staging) && fs::exists(dead_beside));
  fs::create_directories(dir / "out.tmp.999999999");
  std::ofstream(dir / "out.tmp.999999999" / "kept.md") << "the user's own folder";
  ASSERT_EQ(test::wait_for(report(out)), 0) << test::bytes(log);
  EXPECT_EQ(test::snapshot(out), new_report);
  EXPECT_EQ(test::temporaries_in(dir), "");
  EXPECT_EQ(test::temporaries_in(out), "");
  EXPECT_TRUE(fs::exists(dir / "out.tmp.999999999" / "kept.md"));
}

// Only what beachball can prove is an abandoned temporary of its own goes: a living
// process's temporaries stay (it may be writing them), and so does every file of the
// user's, whatever its name looks like.
TEST(KilledReport, TheNextRunKeepsTheTemporariesOfLivingProcessesAndTheUsersFiles) {
  const fs::path dir = test::fresh_dir("living_temporaries");
  const std::string kept = test::write_case(dir, "kept.toml", test::minimal_case("kept"));
  const fs::path out = dir / "out";
  fs::create_directories(out / "mydata.tmp.3999999");
  std::ofstream(out / "mydata.tmp.3999999" / "file.txt") << "the user's data";
  std::ofstream(out / "notes.tmp.77777") << "the user's notes";
  std::ofstream(out / "kept.md.tmp.999999999") << "the user's file";
  const OwnedTemporary living(out.string(), kStagingPrefix);
  const std::string dead = test::abandoned_temporary(out.string(), kStagingPrefix);
  const test::Outcome o = test::beachball("run " + kept + " --no-cost --out " + out.string());
  ASSERT_EQ(o.exit_code, 0) << o.out;
  EXPECT_TRUE(fs::exists(living.path()));
  EXPECT_FALSE(fs::exists(dead));
  EXPECT_EQ(test::bytes(out / "mydata.tmp.3999999" / "file.txt"), "the user's data");
  EXPECT_EQ(test::bytes(out / "notes.tmp.77777"), "the user's notes");
  EXPECT_EQ(test::bytes(out / "kept.md.tmp.999999999"), "the user's file");
  EXPECT_TRUE(fs::exists(out / "kept.md"));
}

}  // namespace
}  // namespace bb
