// The stability searches run together: a core that would be idle tries the steps a search
// may ask for next, and every search records what it records when run one trial at a time.
#include "run/stability_chains.hpp"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <set>

#include "support/program.hpp"
#include "support/test_support.hpp"
#include "support/verdict_backends.hpp"

namespace bb {
namespace {

using Known = StabilitySearch::Known;

Scene chained_scene() {
  std::string text = test::kMinimalCase;
  text += "\n[stability]\ndt_min = 1e-4\ndt_max = 0.5\n";
  return test::scene_from(text);
}

/// Runs a search one trial at a time; before each trial's verdict is known, the steps it
/// may ask for next are looked ahead: the step it then asks for must be among them.
void expect_look_ahead_finds_each_next_step(const std::function<bool(double)>& stable) {
  StabilitySearch search(1e-4, 0.5);
  int asked = 0;
  while (const auto dt = search.next()) {
    const auto known = [&](double d) { return d == *dt ? Known::Running : Known::Nothing; };
    const std::vector<double> ahead = search.likely_next(2, known);
    EXPECT_EQ(std::count(ahead.begin(), ahead.end(), *dt), 0) << "a running step is not offered";
    search.record(*dt, {stable(*dt), "", ""});
    ++asked;
    if (const auto then = search.next()) {
      EXPECT_NE(std::find(ahead.begin(), ahead.end(), *then), ahead.end())
          << "after dt " << *dt << " the search asks for " << *then;
    }
  }
  EXPECT_GT(asked, 10);
}

TEST(StabilityLookAhead, TheStepAskedForNextIsAmongTheTwoLookedAhead) {
  expect_look_ahead_finds_each_next_step([](double dt) { return dt <= 0.0123; });
  expect_look_ahead_finds_each_next_step([](double dt) { return dt <= 0.000137; });
  // Not monotone: bands, probes and narrowing of several brackets.
  expect_look_ahead_finds_each_next_step(
      [](double dt) { return !((dt > 0.003 && dt <= 0.006) || dt > 0.01); });
}

TEST(StabilityLookAhead, AKnownVerdictIsFollowedAndNotOffered) {
  StabilitySearch search(1e-4, 0.5);
  // dt_max known unstable: the search goes to dt_min next, and only there.
  const auto known = [](double d) { return d == 0.5 ? Known::Unstable : Known::Nothing; };
  const std::vector<double> ahead = search.likely_next(1, known);
  ASSERT_EQ(ahead.size(), 1u);
  EXPECT_EQ(ahead[0], 1e-4);
}

StabilityChains::Options on_cores(int jobs, bool isolation) {
  StabilityChains::Options options;
  options.jobs = jobs;
  options.isolation = isolation;
  return options;
}

/// The steps a verdict backend's log file holds, one per start.
std::multiset<double> logged_steps(const std::string& file) {
  std::multiset<double> steps;
  std::ifstream in(file);
  for (double dt; in >> dt;) steps.insert(dt);
  return steps;
}

// One search on two cores: the idle core runs trials ahead, so more trials start than the
// search records, and the result is the one-at-a-time search's, band for band.
TEST(StabilityChains, ASearchOnTwoCoresRecordsWhatItRecordsOneTrialAtATime) {
  const Scene scene = chained_scene();
  const std::string dir = test::fresh_dir("stability_chains");
  std::filesystem::create_directories(dir);
  test::BandBackend alone(0.003, 0.006, 0.01);
  const StabilityResult sequential = find_stability(alone, scene);
  test::BandBackend together(0.003, 0.006, 0.01);
  together.log = dir + "/starts.txt";
  const std::vector<StabilityResult> found =
      StabilityChains(scene, {&together}, on_cores(2, true)).run();
  ASSERT_EQ(found.size(), 1u);
  const StabilityResult& r = found[0];
  EXPECT_EQ(r.status, sequential.status);
  EXPECT_EQ(r.trials, sequential.trials);
  EXPECT_EQ(r.critical_dt, sequential.critical_dt);
  EXPECT_EQ(r.unstable_dt, sequential.unstable_dt);
  ASSERT_EQ(r.bands.size(), sequential.bands.size());
  for (std::size_t i = 0; i < r.bands.size(); ++i) {
    EXPECT_EQ(r.bands[i].from, sequential.bands[i].from) << i;
    EXPECT_EQ(r.bands[i].to, sequential.bands[i].to) << i;
    EXPECT_EQ(r.bands[i].reason, sequential.bands[i].reason) << i;
  }
  const std::multiset<double> started = logged_steps(together.log);
  EXPECT_GT(static_cast<int>(started.size()), r.trials) << "the idle core looked ahead";
  EXPECT_EQ(std::set<double>(started.begin(), started.end()).size(), started.size())
      << "no step is tried twice";
}

// In this process (no isolation) nothing is tried ahead: each started trial is recorded.
TEST(StabilityChains, InThisProcessOnlyTheTrialsAskedForRun) {
  const Scene scene = chained_scene();
  const std::string dir = test::fresh_dir("stability_chains_in_process");
  std::filesystem::create_directories(dir);
  test::ThresholdBackend backend(0.0123);
  backend.log = dir + "/starts.txt";
  const std::vector<StabilityResult> found =
      StabilityChains(scene, {&backend}, on_cores(2, false)).run();
  ASSERT_EQ(found.size(), 1u);
  EXPECT_EQ(static_cast<int>(logged_steps(backend.log).size()), found[0].trials);
}

}  // namespace
}  // namespace bb
