// [[sweep]]: the whole case again at each value of one parameter. A parameter that changes
// nothing gives identical points; one over ground.restitution gives the reference's exact
// rebound e^2 h; the points run in parallel child processes and come back in order.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "report/json_writer.hpp"
#include "run/sweep_runner.hpp"
#include "support/results_rows.hpp"
#include "support/test_support.hpp"

namespace bb {
namespace {

/// A ball (r = 0.5 m) dropped straight down from a centre height of 2.5 m for 1.5 s (at
/// e = 0.5 it is still bouncing at the end) onto `ground`, watched for its first apex,
/// with `sweep` appended.
std::string drop_case(const std::string& ground, const std::string& sweep) {
  return R"(name = "drop"
dims = 2
duration = 1.5
sample = 0.05
dt = [0.01, 0.005]
report_dt = 0.01
[ground]
)" + ground +
         R"(
[[body]]
name = "ball"
radius = 0.5
mass = 1.0
position = [0.0, 2.5, 0.0]
[course]
integrators = ["semi-implicit-euler", "velocity-verlet"]
[[observe]]
kind = "bounce_apex"
body = "ball"
n = 1
)" + sweep;
}

CaseResults swept(const Scene& scene, bool isolation) {
  RunOptions options;
  options.backends = {"course/semi-implicit-euler", "course/velocity-verlet"};
  options.cost = false;
  options.isolation = isolation;
  options.jobs = 2;
  return run_case(scene, Registry::load(), options);
}

