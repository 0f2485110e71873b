// A [[sweep]] over a spring's constants: `spring.<n>.stiffness` and `.damping` name the n-th
// [[spring]] of the file (from 1), `grid.stiffness` and `grid.damping` every spring of the
// [grid]; each value is held to the loader's own bounds on k and c.
#include <gtest/gtest.h>

#include "study/sweep_parameter.hpp"
#include "support/test_support.hpp"

namespace bb {
namespace {

/// A one-row [grid] of three particles (a rope) and two [[spring]]s hanging a ball.
Scene rope_and_springs() {
  return test::scene_from(R"(name = "springs"
dims = 2
duration = 1.0
sample = 0.1
dt = [0.1]
[grid]
size = [3, 1]
origin = [5.0, 0.0, 0.0]
stiffness = 40.0
damping = 0.3
[[body]]
name = "hook"
shape = "point"
fixed = true
position = [0.0, 2.0, 0.0]
[[body]]
name = "ball"
radius = 0.1
mass = 1.0
[[spring]]
bodies = ["hook", "ball"]
stiffness = 100.0
[[spring]]
bodies = ["ball", "p0_0"]
stiffness = 7.0
damping = 0.5
)");
}

TEST(SweepSpringParameter, NamesEachSpringTableFromOneAndTheGrid) {
  const Scene s = rope_and_springs();
  ASSERT_EQ(s.springs.size(), 4u);  // the grid's two, then the tables' two
  EXPECT_EQ(sweep_path_problem(s, "spring.1.stiffness"), "");
  EXPECT_EQ(sweep_path_problem(s, "spring.2.damping"), "");
  EXPECT_EQ(sweep_path_problem(s, "grid.stiffness"), "");
  EXPECT_EQ(sweep_path_problem(s, "grid.damping"), "");
  EXPECT_EQ(sweep_parameter_value(s, "spring.1.stiffness"), 100.0);
  EXPECT_EQ(sweep_parameter_value(s, "spring.2.stiffness"), 7.0);
  EXPECT_EQ(sweep_parameter_value(s, "spring.2.damping"), 0.5);
  EXPECT_EQ(sweep_parameter_value(s, "grid.damping"), 0.3);
  for (const char* missing :
       {"spring.3.stiffness", "spring.0.stiffness", "spring.01.damping", "spring.x.stiffness"})
    EXPECT_NE(sweep_path_problem(s, missing).find("names no [[spring]] number"), std::string::npos)
        << missing;
  EXPECT_NE(sweep_path_problem(s, "spring.1.rest_length").find("names nothing"), std::string::npos);
  EXPECT_NE(sweep_path_problem(test::scene_from(test::kMinimalCase), "grid.stiffness")
                .find("the case has no [grid]"),
            std::string::npos);
}

TEST(SweepSpringParameter, SetsOneTableOrEveryGridSpring) {
  Scene s = rope_and_springs();
  set_sweep_parameter(s, "spring.2.stiffness", 9.5);
  EXPECT_EQ(s.springs[3].stiffness, 9.5);
  EXPECT_EQ(s.springs[2].stiffness, 100.0);
  set_sweep_parameter(s, "grid.stiffness", 60.0);
  set_sweep_parameter(s, "grid.damping", 0.0);
  for (int i : {0, 1}) {
    EXPECT_EQ(s.springs[i].stiffness, 60.0);
    EXPECT_EQ(s.springs[i].damping, 0.0);
  }
  EXPECT_EQ(s.grid->stiffness, 60.0);
  EXPECT_EQ(s.springs[3].damping, 0.5);
}

TEST(SweepSpringParameter, HoldsEachValueToTheLoadersBounds) {
  const Scene s = rope_and_springs();
  for (const char* path : {"spring.1.stiffness", "grid.stiffness"}) {
    EXPECT_NE(sweep_value_problem(s, path, 0.0).find("greater than 0 and at most 1e+09 N/m"),
              std::string::npos);
    EXPECT_NE(sweep_value_problem(s, path, 2e9).find("at most 1e+09"), std::string::npos);
    EXPECT_EQ(sweep_value_problem(s, path, 1e9), "");
  }
  for (const char* path : {"spring.2.damping", "grid.damping"}) {
    EXPECT_NE(sweep_value_problem(s, path, -0.1).find("between 0 and 1e+09 N s/m"),
              std::string::npos);
    EXPECT_EQ(sweep_value_problem(s, path, 0.0), "");
  }
}

}  // namespace
}  // namespace bb
