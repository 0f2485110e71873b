// The Gerstner surface of seed section 10: the reference is the text's formula, and the
// surface folds over itself exactly when amplitude k > 1 (d x / d x0 = 1 - amplitude k
// sin(phase) turns negative at the crests).
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "observe/observables.hpp"
#include "run/accuracy_run.hpp"
#include "run/case_runner.hpp"
#include "run/registry.hpp"
#include "study/case_error.hpp"
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
  const Scene scene = waves(0.3, 2.0, 21);
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

// A sweep over the wavenumber up to what the points resolve (k h = 1 rad): at every point
// surface_fold, taken between neighbours h apart, is 1 - amp k sin(k h / 2) / (k h / 2), so
// within 5% of the wave's 1 - amp k on its wave part; one value past it is refused when the
// case loads, with the value and the points that would do. A sweep to k = 40 used to print
// -15.8 (formula -19), and to k = 1000 "never folds" (0.99999999998; formula -499), `ok`.
TEST(WaveSurface, AWavenumberSweepStopsWhereThePointsStopResolvingTheWave) {
  const std::string surface =
      "name = \"w\"\ndims = 2\nduration = 6.0\nsample = 0.1\ndt = [0.1]\n"
      "gravity = [0.0, 0.0, 0.0]\n[waves]\namplitude = 0.5\nwavenumber = 1.0\npoints = 251\n"
      "from = 0.0\nto = 12.566370614359172\n[[observe]]\nkind = \"surface_fold\"\n"
      "[[sweep]]\nparameter = \"waves.wavenumber\"\n";
  const double h = 12.566370614359172 / 250.0, most = 1.0 / h;
  // 19.89: the largest wavenumber the 251 points resolve, 1 / h = 19.894, to four digits.
  const Scene scene = test::scene_from(surface + "values = [1.0, 5.0, 10.0, 15.0, 19.89]\n");
  RunOptions options;
  options.cost = false;
  options.isolation = false;
  const CaseResults results = run_case(scene, test::registry(), options);
  ASSERT_TRUE(results.sweep);
  for (const SweepPoint& p : results.sweep->points) {
    const RunRecord& reference = p.runs.front();
    ASSERT_EQ(reference.status, RunStatus::Ok) << p.value << ": " << reference.reason;
    const std::optional<double> value = run_quantity(reference, "surface_fold");
    ASSERT_TRUE(value) << p.value;
    const double ak = 0.5 * p.value, half = p.value * h / 2.0;
    EXPECT_NEAR(*value, 1.0 - ak * std::sin(half) / half, 1e-3 * ak) << "k = " << p.value;
    EXPECT_LE(std::abs(*value - (1.0 - ak)), 0.05 * ak) << "k = " << p.value;
  }
  // Just past the rule, and the wavenumbers: refused on the sweep's line.
  for (const double k : {most * 1.001, 40.0, 100.0, 1000.0}) {
    try {
      test::scene_from(surface + "values = [1.0, " + std::to_string(k) + "]\n");
      ADD_FAILURE() << "k = " << k << " loaded";
    } catch (const CaseError& e) {
      EXPECT_NE(e.problem().find("'waves.wavenumber' puts neighbouring surface points"),
                std::string::npos)
          << e.what();
      EXPECT_NE(e.problem().find("more than 1 rad"), std::string::npos) << e.what();
    }
  }
}

}  // namespace
}  // namespace bb
