// The reference on plank_axis: a plank on an axis, hit at its end, spins at the impulse's
// moment about the axis over the parallel-axis inertia 1/12 m (l^2 + t^2) + m a^2, and the
// point of the plank on the axis never leaves it.
#include <gtest/gtest.h>

#include "metrics/observables.hpp"
#include "reference/gsl_reference.hpp"
#include "run/accuracy_run.hpp"
#include "scene/load_case.hpp"
#include "support/test_support.hpp"

namespace bb {
namespace {

TEST(HingeReference, APlankOnAnAxisSpinsByTheParallelAxisTheoremAndKeepsItsAnchor) {
  const Scene scene = load_case(test::source_path("cases/plank_axis.toml"));
  const RunRecord run = run_accuracy(ReferenceBackend(), scene, scene.report_dt);
  ASSERT_EQ(run.status, RunStatus::Ok) << run.reason;
  for (const Hinge& h : scene.hinges) {
    const Body& b = scene.bodies[h.body];
    const double l = 2.0 * b.half_extents.x(), t = 2.0 * b.half_extents.y();
    const double a = (h.anchor - b.position).norm();
    const Impulse& hit = scene.impulses[h.body];
    const double moment = std::abs((*hit.point - h.anchor).cross(hit.impulse).z());
    const double expected = moment / (b.mass * (l * l + t * t) / 12.0 + b.mass * a * a);
    const Observe spin{"post_angular_velocity", h.body, 0, 0, ""};
    const ObservableValue measured = measure(scene, spin, run.trajectory, nullptr);
    ASSERT_TRUE(measured.value) << measured.note;
    EXPECT_NEAR(*measured.value, expected, 1e-9) << b.name;
    // The body point on the axis, carried by the body, stays on the anchor.
    const Vec3 local = b.orientation.conjugate() * (h.anchor - b.position);
    for (const State& s : run.trajectory.states)
      ASSERT_LT((s[h.body].position + s[h.body].orientation * local - h.anchor).norm(), 1e-9)
          << b.name;
  }
}

}  // namespace
}  // namespace bb
