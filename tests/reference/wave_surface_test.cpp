// The Gerstner surface of seed section 10: the reference is the text's formula, and the
// surface folds over itself exactly when amplitude k > 1 (d x / d x0 = 1 - amplitude k
// sin(phase) turns negative at the crests).
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "observe/observables.hpp"
#include "run/accuracy_run.hpp"
#include "run/registry.hpp"
#include "support/engine_support.hpp"
#include "support/test_support.hpp"

namespace bb {
namespace {

/// Two wavelengths of surface at wavenumber `k`, `points` points, amplitude `amp`.
Scene waves(double amp, double k, int points = 401) {
  char text[600];
  std::snprintf(text, sizeof text,
                "name = \"w\"\ndims = 2\nduration = 3.0\nsample = 0.05\ndt = [0.05]\n"
                "gravity = [0.0, 0.0, 0.0]\n[waves]\namplitude = %.17g\nwavenumber = %.17g\n"
                "speed = 2.0\npoints = %d\nfrom = 0.0\nto = %.17g\nlevel = 1.5\n"
                "[[observe]]\nkind = \"surface_fold\"\n",
                amp, k, points, 4.0 * std::numbers::pi / k);
  return test::scene_from(text);
}

double fold(const Scene& scene) {
  const RunRecord run = run_accuracy(test::registry().reference(), scene, scene.sample);
  EXPECT_EQ(run.status, RunStatus::Ok) << run.reason;
  return *measure(scene, scene.observes[0], run.trajectory, nullptr).value;
}

TEST(WaveSurface, EveryPointIsWhereTheTextsFormulaPutsIt) {
  const Scene scene = waves(0.3, 2.0, 11);
  const RunRecord run = run_accuracy(test::registry().reference(), scene, scene.sample);
  ASSERT_EQ(run.status, RunStatus::Ok) << run.reason;
  const Waves& w = *scene.waves;
  for (std::size_t s = 0; s < run.trajectory.states.size(); ++s) {
    const double t = run.trajectory.times[s];
    for (int i = 0; i < w.points; ++i) {
      const double x0 = w.rest_x(i), phase = 2.0 * t + 2.0 * x0;
      const BodyState& b = run.trajectory.states[s][static_cast<std::size_t>(i)];
      EXPECT_NEAR(b.position.x(), x0 + 0.3 * std::cos(phase), 1e-12);
      EXPECT_NEAR(b.position.y(), 1.5 + 0.3 * std::sin(phase), 1e-12);
      // Each point turns on its circle at the phase's rate.
      EXPECT_NEAR(b.velocity.norm(), 0.3 * 2.0, 1e-12);
    }
  }
}

TEST(WaveSurface, FoldsExactlyWhenAmplitudeTimesWavenumberPassesOne) {
  for (const double k : {1.0, 2.5}) {
    SCOPED_TRACE(k);
    // Neighbours 4 pi / (400 k) apart: the discrete slope differs from 1 - amp k sin by
    // about (k h)^2 / 24 = 4e-5 at most.
    for (const double ak : {0.5, 0.99, 1.01, 1.5}) {
      const double value = fold(waves(ak / k, k));
      EXPECT_NEAR(value, 1.0 - ak, 1e-3) << "amp k = " << ak;
      EXPECT_EQ(value<0.0, ak> 1.0) << "amp k = " << ak;
    }
  }
}

TEST(WaveSurface, OnlyTheReferenceRunsItAndTheOthersSayWhy) {
  const Scene scene = waves(0.5, 1.0, 21);
  BackendSet set = backends_for(scene, test::registry());
  ASSERT_FALSE(set.all.empty());
  for (const Backend* b : set.all) {
    const RunRecord run = run_accuracy(*b, scene, scene.dt.front());
    EXPECT_EQ(run.status, RunStatus::Unsupported) << b->name();
    EXPECT_NE(run.reason.find("nothing to integrate"), std::string::npos) << run.reason;
  }
}

}  // namespace
}  // namespace bb
