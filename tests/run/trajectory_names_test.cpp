// The trajectory files' names (docs/output-files.md#trajectories): every run of a case gets
// a file of its own, named by its backend and step as the table shows them, with no '/';
// steps a case could not tell apart by name are refused before any work, at the line of
// 'dt'.
#include "run/trajectory_names.hpp"

#include <gtest/gtest.h>

#include <set>

#include "run/registry.hpp"
#include "study/case_error.hpp"
#include "support/test_support.hpp"

namespace bb {
namespace {

TEST(TrajectoryNames, EveryRunOfACaseHasAFileOfItsOwn) {
  // Several ground rules: course variants named with '+' as well as '/'.
  const Scene scene = load_case(test::source_path("cases/ball_in_box.toml"));
  const Registry registry = Registry::load();
  const BackendSet set = backends_for(scene, registry);
  std::set<std::string> names = {trajectory_file_name("reference", std::nullopt)};
  std::size_t runs = 1;
  bool plus = false;
  for (const Backend* b : set.all)
    for (double dt : scene.dt) {
      const std::string name = trajectory_file_name(b->name(), dt);
      ++runs;
      names.insert(name);
      plus = plus || b->name().find('+') != std::string::npos;
      EXPECT_EQ(name.find('/'), std::string::npos) << name;
      EXPECT_TRUE(name.ends_with(".csv")) << name;
      EXPECT_NE(name.find('@'), std::string::npos) << name;
    }
  EXPECT_TRUE(plus) << "no backend named with '+' was tried";
  EXPECT_EQ(names.size(), runs) << "two runs would write one file";
  EXPECT_EQ(trajectory_folder_name(scene.name), scene.name + "-trajectories");
}

TEST(TrajectoryNames, TheDocumentedExamplesAreTheRule) {
  EXPECT_EQ(trajectory_file_name("course/explicit-euler", 1.0 / 60.0),
            "course-explicit-euler@1-60.csv");
  EXPECT_EQ(trajectory_file_name("course/semi-implicit-euler+reflect", 1.0 / 120.0),
            "course-semi-implicit-euler+reflect@1-120.csv");
  EXPECT_EQ(trajectory_file_name("mujoco/rk4", 1.0 / 240.0), "mujoco-rk4@1-240.csv");
  EXPECT_EQ(trajectory_file_name("bullet", 0.003), "bullet@0.003.csv");
  EXPECT_EQ(trajectory_file_name("reference", std::nullopt), "reference.csv");
}

TEST(TrajectoryNames, StepsAlikeInTheirNamesAreRefusedAtTheLineOfDt) {
  // 1/60 and the next double but one: two steps, one name.
  const Scene scene = test::scene_from(R"(name = "alike"
dims = 2
duration = 1.0
sample = 1.0
dt = [0.016666666666666666, 0.01666666666666667]
report_dt = 0.016666666666666666
[[body]]
name = "ball"
radius = 0.5
mass = 1.0
position = [0.0, 10.0, 0.0]
)");
  ASSERT_EQ(scene.dt.size(), 2u);
  try {
    check_trajectory_names(scene);
    FAIL() << "two steps named alike were accepted";
  } catch (const CaseError& e) {
    EXPECT_EQ(e.line(), 5) << e.what();
    EXPECT_NE(e.problem().find("@1-60.csv"), std::string::npos) << e.what();
  }
  EXPECT_NO_THROW(check_trajectory_names(test::scene_from(test::kMinimalCase)));
}

}  // namespace
}  // namespace bb
