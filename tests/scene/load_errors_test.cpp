// Every kind of bad case file yields a CaseError naming the file, the line and the problem.
// In each case text, the line the message must point at carries the marker "#<".
#include <gtest/gtest.h>

#include <algorithm>
#include <fstream>

#include "scene/case_error.hpp"
#include "support/test_support.hpp"

namespace bb {
namespace {

struct BadCase {
  const char* label;
  std::string text;
  const char* problem;  ///< a part of the message a student reads
};

void PrintTo(const BadCase& c, std::ostream* os) {
  *os << c.label;
}

/// 1-based line of the "#<" marker.
int marked_line(const std::string& text) {
  const std::size_t at = text.find("#<");
  if (at == std::string::npos) return 0;
  return 1 + static_cast<int>(std::count(text.begin(), text.begin() + at, '\n'));
}

const std::string kHead = R"(name = "bad"
dims = 2
duration = 1.0
sample = 0.1
dt = [0.1, 0.05]
report_dt = 0.05
[air]
density = 1.2
)";

const std::string kBall = R"(
[[body]]
name = "ball"
radius = 0.5
mass = 1.0
)";

std::vector<BadCase> bad_cases() {
  return {
      {"unknown_air_key", kHead + "colour = \"red\" #<\n" + kBall, "unknown key 'colour' in [air]"},
      {"unknown_top_key_after_tables", "colour = \"red\" #<\n" + kHead + kBall,
       "unknown key 'colour'"},
      {"unknown_body_key", kHead + kBall + "colour = 3 #<\n",
       "unknown key 'colour' in [[body]] 'ball'"},
      {"wrong_type", R"(name = "bad"
dims = 2
duration = "long" #<
sample = 0.1
dt = [0.1]
)" + kBall,
       "'duration' must be a number, not a string"},
      {"wrong_type_bool", kHead + kBall + "fixed = 1 #<\n", "'fixed' must be true or false"},
      {"missing_top_key", R"(name = "bad" #<
duration = 1.0
sample = 0.1
dt = [0.1]
)" + kBall,
       "needs the key 'dims'"},
      {"missing_body_key", kHead + "[[body]] #<\nname = \"ball\"\nradius = 0.5\n",
       "needs the key 'mass'"},
      {"negative_mass", kHead + "[[body]]\nname = \"ball\"\nradius = 0.5\nmass = -1.0 #<\n",
       "'mass' in [[body]] 'ball' must be greater than 0"},
      {"zero_mass", kHead + "[[body]]\nname = \"ball\"\nradius = 0.5\nmass = 0 #<\n",
       "must be greater than 0, not 0"},
      {"zero_radius", kHead + "[[body]]\nname = \"ball\"\nradius = 0.0 #<\nmass = 1.0\n",
       "'radius' in [[body]] 'ball' must be greater than 0"},
      {"dt_not_dividing_sample", R"(name = "bad"
dims = 2
duration = 1.0
sample = 0.1
dt = [0.03] #<
)" + kBall,
       "does not divide 'sample'"},
      {"report_dt_not_in_dt", R"(name = "bad"
dims = 2
duration = 1.0
sample = 0.1
dt = [0.1, 0.05]
report_dt = 0.025 #<
)" + kBall,
       "'report_dt' 0.025 s is not one of 'dt'"},
      {"duration_not_multiple", R"(name = "bad"
dims = 2
duration = 1.05 #<
sample = 0.1
dt = [0.1]
)" + kBall,
       "must be a whole number of samples"},
      {"duplicate_body", kHead + kBall + "[[body]] #<\nname = \"ball\"\nradius = 1.0\nmass = 2.0\n",
       "body name 'ball' is used twice"},
      {"spring_missing_body",
       kHead + kBall + "[[spring]]\nbodies = [\"ball\", \"ghost\"] #<\nstiffness = 10.0\n",
       "names body 'ghost', which the case does not define"},
      {"spring_to_itself",
       kHead + kBall + "[[spring]]\nbodies = [\"ball\", \"ball\"] #<\nstiffness = 10.0\n",
       "joins body 'ball' to itself"},
      {"gate_missing_backend",
       kHead + kBall + "[[gate]]\nbackend = \"physx\" #<\nmetric = \"position_max\"\nmax = 1.0\n",
       "names backend 'physx', which this case does not run"},
      {"gate_unknown_metric",
       kHead + kBall + "[[gate]]\nbackend = \"ode\"\nmetric = \"wobble\" #<\nmax = 1.0\n",
       "metric 'wobble' is neither an error metric"},
      {"gate_course_variant_not_in_case",
       kHead + kBall +
           "[course]\nintegrators = [\"rk4\"]\n[[gate]]\nbackend = \"course/semi-implicit-euler\" "
           "#<\nmetric = \"position_max\"\nmax = 1.0\n",
       "names backend 'course/semi-implicit-euler'"},
      {"toml_syntax", R"(name = "bad"
dims = = 2 #<
)",
       "not valid TOML"},
      {"nan", R"(name = "bad"
dims = 2
duration = nan #<
sample = 0.1
dt = [0.1]
)" + kBall,
       "must be a finite number"},
      {"inf_in_vector", kHead + kBall + "velocity = [inf, 0.0, 0.0] #<\n",
       "must be a finite number"},
      {"z_in_2d", kHead + kBall + "position = [0.0, 1.0, 2.0] #<\n",
       "has a z component, but the case is 2D"},
      {"vector_length", kHead + kBall + "position = [0.0, 1.0] #<\n",
       "'position' must have 3 numbers, not 2"},
      {"unknown_engine_key", kHead + kBall + "[engines.bullet]\nsolver_iteration = 5 #<\n",
       "unknown key 'solver_iteration' in [engines.bullet]"},
      {"unknown_engine", kHead + kBall + "[engines.physx] #<\nthreads = 4\n",
       "unknown key 'physx' in [engines]"},
      {"engine_iterations_zero", kHead + kBall + "[engines.box2d]\nvelocity_iterations = 0 #<\n",
       "must be at least 1"},
      {"grid_too_large", kHead + "[grid]\nsize = [100000, 100000] #<\n",
       "more than 20000 particles"},
      {"grid_neighbours", kHead + "[grid]\nsize = [3, 3]\nneighbours = 5 #<\n",
       "must be 4, 6 or 8"},
      {"hinge_on_fixed",
       kHead + kBall + "fixed = true\n[[hinge]]\nbody = \"ball\" #<\nanchor = [0.0, 0.0, 0.0]\n",
       "which is fixed and cannot turn"},
      {"zero_normal", kHead + kBall + "[ground]\nnormal = [0.0, 0.0, 0.0] #<\n",
       "must not be the zero vector"},
      {"observe_missing_body",
       kHead + kBall + "[[observe]]\nkind = \"terminal_velocity\"\nbody = \"ghost\" #<\n",
       "names body 'ghost'"},
      {"observe_unknown_kind",
       kHead + kBall + "[[observe]]\nkind = \"wobble\" #<\nbody = \"ball\"\n",
       "unknown observable kind 'wobble'"},
      {"unknown_integrator", kHead + kBall + "[course]\nintegrators = [\"leapfrog\"] #<\n",
       "has 'leapfrog'; known: explicit-euler"},
      {"bad_case_name", "name = \"Bad Name\" #<\n", "'name' must use only a-z, 0-9 and _"},
      {"dims_four", "name = \"bad\"\ndims = 4 #<\n", "'dims' must be 2 or 3"},
      {"drag_on_box",
       kHead + "[[body]]\nname = \"crate\"\nshape = \"box\"\nhalf_extents = [1.0, 1.0, 1.0]\nmass "
               "= 1.0\ndrag_coefficient = 1.0 #<\n",
       "only a sphere has one"},
      {"radius_on_box",
       kHead + "[[body]]\nname = \"crate\"\nshape = \"box\"\nhalf_extents = [1.0, 1.0, "
               "1.0]\nradius = 1.0 #<\nmass = 1.0\n",
       "'radius' belongs to a sphere"},
      {"drag_without_air",
       "name = \"bad\"\ndims = 2\nduration = 1.0\nsample = 0.1\ndt = [0.1]\n" + kBall +
           "drag_coefficient = 0.5 #<\n",
       "has no [air] section"},
      {"dt_longer_than_duration",
       "name = \"bad\"\ndims = 2\nduration = 1.0\nsample = 1.0\ndt = [2.0] #<\n" + kBall,
       "longer than the duration"},
      {"restitution_above_one", kHead + kBall + "[ground]\nrestitution = 1.5 #<\n",
       "between 0 and 1"},
      {"report_unknown_metric", kHead + kBall + "[report]\nmetrics = [\"wobble\"] #<\n",
       "[report] metric 'wobble' is neither an error metric"},
      {"stability_dt_max_too_long", kHead + kBall + "[stability]\ndt_max = 5.0 #<\n",
       "longer than the duration"},
      {"stability_factor_below_one", kHead + kBall + "[stability]\nenergy_factor = 0.5 #<\n",
       "'energy_factor' in [stability] must be greater than 1"},
      {"no_bodies", kHead + "", "has no [[body]]"},
      {"body_not_a_table_array", "body = 3 #<\n" + kHead, "must be written as [[body]] tables"},
      {"angle_in_3d",
       "name = \"bad\"\ndims = 3\nduration = 1.0\nsample = 0.1\ndt = [0.1]\n" + kBall +
           "angle = 10.0 #<\n",
       "'angle' is for 2D cases"},
  };
}

