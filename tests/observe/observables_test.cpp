// final_speed is the speed at the end of a run; terminal_velocity compares the speed
// relative to the air at the end with sqrt(2 m g / (rho Cd A)) computed from the scene.
#include "observe/observables.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <string>
#include <vector>

#include "observe/hinge_observables.hpp"
#include "report/summary_tables.hpp"
#include "run/case_runner.hpp"
#include "support/test_support.hpp"

namespace bb {
namespace {

const ObservableResult& observable(const RunRecord& run, const std::string& name) {
  for (const ObservableResult& o : run.observables)
    if (o.name == name) return o;
  throw std::runtime_error(run.backend + " has no observable " + name);
}

/// The terminal speed from the scene's own numbers, written out here once more.
double elephant_terminal_speed(const Scene& scene) {
  const Body& b = scene.bodies[scene.body_index("elephant")];
  const double g = std::hypot(scene.gravity.x(), scene.gravity.y(), scene.gravity.z());
  const double area = std::numbers::pi * b.radius * b.radius;
  return std::sqrt(2.0 * b.mass * g / (scene.air->density * b.drag_coefficient * area));
}

class DragFall : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    scene_ = new Scene(load_case(test::source_path("cases/drag_fall.toml")));
    RunOptions options;
    options.backends = {"course/semi-implicit-euler"};
    options.dts = {scene_->report_dt};
    options.cost = false;
    options.isolation = false;
    results_ = new CaseResults(run_case(*scene_, Registry::load(), options));
  }
  static void TearDownTestSuite() {
    delete results_;
    delete scene_;
  }
  static const RunRecord& euler() {
    for (const RunRecord& r : results_->runs)
      if (r.backend == "course/semi-implicit-euler") return r;
    throw std::runtime_error("no semi-implicit Euler run");
  }
  static Scene* scene_;
  static CaseResults* results_;
  /// The two runs every property is checked on.
  static std::vector<const RunRecord*> runs() { return {&results_->reference_run, &euler()}; }
};
Scene* DragFall::scene_ = nullptr;
CaseResults* DragFall::results_ = nullptr;

TEST_F(DragFall, TerminalVelocityIsTheFormulaFromTheScenesNumbers) {
  const double expected = elephant_terminal_speed(*scene_);
  EXPECT_NEAR(expected, 30.46, 0.01);  // the issue's number, a check on this test itself
  for (const RunRecord* run : runs()) {
    const ObservableResult& tv = observable(*run, "terminal_velocity/elephant");
    ASSERT_TRUE(tv.reference.has_value()) << run->backend;
    EXPECT_NEAR(*tv.reference / expected, 1.0, 1e-12) << run->backend;
  }
}

TEST_F(DragFall, FinalSpeedIsTheSpeedAtTheEnd) {
  const int elephant = scene_->body_index("elephant");
  for (const RunRecord* run : runs()) {
    const ObservableResult& fs = observable(*run, "final_speed/elephant");
    ASSERT_TRUE(fs.measured.value.has_value()) << run->backend;
    const Vec3 v = run->trajectory.states.back()[elephant].velocity;
    EXPECT_EQ(*fs.measured.value, std::hypot(v.x(), v.y(), v.z())) << run->backend;
  }
  // A backend's final_speed is compared with the reference's, not with a formula.
  const ObservableResult& fs = observable(euler(), "final_speed/elephant");
  EXPECT_EQ(fs.reference,
            observable(results_->reference_run, "final_speed/elephant").measured.value);
}

