// `run --trajectories` (docs/output-files.md#trajectories): one file per run in
// <out>/<case>-trajectories/, named by backend and dt, each the run made here byte for byte;
// the folder is the run's own set (replaced whole, removed with the set), a user's file in
// it stops the run before any work, kept results run again, and a file that cannot be
// written stops the command.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <set>

#include "files/folder_manifest.hpp"
#include "run/accuracy_run.hpp"
#include "run/registry.hpp"
#include "run/trajectory_writer.hpp"
#include "support/program.hpp"
#include "support/test_support.hpp"

namespace bb {
namespace {

namespace fs = std::filesystem;
using test::beachball;
using test::Outcome;

/// The names in `folder`, its record included.
std::set<std::string> names_in(const std::string& folder) {
  std::set<std::string> names;
  for (const auto& entry : fs::directory_iterator(folder))
    names.insert(entry.path().filename().string());
  return names;
}

/// The file `backend` writes at `dt` (the reference at its samples: no dt), written here.
std::string written_here(const Scene& scene, const std::string& backend, double dt,
                         const std::string& path) {
  const Registry registry = Registry::load();
  const BackendSet set = backends_for(scene, registry);
  const Backend* chosen = &registry.reference();
  for (const Backend* b : set.all)
    if (b->name() == backend) chosen = b;
  EXPECT_EQ(chosen->name(), backend);
  TrajectoryWriter writer(path, scene);
  run_accuracy(*chosen, scene, dt, false, &writer);
  EXPECT_EQ(writer.close(), "");
  return test::bytes(path);
}

/// A folder with the minimal case (one ball falling in air, dt 0.1 s and 0.05 s) as
/// `<dir>/traj.toml`; returns the folder.
std::string folder_with_minimal_case(const std::string& name) {
  const std::string dir = test::fresh_dir(name);
  test::write_case(dir, "traj.toml", test::minimal_case("traj"));
  return dir;
}

constexpr const char* kOneBackend = " --no-cost --backends course/explicit-euler";

TEST(Trajectories, AFilePerRunNamedByBackendAndDtHoldsTheRunItself) {
  const std::string dir = folder_with_minimal_case("trajectories_files");
  const std::string out = dir + "/out";
  const Outcome o =
      beachball("run " + dir + "/traj.toml" + kOneBackend + " --trajectories --out " + out);
  ASSERT_EQ(o.exit_code, 0) << o.out;
  const std::string folder = out + "/traj-trajectories";
  EXPECT_EQ(names_in(folder), (std::set<std::string>{".beachball-manifest", "reference.csv",
                                                     "course-explicit-euler@1-10.csv",
                                                     "course-explicit-euler@1-20.csv"}));
  EXPECT_TRUE(read_manifest(out).count("traj-trajectories"));
  EXPECT_TRUE(holds_only_recorded_files(folder));
  EXPECT_NE(o.out.find("traj-trajectories/: 3 files"), std::string::npos) << o.out;
  // Each file is the run of the same backend made here, to the byte.
  const Scene scene = load_case(dir + "/traj.toml");
  EXPECT_EQ(test::bytes(folder + "/course-explicit-euler@1-20.csv"),
            written_here(scene, "course/explicit-euler", 0.05, dir + "/here-euler.csv"));
  EXPECT_EQ(test::bytes(folder + "/reference.csv"),
            written_here(scene, "reference", scene.sample, dir + "/here-reference.csv"));
}

TEST(Trajectories, ASecondRunReplacesTheFolderAndARunWithoutTheOptionRemovesIt) {
  const std::string dir = folder_with_minimal_case("trajectories_replaced");
  const std::string run = "run " + dir + "/traj.toml" + kOneBackend + " --out " + dir + "/out";
  const std::string folder = dir + "/out/traj-trajectories";
  ASSERT_EQ(beachball(run + " --trajectories").exit_code, 0);
  ASSERT_TRUE(fs::exists(folder + "/course-explicit-euler@1-20.csv"));
  const Outcome fewer = beachball(run + " --trajectories --dt 0.1");
  ASSERT_EQ(fewer.exit_code, 0) << fewer.out;
  EXPECT_EQ(names_in(folder), (std::set<std::string>{".beachball-manifest", "reference.csv",
                                                     "course-explicit-euler@1-10.csv"}));
  const Outcome without = beachball(run);
  ASSERT_EQ(without.exit_code, 0) << without.out;
  EXPECT_FALSE(fs::exists(folder)) << "trajectories of runs no longer in the set stayed";
  EXPECT_FALSE(read_manifest(dir + "/out").count("traj-trajectories"));
  EXPECT_TRUE(fs::exists(dir + "/out/traj.json"));
}

TEST(Trajectories, AUsersFileInTheFolderStopsTheRunBeforeAnyWork) {
  const std::string dir = folder_with_minimal_case("trajectories_users_file");
  const std::string out = dir + "/out";
  const std::string run = "run " + dir + "/traj.toml" + kOneBackend + " --out " + out;
  ASSERT_EQ(beachball(run + " --trajectories").exit_code, 0);
  std::ofstream(out + "/traj-trajectories/my-plot.csv") << "the user's";
  fs::remove(out + "/traj.json");
  const auto before = test::snapshot(out);
  // Written again or removed with the set, the folder would take the user's file with it.
  for (const std::string option : {" --trajectories", ""}) {
    const Outcome o = beachball(run + option);
    EXPECT_EQ(o.exit_code, 2) << option << ": " << o.out;
    EXPECT_NE(o.out.find("traj-trajectories/my-plot.csv: exists and beachball did not write it"),
              std::string::npos)
        << o.out;
    EXPECT_EQ(test::snapshot(out), before) << option;
  }
  // A folder of that name beachball did not write: refused with the option, left alone
  // without it.
  const std::string other = dir + "/other";
  fs::create_directories(other + "/traj-trajectories");
  std::ofstream(other + "/traj-trajectories/mine.csv") << "the user's";
  const std::string run_other = "run " + dir + "/traj.toml" + kOneBackend + " --out " + other;
  const Outcome refused = beachball(run_other + " --trajectories");
  EXPECT_EQ(refused.exit_code, 2) << refused.out;
  EXPECT_FALSE(fs::exists(other + "/traj.json")) << "the runs went ahead";
  ASSERT_EQ(beachball(run_other).exit_code, 0);
  EXPECT_EQ(test::bytes(other + "/traj-trajectories/mine.csv"), "the user's");
}

TEST(Trajectories, KeptResultsRunAgainToWriteTheirSteps) {
  const std::string dir = folder_with_minimal_case("trajectories_kept");
  const std::string run = "run " + dir + "/traj.toml" + kOneBackend + " --cache " + dir +
                          "/cache --out " + dir + "/out";
  ASSERT_EQ(beachball(run).exit_code, 0);
  const Outcome o = beachball(run + " --trajectories");
  ASSERT_EQ(o.exit_code, 0) << o.out;
  EXPECT_NE(o.out.find("every run ran: kept results hold no steps"), std::string::npos) << o.out;
  // Every run with a file ran (the reference's self-check, which has none, may be reused).
  const int files = static_cast<int>(names_in(dir + "/out/traj-trajectories").size()) - 1;
  EXPECT_EQ(files, 3);
  EXPECT_EQ(test::kept_counts(o.out).second, files) << o.out;
  // The results of those runs are the kept ones: an invocation without the option reuses
  // them all.
  const Outcome again = beachball(run);
  EXPECT_EQ(test::kept_counts(again.out).second, 0) << again.out;
}

TEST(Trajectories, AFileThatCannotBeWrittenStopsTheCommandWithNothingWritten) {
  const std::string dir = test::fresh_dir("trajectories_too_large");
  std::string text = test::minimal_case("big");
  for (const auto& [from, to] :
       {std::pair<std::string, std::string>{"dt = [0.1, 0.05]", "dt = [0.001]"},
        {"report_dt = 0.05", "report_dt = 0.001"}})
    text.replace(text.find(from), from.size(), to);
  const std::string path = test::write_case(dir, "big.toml", text);
  // 16 KiB: far less than a thousand steps' rows, more than the reference's eleven.
  const Outcome o = beachball("run " + path + kOneBackend + " --trajectories --out " + dir + "/out",
                              "ulimit -f 16;");
  EXPECT_EQ(o.exit_code, 2) << o.out;
  EXPECT_NE(o.out.find("File too large"), std::string::npos) << o.out;
  EXPECT_FALSE(fs::exists(dir + "/out")) << "files, or an empty --out, were left";
}

TEST(Trajectories, AReportReplacesAFolderWhereRunWroteTrajectories) {
  const std::string dir = folder_with_minimal_case("trajectories_then_report");
  const std::string out = dir + "/out";
  ASSERT_EQ(beachball("run " + dir + "/traj.toml" + kOneBackend + " --trajectories --out " + out)
                .exit_code,
            0);
  const Outcome o = beachball("report " + dir + "/traj.toml --no-cost --out " + out);
  EXPECT_EQ(o.exit_code, 0) << o.out;
  EXPECT_FALSE(fs::exists(out + "/traj-trajectories"));
  EXPECT_TRUE(fs::exists(out + "/README.md"));
}

TEST(Trajectories, TheOptionDoesNotGoWithAShard) {
  const std::string dir = folder_with_minimal_case("trajectories_shard");
  const Outcome o =
      beachball("run " + dir + "/traj.toml --trajectories --shard 1/2 --out " + dir + "/shard");
  EXPECT_EQ(o.exit_code, 2) << o.out;
  EXPECT_FALSE(fs::exists(dir + "/shard"));
}

}  // namespace
}  // namespace bb