class LoadErrors : public ::testing::TestWithParam<BadCase> {};

TEST_P(LoadErrors, NamesFileLineAndProblem) {
  const BadCase& bad = GetParam();
  try {
    parse_case(bad.text, "bad.toml");
    FAIL() << "no error for case text:\n" << bad.text;
  } catch (const CaseError& e) {
    EXPECT_EQ(e.file(), "bad.toml");
    const int expected = marked_line(bad.text);
    if (expected > 0) {
      EXPECT_EQ(e.line(), expected) << e.what();
    } else {
      EXPECT_GE(e.line(), 1) << e.what();
    }
    EXPECT_NE(e.problem().find(bad.problem), std::string::npos)
        << "message: " << e.what() << "\nexpected to contain: " << bad.problem;
    EXPECT_EQ(std::string(e.what()).rfind("bad.toml:" + std::to_string(e.line()) + ": ", 0), 0u);
  }
}

INSTANTIATE_TEST_SUITE_P(Catalogue, LoadErrors, ::testing::ValuesIn(bad_cases()),
                         [](const auto& info) { return std::string(info.param.label); });

TEST(LoadFileErrors, MissingFileAndFolderAndEmptyFile) {
  const auto problem_of = [](const std::string& path) {
    try {
      load_case(path);
    } catch (const CaseError& e) {
      return e.problem();
    }
    return std::string("no error");
  };
  EXPECT_EQ(problem_of("/nonexistent/case.toml"), "no such file");
  EXPECT_NE(problem_of(test::source_path("cases")).find("is a directory"), std::string::npos);
  EXPECT_NE(problem_of("/dev/null").find("not a regular file"), std::string::npos);
  const std::string empty = ::testing::TempDir() + "/empty.toml";
  { std::ofstream(empty) << "\n  \n"; }
  EXPECT_NE(problem_of(empty).find("is empty"), std::string::npos);
}

}  // namespace
}  // namespace bb
