// A map's budget as the program says it: `run` names the map's points and runs before any
// work, then, once its first point has run, the others' estimated time and what it is made
// from; a map too large for one machine is refused before anything is written, with its run
// count and how to shard it (`report --shard I/N`, `scripts/slurm/submit -n N`).
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>

#include "model/text.hpp"
#include "run/engine_catalogue.hpp"
#include "study/backend_names.hpp"
#include "study/case_limits.hpp"
#include "support/program.hpp"
#include "support/spring_map_case.hpp"
#include "support/test_support.hpp"

namespace bb {
namespace {

TEST(MapBudget, RunSaysTheMapsRunsBeforeItStartsThenTheOthersEstimatedTime) {
  const std::string dir = test::fresh_dir("map_budget");
  const std::string text = test::spring_map_case("budget", "[2.0, 50.0]", "[0.1, 0.01, 0.001]",
                                                 R"(["semi-implicit-euler"])");
  const std::string file = test::write_case(dir, "budget.toml", text);
  const test::Outcome o =
      test::beachball("run " + file +
                      " --backends course/semi-implicit-euler --no-cost --cache off "
                      "--jobs 2 --out " +
                      dir + "/out");
  ASSERT_EQ(o.exit_code, 0) << o.out;
  // 2 x 3 points, each the reference, its self-check and the one backend asked for.
  const std::size_t size = o.out.find(
      "budget: a map of 2 x 3 points of 3 runs each (the reference, its self-check and each "
      "backend run): 18 runs; its time is estimated from its first point to run");
  const std::size_t estimate = o.out.find("budget: the map's first point took ");
  const std::size_t rest = o.out.find("; the other 5 points to run: about ");
  const std::size_t written = o.out.find("written: ");
  ASSERT_NE(size, std::string::npos) << o.out;
  ASSERT_NE(estimate, std::string::npos) << o.out;
  EXPECT_NE(rest, std::string::npos) << o.out;
  EXPECT_NE(o.out.find("on 2 jobs (estimated from that point"), std::string::npos) << o.out;
  // Said in that order: the size before any work, the estimate before the others ran.
  EXPECT_LT(size, estimate);
  EXPECT_LT(estimate, written);
}

TEST(MapBudget, AMapTooLargeIsRefusedWithItsRunsAndHowToShardItBeforeAnythingIsWritten) {
  const std::string dir = test::fresh_dir("map_budget_refused");
  std::string text = test::spring_map_case("huge", "[2.0, 50.0]", "[0.1, 0.01]", R"(["rk4"])");
  // 200 x 100 points: the stiffness over a range, the mass of one body.
  text.replace(text.find("values = [2.0, 50.0]"), 20, "range = [1.0, 1000.0, 200]");
  text.replace(text.find("parameter = \"dt\""), 16, "parameter = \"body.left.mass\"");
  text.replace(text.find("values = [0.1, 0.01]\n"), 21, "range = [0.5, 2.0, 100]\n");
  const std::string file = test::write_case(dir, "huge.toml", text);
  const test::Outcome o = test::beachball("run " + file + " --no-cost --out " + dir + "/out");
  EXPECT_EQ(o.exit_code, 2) << o.out;
  const Scene scene = test::scene_from(text);
  const double runs =
      2e4 * (1.0 + static_cast<double>(runnable_backend_names(scene, engine_catalogue()).size()));
  ASSERT_GT(runs, kMaxMapRunsPerMachine);
  const int shards = static_cast<int>(std::ceil(runs / kMaxMapRunsPerMachine));
  EXPECT_NE(o.out.find(file + ":" + std::to_string(scene.second_sweep->line) + ":"),
            std::string::npos)
      << o.out;
  EXPECT_NE(o.out.find("200 x 100 points"), std::string::npos) << o.out;
  EXPECT_NE(o.out.find(short_number(runs) + " runs"), std::string::npos) << o.out;
  EXPECT_NE(o.out.find("`beachball report --shard I/" + std::to_string(shards) + "`"),
            std::string::npos)
      << o.out;
  EXPECT_NE(o.out.find("`scripts/slurm/submit -n " + std::to_string(shards) + "`"),
            std::string::npos)
      << o.out;
  // Refused before any work: no map size said, nothing written.
  EXPECT_EQ(o.out.find("a map of"), std::string::npos) << o.out;
  EXPECT_FALSE(std::filesystem::exists(dir + "/out"));
}

}  // namespace
}  // namespace bb