TEST_F(DragFall, TheReferencesFinalSpeedApproachesTheTerminalSpeed) {
  const double vt = elephant_terminal_speed(*scene_);
  const int elephant = scene_->body_index("elephant");
  // From rest the speed climbs towards v_t and never passes it.
  double previous = 0.0;
  for (const State& s : results_->reference_run.trajectory.states) {
    const double speed = s[elephant].velocity.norm();
    EXPECT_GE(speed, previous);
    EXPECT_LT(speed, vt);
    previous = speed;
  }
  const double final_speed =
      *observable(results_->reference_run, "final_speed/elephant").measured.value;
  EXPECT_GT(final_speed, 0.95 * vt);
  // Without wind the speed relative to the air is the speed: how close it came to v_t.
  const ObservableResult& tv = observable(results_->reference_run, "terminal_velocity/elephant");
  EXPECT_EQ(*tv.measured.value, final_speed);
  EXPECT_NEAR(*metric_value(euler(), "terminal_velocity/elephant"),
              vt - *observable(euler(), "final_speed/elephant").measured.value, 1e-12);
}

TEST_F(DragFall, TheReferenceRowShowsHowFarItIsFromTheTerminalSpeed) {
  const Table t = summary_table(*results_, scene_->report_dt);
  std::size_t column = 0;
  while (column < t.headers.size() && t.headers[column] != "terminal_velocity/elephant") ++column;
  ASSERT_LT(column, t.headers.size());
  ASSERT_EQ(t.rows[0][0], "reference");
  // A value and, in brackets, its (negative) difference from v_t.
  EXPECT_NE(t.rows[0][column].find(" (-"), std::string::npos) << t.rows[0][column];
}

TEST(Observables, TerminalVelocityUsesTheSpeedRelativeToTheAir) {
  std::string text = test::kMinimalCase;
  text.replace(text.find("density = 1.2"), 13, "density = 1.2\nwind = [-5.0, 0.0, 0.0]");
  Scene scene = test::scene_from(text +
                                 "\n[[observe]]\nkind = \"terminal_velocity\"\nbody = "
                                 "\"ball\"\n\n[[observe]]\nkind = \"final_speed\"\nbody "
                                 "= \"ball\"\n");
  Trajectory trajectory;
  trajectory.times = {0.0};
  trajectory.states = {{BodyState{{0, 0, 0}, {-5.0, -3.0, 0.0}, {}, {}}}};
  EXPECT_EQ(measure(scene, scene.observes[0], trajectory, nullptr).value, 3.0);
  EXPECT_EQ(measure(scene, scene.observes[1], trajectory, nullptr).value, std::sqrt(34.0));
}

TEST(Observables, TerminalVelocityDoesNotApplyWithoutDragOrGravity) {
  const std::string observe = "\n[[observe]]\nkind = \"terminal_velocity\"\nbody = \"ball\"\n";
  std::string no_drag = test::kMinimalCase;
  no_drag.replace(no_drag.find("drag_coefficient = 0.47"), 23, "");
  std::string no_gravity = test::kMinimalCase;
  no_gravity.replace(no_gravity.find("[air]"), 5, "gravity = [0.0, 0.0, 0.0]\n\n[air]");
  for (const auto& [text, why] :
       {std::pair{no_drag, "does not apply: ball has no drag (no force holds it against gravity)"},
        std::pair{no_gravity, "does not apply: the case has no gravity"}}) {
    const Scene scene = test::scene_from(text + observe);
    Trajectory trajectory;
    trajectory.times = {0.0};
    trajectory.states = {{BodyState{{0, 0, 0}, {0.0, -3.0, 0.0}, {}, {}}}};
    const ObservableValue v = measure(scene, scene.observes[0], trajectory, nullptr);
    EXPECT_FALSE(v.value.has_value());
    EXPECT_EQ(v.note, why);
    EXPECT_FALSE(formula_value(scene, scene.observes[0]).has_value());
  }
}

