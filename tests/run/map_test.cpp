// Two [[sweep]]s make a map: each of its P x Q points is the case written by hand at that
// point (a "dt" axis making the step the point's only one and its report_dt), row for row;
// the points go row by row, each with both values, in the results; and a map with more runs
// than one machine takes is refused before any work, with its run count and the shards it
// needs, unless a shard's share fits.
#include <gtest/gtest.h>

#include <cmath>

#include "model/text.hpp"
#include "report/json_writer.hpp"
#include "run/sweep_runner.hpp"
#include "study/backend_names.hpp"
#include "study/case_error.hpp"
#include "study/case_limits.hpp"
#include "support/results_rows.hpp"
#include "support/spring_pair_case.hpp"
#include "support/test_support.hpp"

namespace bb {
namespace {

/// Two unit masses joined by a spring of stiffness `k`, stepped at `dt` (one step, or
/// report_dt among 0.1 and 0.05 when `dt` is empty); then `sweeps`.
std::string spring_pair(const std::string& k, const std::string& dt,
                        const std::string& sweeps = "") {
  return R"(name = "pair"
dims = 2
duration = 1.0
sample = 0.1
)" + (dt.empty() ? std::string("dt = [0.1, 0.05]\nreport_dt = 0.05\n") : "dt = [" + dt + "]\n") +
         "gravity = [0.0, 0.0, 0.0]\n" + test::two_masses_on_a_spring("0.5005", k) + R"([course]
integrators = ["explicit-euler", "semi-implicit-euler"]
[[observe]]
kind = "max_stretch"
)" + sweeps;
}

const char* kStiffnessByStep = R"([[sweep]]
parameter = "spring.1.stiffness"
values = [40.0, 900.0]
[[sweep]]
parameter = "dt"
values = [0.1, 0.02, 0.05]
)";

RunOptions two_integrators() {
  RunOptions options;
  options.backends = {"course/explicit-euler", "course/semi-implicit-euler"};
  options.cost = false;
  options.jobs = 2;
  return options;
}

TEST(Map, EachPointIsTheCaseWrittenByHandAtItsTwoValues) {
  const Scene scene = test::scene_from(spring_pair("100.0", "", kStiffnessByStep));
  const auto sweep = results_json(run_case(scene, Registry::load(), two_integrators()))["sweep"];
  const std::vector<std::string> ks = {"40.0", "900.0"}, dts = {"0.1", "0.02", "0.05"};
  ASSERT_EQ(sweep["points"].size(), ks.size() * dts.size());
  for (std::size_t i = 0; i < ks.size(); ++i)
    for (std::size_t j = 0; j < dts.size(); ++j) {
      const auto& point = sweep["points"][i * dts.size() + j];
      EXPECT_EQ(point["value"], std::stod(ks[i]));
      EXPECT_EQ(point["second_value"], std::stod(dts[j]));
      const auto rows = results_json(run_case(test::scene_from(spring_pair(ks[i], dts[j])),
                                              Registry::load(), two_integrators()))["runs"];
      ASSERT_EQ(point["runs"].size(), rows.size());
      for (std::size_t r = 0; r < rows.size(); ++r)
        EXPECT_EQ(test::row_text(point["runs"][r]), test::row_text(rows[r]))
            << "k = " << ks[i] << ", dt = " << dts[j];
    }
  // Each parameter's values once, in the case's order.
  EXPECT_EQ(sweep["second_parameter"], "dt");
  EXPECT_EQ(sweep["values"].size(), 2u);
  EXPECT_EQ(sweep["second_values"].size(), 3u);
}

TEST(Map, SemiImplicitEulerExplodesOnlyPastTwoOverOmega) {
  // The course text's section 7 on the map: omega = sqrt(2 k) for two unit masses, so at
  // k = 40 the limit is 0.22 s (every step stable) and at k = 900 it is 0.047 s (0.1 and
  // 0.05 explode, 0.02 does not). The stretch starts at 0.001 m (linear: the masses never
  // pass through each other, which would bound the growth); exploded is past ten times.
  const Scene scene = test::scene_from(spring_pair("100.0", "", kStiffnessByStep));
  const CaseResults results = run_case(scene, Registry::load(), two_integrators());
  for (const SweepPoint& p : results.sweep->points) {
    const bool unstable = p.second_value > 2.0 / std::sqrt(2.0 * p.value);
    for (const RunRecord& run : p.runs) {
      if (run.backend != "course/semi-implicit-euler") continue;
      const std::optional<double> stretch = run_quantity(run, "max_stretch");
      const bool exploded = run.status == RunStatus::Diverged || (stretch && *stretch > 0.01);
      EXPECT_EQ(exploded, unstable) << "k = " << p.value << ", dt = " << p.second_value;
    }
  }
}

TEST(Map, AMapTooLargeForOneMachineIsRefusedWithItsRunCount) {
  const Scene scene = test::scene_from(spring_pair("100.0", "", R"([[sweep]]
parameter = "spring.1.stiffness"
range = [10.0, 1000.0, 100]
[[sweep]]
parameter = "body.left.mass"
range = [0.5, 2.0, 100]
)"));
  RunOptions options;
  const double runs =
      1e4 * (1.0 + static_cast<double>(runnable_backend_names(scene, every_word().engines).size()));
  ASSERT_GT(runs, kMaxMapRunsPerMachine);
  try {
    check_run_options(scene, options);
    FAIL() << "a map of " << runs << " runs was not refused";
  } catch (const CaseError& e) {
    const std::string message = e.what();
    EXPECT_EQ(e.line(), scene.second_sweep->line);
    EXPECT_NE(message.find("100 x 100 points"), std::string::npos) << message;
    EXPECT_NE(message.find(short_number(runs) + " runs"), std::string::npos) << message;
    const int shards = static_cast<int>(std::ceil(runs / kMaxMapRunsPerMachine));
    EXPECT_NE(message.find("--shard I/" + std::to_string(shards)), std::string::npos) << message;
    // A shard's share that fits is not refused, nor a check, which runs no map.
    options.shard = Shard{1, shards};
    EXPECT_NO_THROW(check_run_options(scene, options));
    options.shard.reset();
    options.sweep = false;
    EXPECT_NO_THROW(check_run_options(scene, options));
  }
}

}  // namespace
}  // namespace bb
