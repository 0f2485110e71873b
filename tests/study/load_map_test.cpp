// Two [[sweep]]s make a map: the loader keeps both, in the file's order, with the step "dt"
// allowed as an axis (and alone); its values are checked as each of 'dt' is. The refusals
// (a third [[sweep]], one parameter twice, page keys on the second, two frictions that cross
// at some point, a step that does not divide 'sample', too much work at the smallest swept
// step) are tests/bad_cases/map_*.toml and sweep_*.toml.
#include <gtest/gtest.h>

#include "study/case_error.hpp"
#include "study/sweep_parameter.hpp"
#include "support/spring_pair_case.hpp"
#include "support/test_support.hpp"

namespace bb {
namespace {

/// Two unit masses joined by a spring, then `sweeps`.
std::string spring_pair(const std::string& sweeps) {
  return test::spring_pair_case("pair", "0.1", "[0.1, 0.05]", "0.05") + sweeps;
}

TEST(LoadMap, TwoSweepsMakeAMapOfBothInTheFilesOrder) {
  const Scene scene = test::scene_from(spring_pair(R"([[sweep]]
parameter = "spring.1.stiffness"
values = [10.0, 100.0, 1000.0]
[[sweep]]
parameter = "dt"
range = [0.01, 0.02, 2]
)"));
  ASSERT_TRUE(scene.sweep);
  ASSERT_TRUE(scene.second_sweep);
  EXPECT_EQ(scene.sweep->parameter, "spring.1.stiffness");
  EXPECT_EQ(scene.sweep->values.size(), 3u);
  EXPECT_EQ(scene.second_sweep->parameter, "dt");
  EXPECT_EQ(scene.second_sweep->values, sweep_range(0.01, 0.02, 2));
  EXPECT_EQ(scene.second_sweep->line, 25);
}

TEST(LoadMap, TheStepAloneIsASweepAndSetsTheOnlyStepAndReportDt) {
  const Scene scene = test::scene_from(spring_pair(R"([[sweep]]
parameter = "dt"
values = [0.1, 0.02]
)"));
  ASSERT_TRUE(scene.sweep);
  EXPECT_FALSE(scene.second_sweep);
  EXPECT_EQ(sweep_parameter_value(scene, "dt"), 0.05);
  Scene at = scene;
  set_sweep_parameter(at, "dt", 0.02);
  EXPECT_EQ(at.report_dt, 0.02);
  EXPECT_EQ(at.dt, std::vector<double>{0.02});
}

TEST(LoadMap, AStepLongerThanTheRunIsRefusedAtItsLine) {
  try {
    test::scene_from(spring_pair("[[sweep]]\nparameter = \"dt\"\nvalues = [0.1, 2.0]\n"));
    FAIL() << "loaded";
  } catch (const CaseError& e) {
    EXPECT_EQ(e.line(), 24);
    EXPECT_NE(std::string(e.what()).find("at most the duration"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace bb
