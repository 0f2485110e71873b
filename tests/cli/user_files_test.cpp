// The user's files are never removed, replaced or displaced, whatever their names look
// like and wherever they sit (beside, under, or behind a link to the output folder); and
// no finished run is thrown away for a reason that could be known before it started.
#include <fcntl.h>
#include <gtest/gtest.h>
#include <signal.h>
#include <sys/stat.h>
#include <unistd.h>

#include <chrono>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <thread>

#include "support/program.hpp"
#include "support/temporaries.hpp"
#include "support/test_support.hpp"

namespace bb {
namespace {

namespace fs = std::filesystem;
using test::beachball;
using test::Outcome;

/// A folder with the minimal case in it; returns the folder, the case at `<dir>/<name>.toml`.
std::string folder_with_case(const std::string& dir_name, const std::string& name = "kept") {
  const std::string dir = test::fresh_dir(dir_name);
  test::write_case(dir, name + ".toml", test::minimal_case(name));
  return dir;
}

TEST(UserFiles, AReportRefusesAFolderHoldingTheUsersFilesBeforeAnyRun) {
  const std::string dir = folder_with_case("refuse_foreign");
  const std::string rep = dir + "/rep";
  ASSERT_EQ(beachball("report " + dir + "/kept.toml --no-cost --out " + rep).exit_code, 0);
  fs::create_directories(rep + "/thesis.tmp.1");
  std::ofstream(rep + "/thesis.tmp.1/chapter.tex") << "the user's thesis";
  std::ofstream(rep + "/backup.tmp.2024") << "the user's backup";
  const auto before = test::snapshot(rep);
  const Outcome o = beachball("report " + dir + "/kept.toml --no-cost --out " + rep);
  EXPECT_EQ(o.exit_code, 2) << o.out;
  EXPECT_NE(o.out.find("which beachball did not write there"), std::string::npos) << o.out;
  EXPECT_EQ(test::snapshot(rep), before);
}

TEST(UserFiles, ARunRefusesToReplaceAFileItDidNotWrite) {
  const std::string dir = folder_with_case("refuse_replace");
  const std::string out = dir + "/out";
  fs::create_directories(out);
  std::ofstream(out + "/kept.md") << "the user's notes on this case";
  const Outcome o = beachball("run " + dir + "/kept.toml --no-cost --out " + out);
  EXPECT_EQ(o.exit_code, 2) << o.out;
  EXPECT_NE(o.out.find("kept.md: exists and beachball did not write it"), std::string::npos)
      << o.out;
  EXPECT_EQ(test::bytes(out + "/kept.md"), "the user's notes on this case");
  EXPECT_FALSE(fs::exists(out + "/kept.json")) << "the runs went ahead";
}

TEST(UserFiles, ARunReplacesItsOwnSetAsAWhole) {
  const std::string dir = folder_with_case("replace_own");
  const std::string out = dir + "/out";
  ASSERT_EQ(beachball("run " + dir + "/kept.toml --no-cost --out " + out).exit_code, 0);
  // A plot the second run does not draw (one metric fewer) leaves with the old set.
  std::ofstream(dir + "/kept.toml", std::ios::app) << "\n[report]\nmetrics = [\"velocity_max\"]\n";
  ASSERT_TRUE(fs::exists(out + "/kept-work-precision-position_max.svg"));
  ASSERT_EQ(beachball("run " + dir + "/kept.toml --no-cost --out " + out).exit_code, 0);
  EXPECT_FALSE(fs::exists(out + "/kept-work-precision-position_max.svg"));
  EXPECT_TRUE(fs::exists(out + "/kept-work-precision-velocity_max.svg"));
}

TEST(UserFiles, AReportThroughALinkIsWrittenWhereTheLinkPointsAndTheLinkStays) {
  const std::string dir = folder_with_case("report_link");
  fs::create_directories(dir + "/real");
  fs::create_directory_symlink("real", dir + "/link");
  for (int i = 0; i < 2; ++i) {
    const Outcome o = beachball("report " + dir + "/kept.toml --no-cost --out " + dir + "/link");
    ASSERT_EQ(o.exit_code, 0) << o.out;
    EXPECT_TRUE(fs::is_symlink(dir + "/link"));
    EXPECT_TRUE(fs::exists(dir + "/real/README.md"));
    EXPECT_TRUE(fs::exists(dir + "/real/kept.md"));
  }
  // The folder it holds keeps the permissions it had, not a temporary's.
  EXPECT_EQ(fs::status(dir + "/real").permissions() & fs::perms::others_read,
            fs::perms::others_read);
}

TEST(UserFiles, ARunThroughALinkIsWrittenWhereTheLinkPoints) {
  const std::string dir = folder_with_case("run_link");
  fs::create_directories(dir + "/real");
  fs::create_directory_symlink("real", dir + "/link");
  ASSERT_EQ(beachball("run " + dir + "/kept.toml --no-cost --out " + dir + "/link").exit_code, 0);
  EXPECT_TRUE(fs::is_symlink(dir + "/link"));
  EXPECT_TRUE(fs::exists(dir + "/real/kept.json"));
}

TEST(UserFiles, JunitIntoAFifoIsWrittenIntoItAndTheFifoStays) {
  const std::string dir = folder_with_case("junit_fifo");
  const std::string fifo = dir + "/gates.fifo";
  ASSERT_EQ(mkfifo(fifo.c_str(), 0644), 0);
  std::string read_back;
  std::thread reader([&] { read_back = test::bytes(fifo); });
  const Outcome o = beachball("check " + dir + "/kept.toml --junit " + fifo);
  reader.join();
  EXPECT_EQ(o.exit_code, 0) << o.out;
  EXPECT_NE(read_back.find("<testsuites"), std::string::npos) << read_back;
  struct stat st {};
  ASSERT_EQ(lstat(fifo.c_str(), &st), 0);
  EXPECT_TRUE(S_ISFIFO(st.st_mode));
}

TEST(UserFiles, JunitIntoDevStdoutAppearsOnStdout) {
  const std::string dir = folder_with_case("junit_stdout");
  const Outcome o = beachball("check " + dir + "/kept.toml --junit /dev/stdout");
  EXPECT_EQ(o.exit_code, 0) << o.out;
  EXPECT_NE(o.out.find("<testsuites"), std::string::npos) << o.out;
}

TEST(UserFiles, JunitIntoDevFullFailsAndDevFullStaysADevice) {
  const std::string dir = folder_with_case("junit_full");
  const Outcome o = beachball("check " + dir + "/kept.toml --junit /dev/full");
  EXPECT_EQ(o.exit_code, 2) << o.out;
  EXPECT_NE(o.out.find("No space left on device"), std::string::npos) << o.out;
  struct stat st {};
  ASSERT_EQ(lstat("/dev/full", &st), 0);
  EXPECT_TRUE(S_ISCHR(st.st_mode));
}

TEST(UserFiles, JunitThroughALinkReplacesTheFileAtItsEndAndTheLinkStays) {
  const std::string dir = folder_with_case("junit_link");
  std::ofstream(dir + "/gates.xml") << "old";
  fs::create_symlink("gates.xml", dir + "/link.xml");
  ASSERT_EQ(beachball("check " + dir + "/kept.toml --junit " + dir + "/link.xml").exit_code, 0);
  EXPECT_TRUE(fs::is_symlink(dir + "/link.xml"));
  EXPECT_NE(test::bytes(dir + "/gates.xml").find("<testsuites"), std::string::npos);
  EXPECT_EQ(test::temporaries_in(dir), "");
}

TEST(UserFiles, AReportIntoTheCurrentFolderIsSwitchedInFileByFile) {
  const std::string dir = folder_with_case("report_here");
  const std::string rep = dir + "/rep";
  ASSERT_EQ(beachball("report " + dir + "/kept.toml --no-cost --out " + rep).exit_code, 0);
  std::ofstream(rep + "/kept.md") << "changed";
  const Outcome o = beachball("report ../kept.toml --no-cost --out .", "cd " + rep + " &&");
  ASSERT_EQ(o.exit_code, 0) << o.out;
  EXPECT_NE(o.out.find("it is the current folder"), std::string::npos) << o.out;
  EXPECT_NE(test::bytes(rep + "/kept.md"), "changed");
  EXPECT_EQ(test::temporaries_in(rep), "");
  EXPECT_EQ(test::temporaries_in(dir), "");
}

TEST(UserFiles, AReportIntoAMountPointIsSwitchedInFileByFile) {
  const std::string dir = folder_with_case("report_mount");
  const std::string vol = dir + "/vol";
  fs::create_directories(vol);
  if (std::system("unshare -m true 2>/dev/null") != 0)
    GTEST_SKIP() << "no mount namespace here (needs root)";
  // Two reports into a fresh tmpfs: the first and its replacement.
  const std::string report = std::string(BEACHBALL_PROGRAM) + " report " + dir +
                             "/kept.toml --no-cost --out " + vol + " > " + dir + "/log.txt 2>&1";
  const std::string script = "mount -t tmpfs tmpfs " + vol + " && " + report + " && " + report +
                             " && test -f " + vol + "/kept.md && test -z \"$(ls -A " + vol +
                             " | grep -v manifest | grep beachball-)\"";
  EXPECT_EQ(std::system(("unshare -m sh -c '" + script + "'").c_str()), 0)
      << test::bytes(dir + "/log.txt");
  EXPECT_NE(test::bytes(dir + "/log.txt").find("it is a mount point"), std::string::npos)
      << test::bytes(dir + "/log.txt");
}

TEST(UserFiles, APlotWithNothingFiniteToDrawIsANoteNotAnAbort) {
  const std::string dir = test::fresh_dir("empty_plots");
  // The reference has no answer for a crowd: every plot of a reference-only run is empty.
  Outcome o = beachball("run " + test::source_path("cases/many_beachballs.toml") +
                        " --backends reference --no-cost --out " + dir + "/crowd");
  EXPECT_EQ(o.exit_code, 0) << o.out;
  EXPECT_NE(test::bytes(dir + "/crowd/many_beachballs.md").find("finite"), std::string::npos);
  // A start so large its energy would overflow is refused at load, before any file is written.
  std::string huge = test::minimal_case("huge");
  huge.replace(huge.find("drag_coefficient"), 0, "velocity = [1e300, 0.0, 0.0]\n");
  test::write_case(dir, "huge.toml", huge);
  o = beachball("run " + dir + "/huge.toml --no-cost --out " + dir + "/huge");
  EXPECT_EQ(o.exit_code, 2) << o.out;
  EXPECT_NE(o.out.find("huge.toml:"), std::string::npos) << o.out;
  EXPECT_FALSE(fs::exists(dir + "/huge"));
  // Every run timing out.
  test::write_case(dir, "slow.toml", test::slow_case("slow"));
  o = beachball("run " + dir + "/slow.toml --backends course/rk4 --timeout 0.001 --no-cost --out " +
                dir + "/slow");
  EXPECT_EQ(o.exit_code, 0) << o.out;
  EXPECT_NE(test::bytes(dir + "/slow/slow.json").find("timeout"), std::string::npos);
}

/// The JSON runs of `beachball run` of the stacked balls with the environment `env`.
nlohmann::json stacked_runs(const std::string& dir, const std::string& env) {
  test::write_case(dir, "stack.toml", test::kStackedBalls);
  const Outcome o = beachball("run " + dir + "/stack.toml --no-cost --out " + dir + "/out", env);
  EXPECT_EQ(o.exit_code, 0) << o.out;
  auto j = nlohmann::json::parse(std::ifstream(dir + "/out/stack.json"));
  for (auto& run : j["runs"]) run.erase("cost");
  return j;
}

TEST(UserFiles, WithoutATemporaryFolderTheFallbackErrorsAreTheSame) {
  // Errors measured in the children against the finest run (read from $TMPDIR), or in the
  // parent when $TMPDIR cannot take it: the same numbers, and the method says the same.
  const nlohmann::json with = stacked_runs(test::fresh_dir("tmpdir_ok"), "");
  const nlohmann::json without =
      stacked_runs(test::fresh_dir("tmpdir_missing"), "export TMPDIR=/nonexistent/tmp;");
  EXPECT_EQ(with["runs"], without["runs"]);
  EXPECT_EQ(with["reference"]["method"], without["reference"]["method"]);
  int with_errors = 0;
  for (const auto& run : without["runs"]) with_errors += run["errors"].is_object();
  EXPECT_GT(with_errors, 0);
}

TEST(UserFiles, AKilledRunsScratchFolderGoesAtTheNextRunAndNothingElse) {
  const std::string dir = test::fresh_dir("scratch_cleanup");
  const std::string tmp = dir + "/tmp";
  fs::create_directories(tmp + "/beachball-AbC123");  // a folder of the user's
  const std::string dead = test::abandoned_temporary(tmp, "beachball-scratch-");
  ASSERT_TRUE(fs::exists(dead));
  stacked_runs(dir, "export TMPDIR=" + tmp + ";");
  EXPECT_FALSE(fs::exists(dead));
  EXPECT_TRUE(fs::exists(tmp + "/beachball-AbC123"));
  // The run's own scratch folder went when it was done.
  for (const auto& entry : fs::directory_iterator(tmp))
    EXPECT_NE(entry.path().filename().string().rfind("beachball-scratch-", 0), 0u) << entry.path();
}

TEST(UserFiles, ASecondReportInAnotherPidNamespaceLeavesTheFirstsWorkAlone) {
  const std::string dir = test::fresh_dir("two_namespaces");
  const std::string slow = test::write_case(dir, "slow.toml", test::slow_case("slow"));
  const std::string out = dir + "/out";
  const pid_t first =
      test::start_beachball({"report", slow, "--no-cost", "--out", out}, dir + "/first.log");
  // Wait for the first report's folder beside the output.
  std::string beside;
  for (int i = 0; i < 200 && beside.empty(); ++i) {
    std::this_thread::sleep_for(std::chrono::milliseconds(25));
    std::error_code ec;
    for (const auto& entry : fs::directory_iterator(dir, ec))
      if (entry.path().filename().string().rfind(".beachball-report-", 0) == 0)
        beside = entry.path().string();
  }
  ASSERT_FALSE(beside.empty()) << test::bytes(dir + "/first.log");
  // The second report runs in a PID namespace of its own where one can be made: there the
  // first report's process id means nothing.
  const bool namespaces = std::system("unshare --pid --fork --mount-proc true 2>/dev/null") == 0;
  const std::string second_log = dir + "/second.log";
  const int status = std::system(((namespaces ? "unshare --pid --fork --mount-proc " : "") +
                                  std::string(BEACHBALL_PROGRAM) + " report " + slow +
                                  " --no-cost --out " + out + " > " + second_log + " 2>&1")
                                     .c_str());
  EXPECT_EQ(WEXITSTATUS(status), 2) << test::bytes(second_log);
  EXPECT_NE(test::bytes(second_log).find("another beachball is writing this folder"),
            std::string::npos)
      << test::bytes(second_log);
  EXPECT_TRUE(fs::exists(beside)) << "the second report removed the first's live work";
  kill(first, SIGTERM);
  EXPECT_EQ(test::wait_for(first), 128 + SIGTERM) << test::bytes(dir + "/first.log");
}

TEST(UserFiles, SighupAndSigpipeStopLikeSigterm) {
  const std::string dir = folder_with_case("hangup");
  test::write_case(dir, "slow.toml", test::slow_case("slow"));
  const pid_t pid = test::start_beachball(
      {"report", dir + "/slow.toml", "--no-cost", "--out", dir + "/rep"}, dir + "/log.txt");
  std::this_thread::sleep_for(std::chrono::milliseconds(700));
  kill(pid, SIGHUP);
  EXPECT_EQ(test::wait_for(pid), 128 + SIGHUP) << test::bytes(dir + "/log.txt");
  EXPECT_NE(test::bytes(dir + "/log.txt").find("interrupted by signal 1"), std::string::npos);
  EXPECT_EQ(test::temporaries_in(dir), "");
  // A reader that goes away: the second case's table cannot be printed.
  test::write_case(dir, "other.toml", test::minimal_case("other"));
  const std::string command = std::string("bash -c '") + BEACHBALL_PROGRAM + " run " + dir +
                              "/kept.toml " + dir + "/other.toml --no-cost --out " + dir +
                              "/out 2> " + dir + "/err.txt | head -1 > /dev/null; exit " +
                              "${PIPESTATUS[0]}'";
  const int status = std::system(command.c_str());
  EXPECT_EQ(WEXITSTATUS(status), 128 + SIGPIPE) << test::bytes(dir + "/err.txt");
  EXPECT_NE(test::bytes(dir + "/err.txt").find("interrupted by signal 13"), std::string::npos);
  EXPECT_TRUE(fs::exists(dir + "/out/other.json")) << "the write it had begun was not finished";
}

TEST(UserFiles, TheIndexLinksARotationPlotOnlyWhenOneWasDrawn) {
  const std::string dir = test::fresh_dir("no_gnuplot");
  const Outcome o = beachball(
      "report " + test::source_path("cases/plank_free.toml") + " --no-cost --out " + dir + "/rep",
      "export PATH=/nonexistent;");
  ASSERT_EQ(o.exit_code, 0) << o.out;
  const std::string index = test::bytes(dir + "/rep/README.md");
  EXPECT_EQ(index.find("-rotation.svg"), std::string::npos) << index;
  EXPECT_NE(index.find("No rotation plot was drawn"), std::string::npos) << index;
}

TEST(UserFiles, AStabilitySearchAndARunShareAFolder) {
  const std::string dir = folder_with_case("run_and_stability");
  const std::string out = dir + "/out";
  ASSERT_EQ(beachball("run " + dir + "/kept.toml --no-cost --out " + out).exit_code, 0);
  const std::string run_json = test::bytes(out + "/kept.json");
  ASSERT_EQ(beachball("stability " + dir + "/kept.toml --out " + out).exit_code, 0);
  EXPECT_EQ(test::bytes(out + "/kept.json"), run_json);
  EXPECT_TRUE(fs::exists(out + "/kept-stability.json"));
  EXPECT_TRUE(fs::exists(out + "/kept-stability.md"));
}

}  // namespace
}  // namespace bb
