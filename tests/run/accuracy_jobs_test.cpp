// The schedule of a case's accuracy runs: the order the pool is handed them in.
#include <gtest/gtest.h>

#include <algorithm>
#include <string>
#include <vector>

#include "model/text.hpp"
#include "run/case_runner.hpp"
#include "support/test_support.hpp"

namespace bb {
namespace {

// With one child at a time, runs end in the order they were handed to the pool. The longest
// (the smallest dt: the most steps) go first, whichever backend they belong to, so that a
// case's last runs are short and no core waits on a long one the other could have shared.
TEST(AccuracyJobs, TheLongestRunsStartFirst) {
  const Scene scene = load_case(test::source_path("cases/drag_fall.toml"));
  ASSERT_GE(scene.dt.size(), 3u);
  RunOptions options;
  options.cost = false;
  options.sweep = false;
  options.jobs = 1;
  options.backends = {"course/explicit-euler", "course/rk4"};
  std::vector<std::string> done;
  options.on_progress = [&](const std::string& what) { done.push_back(what); };
  const CaseResults results = run_case(scene, Registry::load(), options);
  ASSERT_EQ(results.runs.size(), 2 * scene.dt.size());
  // The dt of each backend run, in the order the runs ended.
  std::vector<double> ended;
  for (const std::string& what : done)
    for (double dt : scene.dt)
      for (const std::string& backend : options.backends)
        if (what == scene.name + ": " + backend + " at dt " + format_dt(dt)) ended.push_back(dt);
  ASSERT_EQ(ended.size(), results.runs.size());
  EXPECT_TRUE(std::is_sorted(ended.begin(), ended.end())) << "the coarsest dt ended first";
  // The results keep the jobs' order: by backend, largest dt first.
  for (std::size_t i = 0; i < results.runs.size(); ++i) {
    EXPECT_EQ(results.runs[i].backend, options.backends[i / scene.dt.size()]);
    EXPECT_EQ(results.runs[i].dt, scene.dt[i % scene.dt.size()]);
  }
}

}  // namespace
}  // namespace bb
