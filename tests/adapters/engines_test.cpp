// Every engine adapter runs every bundled drag case, converges towards the reference as dt
// halves, and steps like semi-implicit Euler (which Bullet, Box2D and ODE all use).
#include <gtest/gtest.h>

#include "cli/commands.hpp"
#include "course/course_backend.hpp"
#include "metrics/errors.hpp"
#include "reference/gsl_reference.hpp"
#include "run/accuracy_run.hpp"
#include "run/registry.hpp"
#include "study/start_case.hpp"
#include "support/engine_support.hpp"
#include "support/test_support.hpp"

namespace bb {
namespace {

using test::text_setting;

using test::engine;
using test::registry;

using test::single_precision;

struct EngineCase {
  std::string engine;
  std::string case_name;
};

void PrintTo(const EngineCase& c, std::ostream* os) {
  *os << c.engine << " on " << c.case_name;
}

class EngineConvergence : public ::testing::TestWithParam<EngineCase> {};

TEST_P(EngineConvergence, ConvergesAndStepsLikeSemiImplicitEuler) {
  const Backend* backend = engine(GetParam().engine);
  BB_SKIP_IF_MISSING(test::not_built({GetParam().engine}));
  if (const std::string staged = test::staged_step(GetParam().engine); !staged.empty())
    GTEST_SKIP() << GetParam().engine << " does not step like semi-implicit Euler: " << staged;
  const Scene scene = load_case(test::source_path("cases/" + GetParam().case_name + ".toml"));
  if (!missing_features(*backend, scene).empty()) GTEST_SKIP() << "case not supported";
  const RunRecord reference = run_accuracy(ReferenceBackend(), scene, scene.sample);
  const CourseBackend euler(
      {"course/semi-implicit-euler", "semi-implicit-euler", "mirror", "clamp"});
  // Single precision rounds every step; its error stops shrinking near this many metres.
  const double precision_floor = single_precision(backend->name()) ? 5e-3 : 1e-9;
  std::vector<double> errors;
  for (double dt : scene.dt) {
    const RunRecord run = run_accuracy(*backend, scene, dt);
    ASSERT_EQ(run.status, RunStatus::Ok) << dt << ": " << run.reason;
    errors.push_back(compare(scene, run.trajectory, reference.trajectory).position_max);
    const RunRecord same_method = run_accuracy(euler, scene, dt);
    EXPECT_LT(max_position_difference(run.trajectory, same_method.trajectory), precision_floor)
        << "dt = " << dt << ": the engine does not step like semi-implicit Euler";
  }
  for (std::size_t i = 1; i < errors.size(); ++i)
    if (errors[i - 1] > 10 * precision_floor) {
      EXPECT_LT(errors[i], 0.75 * errors[i - 1]) << i;
    }
  EXPECT_LT(errors.back(), errors.front() / 16.0);
}

std::vector<EngineCase> engine_cases() {
  std::vector<EngineCase> out;
  for (const std::string& e : test::rigid_engines())
    for (const char* c : {"drag_fall", "beachball_shells", "three_beachballs_2", "magnus_throw"})
      // The 3D case only on an engine that declares 3D (Box2D is 2D only;
      // Engines.Box2dSaysItCannotRunA3dCase covers it there).
      if (test::described_with(e, Feature::ThreeD) || std::string(c) != "beachball_shells")
        out.push_back({e, c});
  return out;
}

INSTANTIATE_TEST_SUITE_P(DragCases, EngineConvergence, ::testing::ValuesIn(engine_cases()),
                         [](const auto& info) {
                           return test::test_name(info.param.engine + "_" + info.param.case_name);
                         });

// Every backend the adapters describe (the catalogue names them, built or not) is built here,
// or the test says which are not: where BEACHBALL_REQUIRE_ALL is set (CI), it fails.
TEST(Engines, TheStandardEnginesAreBuilt) {
  ASSERT_FALSE(test::rigid_engines().empty());
  std::vector<std::string> described;
  for (const EngineDescription& e : built_in_engine_catalogue())
    if (e.has_adapter)
      for (const std::string& name : variant_names(e)) described.push_back(name);
  BB_SKIP_IF_MISSING(test::not_built(described));
}

TEST(Engines, Box2dSaysItCannotRunA3dCase) {
  const Backend* box2d = engine("box2d");
  BB_SKIP_IF_MISSING(test::not_built({"box2d"}));
  const Scene scene = load_case(test::source_path("cases/beachball_shells.toml"));
  const RunRecord run = run_accuracy(*box2d, scene, scene.report_dt);
  EXPECT_EQ(run.status, RunStatus::Unsupported);
  EXPECT_EQ(run.reason, "does not support: 3d");
}

TEST(Engines, FloatAndDoubleBulletDifferOnlyByRounding) {
  const Backend* d = engine("bullet");
  const Backend* f = engine("bullet-float");
  BB_SKIP_IF_MISSING(test::not_built({"bullet", "bullet-float"}));
  const Scene scene = load_case(test::source_path("cases/drag_fall.toml"));
  const RunRecord rd = run_accuracy(*d, scene, scene.dt.back());
  const RunRecord rf = run_accuracy(*f, scene, scene.dt.back());
  const double difference = max_position_difference(rd.trajectory, rf.trajectory);
  // Both plugins live in one process; different results show each got its own library.
  EXPECT_GT(difference, 1e-7);
  EXPECT_LT(difference, 5e-3);
}

// A drag-free 2D fall of a spinning point mass beside a sphere: every engine runs it.
const char* kPointFall = R"(name = "point_fall"
dims = 2
duration = 3.0
sample = 0.1
dt = [0.02, 0.01]
report_dt = 0.01

[[body]]
name = "grain"
shape = "point"
mass = 0.003
position = [0.0, 20.0, 0.0]
velocity = [1.5, 4.0, 0.0]
angular_velocity = [0.0, 0.0, 2.0]

[[body]]
name = "ball"
radius = 0.2
mass = 1.0
position = [2.0, 20.0, 0.0]
)";

TEST(Engines, EveryEngineRunsAPointBodyLikeSemiImplicitEuler) {
  const Scene scene = test::scene_from(kPointFall);
  const CourseBackend euler(
      {"course/semi-implicit-euler", "semi-implicit-euler", "mirror", "clamp"});
  ASSERT_FALSE(registry().engines().empty());
  for (const Backend* backend : registry().engines()) {
    SCOPED_TRACE(backend->name());
    // A variant that needs springs (bullet-softbody) takes no part in a scene without them.
    if (!backend->needs().missing_from(scene.features()).empty()) continue;
    // An engine's own RK4 (its description says so) is tested in its own file.
    if (!test::staged_step(backend->name()).empty()) continue;
    ASSERT_EQ(missing_features(*backend, scene), "");
    const RunRecord run = run_accuracy(*backend, scene, scene.report_dt);
    ASSERT_EQ(run.status, RunStatus::Ok) << run.reason;
    // The engine's own precision: a float engine rounds every step.
    const std::string precision = text_setting(run.engine_settings, "precision");
    ASSERT_TRUE(precision == "double" || precision == "float") << precision;
    const double tolerance = precision == "double" ? 1e-9 : 1e-4;
    const RunRecord same_method = run_accuracy(euler, scene, scene.report_dt);
    EXPECT_LT(max_position_difference(run.trajectory, same_method.trajectory), tolerance);
    // The point really fell: from 20 m, thrown up at 4 m/s, it is below 0 after 3 s.
    EXPECT_LT(run.trajectory.states.back()[0].position.y(), 0.0);
    const std::string stand_in = text_setting(run.engine_settings, "point_body");
    EXPECT_NE(stand_in.find("sphere of radius 0.01 m"), std::string::npos) << stand_in;
    EXPECT_NE(stand_in.find("no collisions"), std::string::npos) << stand_in;
  }
}

TEST(Engines, APointBodyStandInIsNamedOnlyWhereThereIsOne) {
  const Scene scene = load_case(test::source_path("cases/drag_fall.toml"));
  for (const Backend* b : registry().engines())
    EXPECT_EQ(text_setting(start_case(*b, scene, scene.report_dt)->settings(), "point_body"), "")
        << b->name();
}

TEST(Engines, SettingsThatChangeResultsAreReported) {
  const Scene scene = load_case(test::source_path("cases/drag_fall.toml"));
  for (const Backend* b : registry().engines()) {
    const Settings s = start_case(*b, scene, scene.report_dt)->settings();
    std::vector<std::string> keys;
    for (const auto& [k, v] : s) keys.push_back(k);
    for (const char* k : {"linear_damping", "angular_damping", "precision"})
      EXPECT_NE(std::find(keys.begin(), keys.end(), k), keys.end()) << b->name() << " lacks " << k;
  }
}

}  // namespace
}  // namespace bb
