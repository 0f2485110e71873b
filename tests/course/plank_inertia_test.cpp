// The seed's plank on an axis against the parallel-axis theorem: its formula gives each
// side of the axis the whole plank's mass, so at the centre it is twice the truth, and it
// agrees only with the axis at an end, where one side has no length.
#include "course/plank_inertia.hpp"

#include <gtest/gtest.h>

#include "course/course_backend.hpp"
#include "observe/observables.hpp"
#include "run/accuracy_run.hpp"
#include "run/case_loading.hpp"
#include "support/test_support.hpp"

namespace bb {
namespace {

using course::plank_axis_inertia;
using course::seed_axis_inertia;

TEST(PlankInertia, ParallelAxisEqualsTheTwoSidesWithTheirOwnMass) {
  // Each side as a rod about its end with its share of the mass, m d / l.
  const double m = 2.0, l = 5.0;
  for (double a : {0.0, 0.5, 1.25, 2.0, 2.5}) {
    const double d1 = l / 2 - a, d2 = l / 2 + a;
    const double sides = (m * d1 / l) * d1 * d1 / 3.0 + (m * d2 / l) * d2 * d2 / 3.0;
    EXPECT_NEAR(plank_axis_inertia(m, l, a), sides, 1e-12) << a;
  }
}

TEST(PlankInertia, TheSeedsFormulaIsTwiceTheTruthAtTheCentreAndRightAtAnEnd) {
  const double m = 2.0, l = 5.0;
  EXPECT_NEAR(seed_axis_inertia(m, l, 0.0) / plank_axis_inertia(m, l, 0.0), 2.0, 1e-12);
  EXPECT_NEAR(seed_axis_inertia(m, l, l / 2) / plank_axis_inertia(m, l, l / 2), 1.0, 1e-12);
  // Between, it overestimates, less and less towards the end.
  double previous = 2.0;
  for (double a : {0.5, 1.0, 1.5, 2.0}) {
    const double ratio = seed_axis_inertia(m, l, a) / plank_axis_inertia(m, l, a);
    EXPECT_GT(ratio, 1.0) << a;
    EXPECT_LT(ratio, previous) << a;
    previous = ratio;
  }
}

// The course on plank_axis turns each plank with the seed's J: its spin after the hit is
// the impulse's moment about z over 1/3 m d1^2 + 1/3 m d2^2, half the true spin at the
// centre, turning the way the moment does.
TEST(PlankInertia, TheCourseSpinsEachPlankWithTheSeedsInertia) {
  const Scene scene = load_case(test::source_path("cases/plank_axis.toml"));
  const CourseBackend backend(
      {"course/semi-implicit-euler", "semi-implicit-euler", "mirror", "clamp"});
  const RunRecord run = run_accuracy(backend, scene, scene.report_dt);
  ASSERT_EQ(run.status, RunStatus::Ok) << run.reason;
  for (const Hinge& h : scene.hinges) {
    const Body& b = scene.bodies[h.body];
    const double a = (h.anchor - b.position).x();
    const Impulse& hit = scene.impulses[h.body];
    const double moment = (*hit.point - h.anchor).cross(hit.impulse).z();
    const Observe spin{"post_angular_velocity", h.body, 0, 0, ""};
    const ObservableValue measured = measure(scene, spin, run.trajectory, nullptr);
    ASSERT_TRUE(measured.value) << measured.note;
    EXPECT_NEAR(*measured.value, moment / seed_axis_inertia(b.mass, 5.0, a), 1e-12) << b.name;
  }
}

}  // namespace
}  // namespace bb
