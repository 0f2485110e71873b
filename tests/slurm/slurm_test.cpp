// The Slurm job array of docs/design.md (Shards), run for real: a one-node cluster on
// localhost, started here in a temporary folder (its own munged, slurmctld and slurmd, on
// free ports, nothing system-wide touched: slurm_cluster.hpp), runs scripts/slurm/submit: the array
// of shards (scripts/slurm/report.sbatch) and the merge that depends on it; the merged report is
// the report run whole, byte for byte; and the by-hand example of the same section, its two sbatch
// lines run as written; and a map (two [[sweep]]s) sharded over the array point by point, merged
// byte-identical to the map run whole. Skipped, with the reason, where Slurm is not installed
// (Debian's slurm-wlm); a cluster that fails to start is a failure, with the daemons' logs.
#include <gtest/gtest.h>

#include <chrono>
#include <cstdlib>
#include <filesystem>
#include <nlohmann/json.hpp>
#include <string>
#include <thread>
#include <vector>

#include "slurm/slurm_cluster.hpp"
#include "support/program.hpp"
#include "support/spring_pair_case.hpp"
#include "support/test_support.hpp"

namespace bb {
namespace {

namespace fs = std::filesystem;
using namespace std::chrono_literals;

/// The cluster, up before each test's body runs.
class Slurm : public test::SlurmCluster {};

TEST_F(Slurm, AJobArrayOfShardsMergedIsTheReportUnsplit) {
  const std::string& dir = dir_;
  test::Cluster& cluster = *cluster_;

  // Two cases, three shards, each a task of the array the committed scripts submit; the
  // merge is the job depending on it, waited for (bounded: a stuck job is a failure, with
  // the queue as it was).
  const std::string work = dir + "/work";
  const std::string cases = test::write_case(work, "a.toml", test::minimal_case("a")) + " " +
                            test::write_case(work, "stack.toml", test::kStackedBalls);
  const test::Outcome submitted =
      test::shell("cd " + work + " && timeout 300 " + test::source_path("scripts/slurm/submit") +
                  " -n 3 --out merged --program " + BEACHBALL_PROGRAM +
                  " --report-args --no-cost --wait " + cases);
  const auto job_logs = [&] {
    std::string out = "\n--- queue:\n" + test::shell("squeue").out;
    if (fs::exists(work + "/merged.shards/logs"))
      for (const auto& [name, bytes] : test::snapshot(work + "/merged.shards/logs"))
        out += "\n--- " + name + ":\n" + bytes;
    return out + cluster.logs();
  };
  ASSERT_EQ(submitted.exit_code, 0) << submitted.out << job_logs();
  EXPECT_NE(submitted.out.find("shards: job"), std::string::npos) << submitted.out;

  const test::Outcome whole =
      test::beachball("report " + cases + " --no-cost --out " + work + "/whole");
  ASSERT_EQ(whole.exit_code, 0) << whole.out;
  const auto merged = test::snapshot(work + "/merged"), unsplit = test::snapshot(work + "/whole");
  ASSERT_GT(unsplit.size(), 5u);
  EXPECT_EQ(merged, unsplit) << job_logs();
  for (int i = 1; i <= 3; ++i)
    EXPECT_TRUE(fs::exists(work + "/merged.shards/" + std::to_string(i) + "/beachball-shard.txt"))
        << i;
}

// A map's points spread over the array (each point a unit of a shard, sweep_runner.hpp): three
// tasks each run their share of a 3 x 3 spring map's points (every backend: `report` takes
// no --backends), the merge job puts them together,
// and the report is the map run whole in one process, byte for byte: its results, its page, the
// small multiples and each backend's map with the theory's line.
TEST_F(Slurm, AMapShardedOverAJobArrayMergedIsTheMapUnsplit) {
  const std::string work = dir_ + "/work";
  const std::string map = test::write_case(
      work, "spring_map.toml",
      test::spring_pair_case("spring_map", "0.1", "[0.1, 0.05]", "0.05") + R"([course]
integrators = ["explicit-euler", "semi-implicit-euler"]
[[observe]]
kind = "max_stretch"
[[sweep]]
parameter = "spring.1.stiffness"
values = [40.0, 300.0, 900.0]
onset = "max_stretch"
onset_above = 2.0
[[sweep]]
parameter = "dt"
values = [0.1, 0.05, 0.02]
)");
  const std::string options = "--no-cost";
  const test::Outcome submitted =
      test::shell("cd " + work + " && timeout 300 " + test::source_path("scripts/slurm/submit") +
                  " -n 3 --out merged --program " + BEACHBALL_PROGRAM + " --report-args \"" +
                  options + "\" --wait " + map);
  const auto job_logs = [&] {
    std::string out = "\n--- queue:\n" + test::shell("squeue").out;
    if (fs::exists(work + "/merged.shards/logs"))
      for (const auto& [name, bytes] : test::snapshot(work + "/merged.shards/logs"))
        out += "\n--- " + name + ":\n" + bytes;
    return out + logs();
  };
  ASSERT_EQ(submitted.exit_code, 0) << submitted.out << job_logs();

  const test::Outcome whole =
      test::beachball("report " + map + " " + options + " --out " + work + "/whole");
  ASSERT_EQ(whole.exit_code, 0) << whole.out;
  const auto merged = test::snapshot(work + "/merged"), unsplit = test::snapshot(work + "/whole");
  ASSERT_TRUE(unsplit.count("spring_map.json") && unsplit.count("spring_map-map.svg") &&
              unsplit.count("spring_map-map-course-semi-implicit-euler.svg"))
      << whole.out;
  EXPECT_NE(unsplit.at("spring_map-map-course-semi-implicit-euler.svg").find("<polyline"),
            std::string::npos);
  EXPECT_EQ(merged, unsplit) << job_logs();
  for (int i = 1; i <= 3; ++i)
    EXPECT_TRUE(fs::exists(work + "/merged.shards/" + std::to_string(i) + "/beachball-shard.txt"))
        << i;
}

/// The fenced block of docs/design.md that follows `after`, as the shell would run it.
std::string doc_example(const std::string& after) {
  const std::string doc = test::bytes(test::source_path("docs/design.md"));
  const std::size_t at = doc.find(after);
  if (at == std::string::npos) return "";
  const std::size_t open = doc.find("```", at);
  const std::size_t first = doc.find('\n', open) + 1;
  return doc.substr(first, doc.find("```", first) - first);
}

/// PATH without the folders that hold a `beachball`: the example must find the build itself.
std::string path_without_beachball() {
  const char* env = std::getenv("PATH");
  const std::string dirs = env ? env : "";
  std::string kept;
  for (std::size_t start = 0; start <= dirs.size();) {
    const std::size_t end = std::min(dirs.find(':', start), dirs.size());
    const std::string dir = dirs.substr(start, end - start);
    std::error_code unreadable;
    if (!dir.empty() && !fs::exists(fs::path(dir) / "beachball", unreadable))
      kept += (kept.empty() ? "" : ":") + dir;
    start = end + 1;
  }
  return kept;
}

/// A job's state as scontrol shows it ("COMPLETED", "PENDING", ...; "" once forgotten).
std::string job_state(const std::string& scontrol, const std::string& id) {
  const std::string shown = test::shell(scontrol + " show job " + id + " 2>/dev/null").out;
  const std::size_t at = shown.find("JobState=");
  if (at == std::string::npos) return "";
  return shown.substr(at + 9, shown.find_first_of(" \n", at) - at - 9);
}

// The by-hand example of docs/design.md, run as written from a folder laid out as the
// repository's root (the script, a build in build/bin and a cases/ folder of two small cases,
// not the bundled suite), with no beachball in PATH: every shard runs, the merge runs after
// them, and the report has every case's page and results. It failed as written: every task
// said "exec: beachball: not found" and the merge pended for ever on a dependency that could
// no longer be met.
TEST_F(Slurm, TheByHandExampleOfTheDesignRunsAsWritten) {
  const std::string example = doc_example("Or by hand");
  ASSERT_NE(example.find("sbatch"), std::string::npos) << "no example found:\n" << example;
  const std::string work = dir_ + "/work";
  fs::create_directories(work + "/scripts/slurm");
  fs::create_directories(work + "/build/bin");
  fs::create_symlink(test::source_path("scripts/slurm/report.sbatch"),
                     work + "/scripts/slurm/report.sbatch");
  fs::create_symlink(BEACHBALL_PROGRAM, work + "/build/bin/beachball");
  test::write_case(work + "/cases", "a.toml", test::minimal_case("a"));
  test::write_case(work + "/cases", "stack.toml", test::kStackedBalls);
  test::write_case(work, "example.sh", example);

  const test::Outcome submitted = test::shell(
      "cd " + work + " && PATH=" + path_without_beachball() + " timeout 60 bash -eu example.sh");
  const auto job_logs = [&] {
    std::string out = "\n--- example:\n" + example + "\n--- it printed:\n" + submitted.out +
                      "\n--- queue:\n" + test::shell("squeue").out;
    for (const auto& entry : fs::directory_iterator(work))
      if (entry.path().filename().string().rfind("slurm-", 0) == 0)
        out += "\n--- " + entry.path().filename().string() + ":\n" + test::bytes(entry.path());
    return out + logs();
  };
  ASSERT_EQ(submitted.exit_code, 0) << job_logs();
  // The merge's id: the last job submitted.
  const std::string said = "Submitted batch job ";
  const std::size_t at = submitted.out.rfind(said);
  ASSERT_NE(at, std::string::npos) << job_logs();
  const std::string merge =
      submitted.out.substr(at + said.size(), submitted.out.find('\n', at) - at - said.size());

  // Waited for until it ends (bounded: a merge that pends for ever is a failure, with the
  // queue as it was). Its record is kept 5 s after it ends (MinJobAge).
  const auto deadline = std::chrono::steady_clock::now() + 400s;
  std::string state = job_state(programs_["scontrol"], merge), last = state;
  while (std::chrono::steady_clock::now() < deadline &&
         (state == "PENDING" || state == "RUNNING" || state == "CONFIGURING" ||
          state == "COMPLETING")) {
    std::this_thread::sleep_for(500ms);
    last = state;
    state = job_state(programs_["scontrol"], merge);
  }
  if (state.empty()) state = last;
  EXPECT_EQ(state, "COMPLETED") << "the merge, job " << merge << job_logs();

  // The report the example merged: the same files as the report run whole, and the same
  // results but for the costs (each timed by its own run).
  const test::Outcome whole = test::shell("cd " + work + " && " + BEACHBALL_PROGRAM +
                                          " report cases/ --cache off --out whole");
  ASSERT_EQ(whole.exit_code, 0) << whole.out;
  ASSERT_TRUE(fs::exists(work + "/reports")) << job_logs();
  const auto merged = test::snapshot(work + "/reports"), unsplit = test::snapshot(work + "/whole");
  std::vector<std::string> merged_files, unsplit_files;
  for (const auto& [name, bytes] : merged) merged_files.push_back(name);
  for (const auto& [name, bytes] : unsplit) unsplit_files.push_back(name);
  EXPECT_EQ(merged_files, unsplit_files) << job_logs();
  for (const char* name : {"a.json", "stack.json"}) {
    auto rows = [](const std::string& text) {
      nlohmann::json runs = nlohmann::json::parse(text)["runs"];
      for (auto& row : runs) row.erase("cost");
      return runs.dump();
    };
    ASSERT_TRUE(merged.count(name) && unsplit.count(name)) << name;
    EXPECT_EQ(rows(merged.at(name)), rows(unsplit.at(name))) << name;
  }
}

}  // namespace
}  // namespace bb