// terminal_time: the first time the speed relative to the air reaches 95 % of the terminal
// speed, placed between the two samples around it by a straight line; a run that never
// gets there says so, and a body the terminal speed does not apply to says why.
TEST(Observables, TerminalTimeIsWhenTheSpeedFirstReaches95PercentOfTheTerminalSpeed) {
  const Scene scene =
      test::scene_from(test::kMinimalCase +
                       std::string("\n[[observe]]\nkind = \"terminal_time\"\nbody = \"ball\"\n"));
  const double vt = *terminal_speed(scene, scene.bodies[0]).value;
  Trajectory trajectory;
  trajectory.times = {0.0, 1.0, 2.0, 3.0};
  for (double speed : {0.0, 5.0, 0.96 * vt, 0.9 * vt})
    trajectory.states.push_back({BodyState{{0, 0, 0}, {0.0, -speed, 0.0}, {}, {}}});
  const ObservableValue v = measure(scene, scene.observes[0], trajectory, nullptr);
  ASSERT_TRUE(v.value.has_value()) << v.note;
  EXPECT_NEAR(*v.value, 1.0 + (0.95 * vt - 5.0) / (0.96 * vt - 5.0), 1e-12);
  trajectory.states[2][0].velocity.y() = -0.9 * vt;
  const ObservableValue never = measure(scene, scene.observes[0], trajectory, nullptr);
  EXPECT_FALSE(never.value.has_value());
  EXPECT_NE(never.note.find("never reached 95 %"), std::string::npos) << never.note;
  std::string no_drag = test::kMinimalCase;
  no_drag.replace(no_drag.find("drag_coefficient = 0.47"), 23, "");
  const Scene plain =
      test::scene_from(no_drag + "\n[[observe]]\nkind = \"terminal_time\"\nbody = \"ball\"\n");
  EXPECT_EQ(measure(plain, plain.observes[0], trajectory, nullptr).note,
            "does not apply: ball has no drag (no force holds it against gravity)");
}

// final_height is the centre's height along -gravity at the end of the run, whatever the
// direction gravity points in; without gravity it does not apply.
TEST(Observables, FinalHeightIsTheHeightAlongMinusGravityAtTheEnd) {
  const std::string observe = "\n[[observe]]\nkind = \"final_height\"\nbody = \"ball\"\n";
  Trajectory trajectory;
  trajectory.times = {0.0, 1.0};
  trajectory.states = {{BodyState{{0.0, 9.0, 0.0}, {}, {}, {}}},
                       {BodyState{{2.0, 3.0, -4.0}, {0.0, -3.0, 0.0}, {}, {}}}};
  const Scene scene = test::scene_from(test::kMinimalCase + observe);
  EXPECT_DOUBLE_EQ(*measure(scene, scene.observes[0], trajectory, nullptr).value, 3.0);
  std::string sideways = test::kMinimalCase;
  sideways.replace(sideways.find("[air]"), 5, "gravity = [-2.0, 0.0, 0.0]\n\n[air]");
  const Scene side = test::scene_from(sideways + observe);
  EXPECT_DOUBLE_EQ(*measure(side, side.observes[0], trajectory, nullptr).value, 2.0);
  std::string none = test::kMinimalCase;
  none.replace(none.find("[air]"), 5, "gravity = [0.0, 0.0, 0.0]\n\n[air]");
  const Scene floating = test::scene_from(none + observe);
  const ObservableValue v = measure(floating, floating.observes[0], trajectory, nullptr);
  EXPECT_FALSE(v.value.has_value());
  EXPECT_EQ(v.note, "does not apply: the case has no gravity");
}

// final_shear is the largest relative change of a grid cell's diagonal from the start to
// the end: a unit cell whose lower row slides half a side along x lengthens one diagonal to
// sqrt(1.5^2 + 1) and shortens the other to sqrt(0.5^2 + 1); the larger change counts.
TEST(Observables, FinalShearIsTheLargestChangeOfACellDiagonal) {
  const Scene scene = test::scene_from(
      "name = \"g\"\ndims = 2\nduration = 1.0\nsample = 0.1\ndt = [0.1]\n"
      "gravity = [0.0, 0.0, 0.0]\n[grid]\nsize = [2, 2]\nspacing = 1.0\nneighbours = 4\n"
      "[[observe]]\nkind = \"final_shear\"\n");
  State start;
  for (const Body& b : scene.bodies) start.push_back(BodyState{b.position, {}, {}, {}});
  ASSERT_EQ(start.size(), 4u);
  State sheared = start;
  sheared[2].position.x() += 0.5;  // p0_1 and p1_1: the row below the first
  sheared[3].position.x() += 0.5;
  Trajectory trajectory;
  trajectory.times = {0.0, 1.0};
  trajectory.states = {start, start};
  EXPECT_DOUBLE_EQ(*measure(scene, scene.observes[0], trajectory, nullptr).value, 0.0);
  trajectory.states = {start, sheared};
  EXPECT_NEAR(*measure(scene, scene.observes[0], trajectory, nullptr).value,
              std::sqrt(3.25) / std::sqrt(2.0) - 1.0, 1e-12);
  const ObservableValue none = final_shear(test::scene_from(test::kMinimalCase), start, start);
  EXPECT_FALSE(none.value.has_value());
  EXPECT_EQ(none.note, "does not apply: the case has no [grid]");
}