TEST(Sweep, AParameterThatChangesNothingGivesIdenticalPoints) {
  // The ball falls straight down: nothing slides, so friction never acts. (Static friction
  // is swept from the kinetic one up: below it, the loader refuses the point.)
  const Scene scene = test::scene_from(
      drop_case("restitution = 0.5\nfriction_static = 0.4\nfriction_kinetic = 0.4", R"(
[[sweep]]
parameter = "ground.friction_static"
values = [0.4, 0.6, 0.9]
)"));
  const CaseResults results = swept(scene, true);
  ASSERT_TRUE(results.sweep);
  const std::vector<SweepPoint>& points = results.sweep->points;
  ASSERT_EQ(points.size(), 3u);
  EXPECT_EQ(points[2].value, 0.9);
  const std::vector<RunRecord>& first = points.front().runs;
  ASSERT_EQ(first.size(), 3u);  // the reference and two integrators
  for (const SweepPoint& p : points) {
    ASSERT_EQ(p.runs.size(), first.size());
    for (std::size_t k = 0; k < first.size(); ++k) {
      const RunRecord& a = first[k];
      const RunRecord& b = p.runs[k];
      EXPECT_EQ(b.backend, a.backend);
      ASSERT_EQ(b.status, RunStatus::Ok) << b.backend << ": " << b.reason;
      ASSERT_EQ(b.observables.size(), 1u);
      ASSERT_TRUE(b.observables[0].measured.value) << b.backend;
      EXPECT_EQ(*b.observables[0].measured.value, *a.observables[0].measured.value) << b.backend;
      if (a.errors) {
        ASSERT_TRUE(b.errors);
        EXPECT_EQ(b.errors->position_max, a.errors->position_max) << b.backend;
        EXPECT_EQ(b.errors->energy_max, a.errors->energy_max) << b.backend;
      }
    }
  }
}

TEST(Sweep, RestitutionGivesTheReferencesReboundHeightsExactly) {
  // A smooth ground: a ball that stops bouncing there simply rests.
  const Scene scene = test::scene_from(drop_case("restitution = 0.5", R"(
[[sweep]]
parameter = "ground.restitution"
values = [0.1, 0.5, 0.9]
)"));
  // In this process, so the test also covers the sweep without isolation.
  const CaseResults results = swept(scene, false);
  ASSERT_TRUE(results.sweep);
  const double r = scene.bodies[0].radius, h = scene.bodies[0].position.y() - r;
  for (const SweepPoint& p : results.sweep->points) {
    const RunRecord& reference = p.runs.front();
    ASSERT_EQ(reference.backend, "reference");
    ASSERT_EQ(reference.status, RunStatus::Ok) << reference.reason;
    const std::optional<double> apex = run_quantity(reference, "bounce_apex/ball/1");
    ASSERT_TRUE(apex) << "e = " << p.value;
    // The bottom's rebound above the ground: e^2 h.
    EXPECT_NEAR(*apex - r, p.value * p.value * h, 1e-9) << "e = " << p.value;
    // A course integrator at report_dt does not hit it exactly, but follows e^2.
    const std::optional<double> course = run_quantity(p.runs[1], "bounce_apex/ball/1");
    ASSERT_TRUE(course);
    EXPECT_NEAR(*course - r, p.value * p.value * h, 0.1) << p.runs[1].backend;
  }
  // The results JSON carries the sweep: parameter, values and a row per run per point.
  const auto json = results_json(results);
  EXPECT_EQ(json["sweep"]["parameter"], "ground.restitution");
  EXPECT_EQ(json["sweep"]["values"].size(), 3u);
  EXPECT_EQ(json["sweep"]["points"][1]["runs"].size(), 3u);
  EXPECT_EQ(json["sweep"]["points"][1]["value"], 0.5);
}

TEST(Sweep, ThePointSceneHasTheValueAndOnlyReportDt) {
  const Scene scene = test::scene_from(drop_case("restitution = 0.5", R"(
[[sweep]]
parameter = "body.ball.position.y"
range = [2.0, 3.0, 5]
)"));
  ASSERT_TRUE(scene.sweep);
  EXPECT_EQ(scene.sweep->values, (std::vector<double>{2.0, 2.25, 2.5, 2.75, 3.0}));
  const Scene point = sweep_point_scene(scene, 2.75);
  EXPECT_EQ(point.bodies[0].position.y(), 2.75);
  EXPECT_EQ(point.dt, std::vector<double>{scene.report_dt});
  EXPECT_FALSE(point.sweep);
  EXPECT_TRUE(point.gates.empty());
}

/// A 1 m crate (mu_s 0.6, mu_k 0.5) on a ground tilted by `degrees` towards +x, sent down
/// the slope at 2 m/s, written as by hand: the normal [sin, cos], the crate's centre half a
/// metre along it, its velocity along the slope and its `angle` -degrees, each number to 17
/// digits from the angle in radians as the loader reads `angle` (degrees pi / 180); then
/// `sweep`.
std::string crate_on_a_slope(double degrees, const std::string& sweep = "") {
  const double a = degrees * M_PI / 180.0, c = std::cos(a), s = std::sin(a);
  char text[1024];
  std::snprintf(text, sizeof text, R"(name = "crate"
dims = 2
duration = 1.0
sample = 0.05
dt = [0.05, 0.025]
report_dt = 0.025
[ground]
normal = [%.17g, %.17g, 0.0]
restitution = 0.0
friction_static = 0.6
friction_kinetic = 0.5
[[body]]
name = "crate"
shape = "box"
half_extents = [0.5, 0.5, 0.5]
mass = 1.0
position = [%.17g, %.17g, 0.0]
velocity = [%.17g, %.17g, 0.0]
angle = %.17g
[course]
integrators = ["semi-implicit-euler"]
[[observe]]
kind = "final_velocity"
body = "crate"
)",
                s, c, 0.5 * s, 0.5 * c, 2.0 * c, -2.0 * s, -degrees);
  return text + sweep;
}

// A point of a sweep over ground.normal is the case written by hand at that angle, row for
// row, byte for byte: every backend's status, reason, errors and observables. The crate
// used to lose the reference at 10, 11, 12 and 25 degrees ("starts moving off the ground"):
// the sweep turned it by a quaternion from one normal to the other, whose rounding left
// its velocity 1e-17 m/s off the slope, where the case by hand has none.
TEST(Sweep, AGroundTiltPointIsTheCaseWrittenByHandAtThatAngle) {
  const std::vector<double> angles{5.0, 10.0, 11.0, 12.0, 25.0};
  std::string values;
  for (double a : angles) values += (values.empty() ? "" : ", ") + std::to_string(a);
  const Scene level = test::scene_from(crate_on_a_slope(
      0.0, "[[sweep]]\nparameter = \"ground.normal\"\nvalues = [" + values + "]\n"));
  RunOptions options;
  options.cost = false;
  options.jobs = 2;
  const CaseResults swept = run_case(level, Registry::load(), options);
  const auto points = results_json(swept)["sweep"]["points"];
  ASSERT_EQ(points.size(), angles.size());
  options.dts = {level.report_dt};
  for (std::size_t i = 0; i < angles.size(); ++i) {
    const Scene by_hand = test::scene_from(crate_on_a_slope(angles[i]));
    const auto rows = results_json(run_case(by_hand, Registry::load(), options))["runs"];
    const auto& point = points[i]["runs"];
    ASSERT_EQ(point.size(), rows.size()) << angles[i];
    for (std::size_t k = 0; k < rows.size(); ++k) {
      EXPECT_EQ(test::row_text(point[k]), test::row_text(rows[k])) << angles[i] << " degrees";
      if (point[k]["backend"] == "reference") {
        EXPECT_EQ(point[k]["status"], "ok") << angles[i] << ": " << point[k]["reason"];
      }
    }
  }
}

}  // namespace
}  // namespace bb
