// Error norms pick the worst body and the right sample.
#include "metrics/errors.hpp"

#include <gtest/gtest.h>

#include "support/test_support.hpp"

namespace bb {
namespace {

TEST(ErrorMetrics, WorstBodyMaxRmsAndFinal) {
  std::string text = test::kMinimalCase;
  text += "\n[[body]]\nname = \"other\"\nradius = 0.5\nmass = 1.0\n";
  const Scene scene = test::scene_from(text);
  Trajectory ref, run;
  for (int j = 0; j < 4; ++j) {
    State r(2), s(2);
    r[0].position = {0, 10.0 - j, 0};
    r[1].position = {5, 10.0, 0};
    s = r;
    s[0].position.y() += 0.1 * j;              // body 0 drifts: 0, 0.1, 0.2, 0.3
    s[1].position.x() += j == 1 ? 0.25 : 0.0;  // body 1 jumps once
    ref.times.push_back(j);
    run.times.push_back(j);
    ref.states.push_back(r);
    run.states.push_back(s);
  }
  const ErrorMetrics m = compare(scene, run, ref);
  EXPECT_NEAR(m.position_max, 0.3, 1e-12);
  EXPECT_NEAR(m.position_final, 0.3, 1e-12);
  EXPECT_NEAR(m.position_rms, std::sqrt((0.01 + 0.04 + 0.09) / 4.0), 1e-12);
  EXPECT_EQ(m.velocity_max, 0.0);
  // Body 0's potential energy differs by m g dy; the scale is |E_ref(0)|.
  const double scale = 1.0 * 9.81 * 20.0;
  EXPECT_NEAR(m.energy_max, 9.81 * 0.3 / scale, 1e-12);
  EXPECT_EQ(m.get("position_final"), m.position_final);
  EXPECT_THROW(m.get("nonsense"), std::invalid_argument);
  // Each body's own: body 1 jumped 0.25 m once and ends where the reference is.
  ASSERT_EQ(m.bodies.size(), 2u);
  EXPECT_EQ(m.worst_body(), 0);
  EXPECT_NEAR(m.bodies[1].position_max, 0.25, 1e-12);
  EXPECT_NEAR(m.bodies[1].position_rms, std::sqrt(0.0625 / 4.0), 1e-12);
  EXPECT_EQ(m.bodies[1].position_final, 0.0);
  EXPECT_EQ(m.bodies[0].position_max, m.position_max);
}

TEST(ErrorMetrics, TheWorstBodyIsTheOneFarthestFromTheReference) {
  std::string text = test::kMinimalCase;
  text += "\n[[body]]\nname = \"other\"\nradius = 0.5\nmass = 1.0\n";
  const Scene scene = test::scene_from(text);
  Trajectory ref, run;
  for (int j = 0; j < 3; ++j) {
    State r(2);
    r[1].position = {5, 0, 0};
    State s = r;
    s[1].position.x() += 0.5 * j;  // only the second body is off
    ref.times.push_back(j), run.times.push_back(j);
    ref.states.push_back(r), run.states.push_back(s);
  }
  const ErrorMetrics m = compare(scene, run, ref);
  EXPECT_EQ(m.worst_body(), 1);
  EXPECT_EQ(m.bodies[0].position_max, 0.0);
  EXPECT_NEAR(m.position_max, 1.0, 1e-12);
  EXPECT_EQ(ErrorMetrics{}.worst_body(), -1);
}

}  // namespace
}  // namespace bb
