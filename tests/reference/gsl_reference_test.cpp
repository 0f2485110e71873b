// The GSL reference agrees with the closed form of a vertical fall with quadratic drag.
#include "reference/gsl_reference.hpp"

#include <gtest/gtest.h>

#include "metrics/errors.hpp"
#include "reference/closed_form.hpp"
#include "run/accuracy_run.hpp"
#include "support/test_support.hpp"

namespace bb {
namespace {

TEST(GslReference, MatchesTheClosedFormOfADragFallTo1e8Relative) {
  const Scene scene = load_case(test::source_path("cases/drag_fall.toml"));
  const RunRecord run = run_accuracy(ReferenceBackend(), scene, scene.sample);
  ASSERT_EQ(run.status, RunStatus::Ok) << run.reason;
  const double g = -scene.gravity.y();
  for (std::size_t i = 0; i < scene.bodies.size(); ++i) {
    const Body& b = scene.bodies[i];
    // Every constant of the closed form comes from the case file.
    const double vt = closed_form::terminal_speed(b.mass, g, scene.air->density, b.drag_coefficient,
                                                  frontal_area(b));
    for (std::size_t j = 1; j < run.trajectory.times.size(); ++j) {
      const double t = run.trajectory.times[j];
      const BodyState& s = run.trajectory.states[j][i];
      const double fallen = b.position.y() - s.position.y();
      const double speed = -s.velocity.y();
      EXPECT_NEAR(fallen, closed_form::fall_distance(vt, g, t), 1e-8 * fallen)
          << b.name << " t=" << t;
      EXPECT_NEAR(speed, closed_form::fall_speed(vt, g, t), 1e-8 * speed) << b.name << " t=" << t;
      EXPECT_EQ(s.position.x(), b.position.x());
    }
  }
}

TEST(GslReference, StepsLandExactlyOnTheSampleTimes) {
  const Scene scene = load_case(test::source_path("cases/drag_fall.toml"));
  const RunRecord run = run_accuracy(ReferenceBackend(), scene, scene.sample);
  ASSERT_EQ(static_cast<int>(run.trajectory.times.size()), scene.sample_count() + 1);
  EXPECT_EQ(run.trajectory.times.back(), scene.sample_count() * scene.sample);
  // steps counts GSL's own adaptive steps over the whole run: at least one per sample, and
  // far fewer than a fixed-step method needs.
  EXPECT_GE(run.steps, scene.sample_count());
  EXPECT_LT(run.steps, 10 * scene.sample_count());
}

TEST(GslReference, TighterToleranceChangesItLittle) {
  const Scene scene = load_case(test::source_path("cases/magnus_throw.toml"));
  const RunRecord loose = run_accuracy(ReferenceBackend(1e-6), scene, scene.sample);
  const RunRecord tight = run_accuracy(ReferenceBackend(1e-12), scene, scene.sample);
  double worst = 0.0;
  for (std::size_t j = 0; j < loose.trajectory.states.size(); ++j)
    for (std::size_t i = 0; i < scene.bodies.size(); ++i)
      worst = std::max(
          worst,
          (loose.trajectory.states[j][i].position - tight.trajectory.states[j][i].position).norm());
  EXPECT_GT(worst, 0.0);
  EXPECT_LT(worst, 1e-4);
}

// A light body in drag is stiff (tiny_mass_fall: 1e-7 kg, terminal speed about 1 cm/s): the
// reference changes to msbdf, says so, and still matches the closed form to 1e-8.
TEST(GslReference, SolvesAStiffFallImplicitlyAndNamesTheMethod) {
  const Scene scene = load_case(test::source_path("cases/tiny_mass_fall.toml"));
  const RunRecord run = run_accuracy(ReferenceBackend(), scene, scene.sample);
  ASSERT_EQ(run.status, RunStatus::Ok) << run.reason;
  std::string method;
  for (const auto& [key, value] : run.engine_settings)
    if (key == "method") method = std::get<std::string>(value);
  EXPECT_NE(method.find("msbdf"), std::string::npos) << method;
  const Body& b = scene.bodies[0];
  const double g = -scene.gravity.y();
  const double vt = closed_form::terminal_speed(b.mass, g, scene.air->density, b.drag_coefficient,
                                                frontal_area(b));
  for (std::size_t j = 1; j < run.trajectory.times.size(); ++j) {
    const double t = run.trajectory.times[j];
    const BodyState& s = run.trajectory.states[j][0];
    const double fallen = b.position.y() - s.position.y();
    EXPECT_NEAR(fallen, closed_form::fall_distance(vt, g, t), 1e-8 * fallen) << "t=" << t;
    EXPECT_NEAR(-s.velocity.y(), closed_form::fall_speed(vt, g, t), 1e-8 * vt) << "t=" << t;
  }
}

// The self-check is a real second solve: forced smaller steps make it differ from the
// reference even where the sample times limit both (it was exactly 0 there before), and it
// stays far below the tolerance's scale.
TEST(GslReference, TheSelfCheckDiffersFromTheReferenceButLittle) {
  for (const char* name : {"cases/drag_fall.toml", "cases/tiny_mass_fall.toml"}) {
    const Scene scene = load_case(test::source_path(name));
    const RunRecord reference = run_accuracy(ReferenceBackend(), scene, scene.sample);
    const RunRecord check = run_accuracy(ReferenceBackend().self_check(), scene, scene.sample);
    const double d = max_position_difference(reference.trajectory, check.trajectory);
    EXPECT_GT(d, 0.0) << name;
    EXPECT_LT(d, 1e-6) << name;
    EXPECT_GT(check.steps, reference.steps) << name;
  }
}

}  // namespace
}  // namespace bb