// A ball dropped on the ground: contact_time and bounce_apex reach the results through the
// runner, from the reference's located events (the closed form) and from every course step.
TEST(DroppedBall, BounceObservablesComeFromTheRunsEvents) {
  const Scene scene = test::scene_from(R"(name = "drop"
dims = 2
duration = 2.0
sample = 0.1
dt = [0.001]
[ground]
restitution = 0.5
[[body]]
name = "ball"
radius = 0.5
mass = 1.0
position = [0.0, 5.5, 0.0]
[[observe]]
kind = "contact_time"
body = "ball"
n = 1
[[observe]]
kind = "bounce_apex"
body = "ball"
n = 1
)");
  RunOptions options;
  options.backends = {"course/semi-implicit-euler"};
  options.dts = {0.001};
  options.cost = false;
  options.isolation = false;
  const CaseResults results = run_case(scene, Registry::load(), options);
  // Falling 5 m from rest: t = sqrt(2 h / g); it leaves at e v and rises (e v)^2 / 2g.
  const double g = 9.81, t = std::sqrt(2.0 * 5.0 / g), v = g * t;
  const double apex = 0.5 + (0.5 * v) * (0.5 * v) / (2.0 * g);
  const RunRecord& reference = results.reference_run;
  EXPECT_NEAR(observable(reference, "contact_time/ball/1").measured.value.value(), t, 1e-9);
  EXPECT_NEAR(observable(reference, "bounce_apex/ball/1").measured.value.value(), apex, 1e-8);
  ASSERT_FALSE(results.runs.empty());
  const RunRecord& euler = results.runs.front();
  EXPECT_NEAR(observable(euler, "contact_time/ball/1").measured.value.value(), t, 2e-3);
  EXPECT_NEAR(observable(euler, "bounce_apex/ball/1").measured.value.value(), apex, 2e-2);
}

// The hinge force by the hinge's law: a plank hanging still from its end is held up by
// exactly its weight; spinning without gravity about its end, it is pulled in by m w^2 d.
TEST(HingeForce, HoldsTheWeightAndSuppliesTheCentripetalPull) {
  Scene scene = test::scene_from(R"(name = "x"
dims = 2
duration = 1.0
sample = 0.1
dt = [0.1, 0.05]
report_dt = 0.05
[[body]]
name = "plank"
shape = "box"
half_extents = [0.1, 1.0, 0.1]
mass = 2.0
position = [0.0, -1.0, 0.0]
[[hinge]]
body = "plank"
anchor = [0.0, 0.0, 0.0]
axis = [0.0, 0.0, 1.0]
)");
  BodyState s{scene.bodies[0].position, Vec3::Zero(), Quat::Identity(), Vec3::Zero()};
  EXPECT_LT((hinge_force(scene, scene.hinges[0], s) - Vec3(0.0, 2.0 * 9.81, 0.0)).norm(), 1e-12);
  scene.gravity = Vec3::Zero();
  s.angular_velocity = {0.0, 0.0, 3.0};
  s.velocity = s.angular_velocity.cross(s.position);
  EXPECT_LT((hinge_force(scene, scene.hinges[0], s) - Vec3(0.0, 2.0 * 9.0 * 1.0, 0.0)).norm(),
            1e-12);
}

}  // namespace
}  // namespace bb
