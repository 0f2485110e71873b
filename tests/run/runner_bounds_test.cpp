// Correct runs are never called diverged: the divergence bounds count what a case's
// impulses, spins and wind give (a big push, a fast spin, a wall blown away), and stay of
// the order of the motion.
#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <utility>
#include <vector>

#include "run/case_runner.hpp"
#include "run/divergence.hpp"
#include "support/engine_support.hpp"
#include "support/test_support.hpp"

namespace bb {
namespace {

/// Every run of `scene` at report_dt, the reference's first, on every backend there is.
std::vector<RunRecord> every_run(const Scene& scene) {
  RunOptions options;
  options.cost = false;
  options.dts = {scene.report_dt};
  CaseResults results = run_case(scene, Registry::load(), options);
  std::vector<RunRecord> out = {results.reference_run};
  for (RunRecord& r : results.runs) out.push_back(std::move(r));
  return out;
}

// Correct runs are never called diverged: the push case with impulses of 20 N s sends the
// light ball off at 20 m/s (30 m in the 1.5 s after the push), which every backend, the
// reference first, computes correctly; the bound must count the impulses.
TEST(Runner, ABigPushIsNotADivergence) {
  std::string text = test::bytes(test::source_path("cases/push.toml"));
  for (const auto& [from, to] :
       {std::pair<std::string, std::string>{"[-2.0, 0.0, 0.0]", "[-20.0, 0.0, 0.0]"},
        {"[2.0, 0.0, 0.0]", "[20.0, 0.0, 0.0]"}})
    text.replace(text.find(from), from.size(), to);
  const Scene scene = parse_case(text, "push.toml");
  const std::vector<RunRecord> runs = every_run(scene);
  EXPECT_GE(runs.size(), 5u);
  std::vector<std::string> not_built;
  for (const RunRecord& r : runs) {
    if (test::described_but_not_built(r.backend)) {
      not_built.push_back(r.backend);
      continue;
    }
    EXPECT_EQ(r.status, RunStatus::Ok) << r.backend << ": " << r.reason;
    // Right, too: the light ball's speed is J / m.
    if (r.status == RunStatus::Ok) {
      EXPECT_NEAR(r.trajectory.states.back()[0].velocity.norm(), 20.0, 1e-3) << r.backend;
    }
  }
  BB_SKIP_IF_MISSING(test::not_built(not_built));
}

// A couple of impulses off the centre spins a light ball at 1200 rad/s without moving it:
// 12 kJ of spin from nothing but the case's impulses (the bound was 10 kJ). The energy bound counts
// the spin the impulses give: no backend is diverged, and the reference and the course spin the
// ball exactly.
TEST(Runner, AFastSpinFromAnOffCentreImpulseIsNotADivergence) {
  const Scene scene = test::scene_from(R"(name = "spun"
dims = 2
duration = 1.0
sample = 0.0166666666666666667
dt = [0.0166666666666666667]
report_dt = 0.0166666666666666667
gravity = [0.0, 0.0, 0.0]
[[body]]
name = "ball"
radius = 0.5
mass = 0.1
shell = true
position = [0.0, 2.0, 0.0]
[[impulse]]
body = "ball"
time = 0.5
impulse = [20.0, 0.0, 0.0]
point = [0.0, 2.5, 0.0]
[[impulse]]
body = "ball"
time = 0.5
impulse = [-20.0, 0.0, 0.0]
point = [0.0, 1.5, 0.0]
)");
  const std::vector<RunRecord> runs = every_run(scene);
  int exact = 0;
  for (const RunRecord& r : runs) {
    // An engine may limit a spin per step (its own result), but nothing here blows up.
    EXPECT_NE(r.status, RunStatus::Diverged) << r.backend << ": " << r.reason;
    if (r.backend != "reference" && r.backend.rfind("course/", 0) != 0) continue;
    ++exact;
    ASSERT_EQ(r.status, RunStatus::Ok) << r.backend << ": " << r.reason;
    // The couple's moment 2 J r = 20 N m s over the shell's 2/3 m r^2 = 1/60 kg m^2.
    EXPECT_NEAR(std::abs(r.trajectory.states.back()[0].angular_velocity.z()), 1200.0, 1e-6)
        << r.backend;
  }
  EXPECT_EQ(exact, 5);
}

// A wall the wind pushes with 1000 N, free in the air: 2000 m in 2 s, from the case's own
// numbers. Every backend was "diverged" (the bound left out the wind's force); none is now.
TEST(Runner, AWallBlownAwayByAStrongWindIsNotADivergence) {
  const Scene scene = test::scene_from(R"(name = "blown"
dims = 2
duration = 2.0
sample = 0.0333333333333333333
dt = [0.0166666666666666667]
report_dt = 0.0166666666666666667
[[body]]
name = "panel"
shape = "box"
half_extents = [0.05, 0.5, 0.5]
mass = 1.0
position = [0.0, 0.0, 0.0]
wind_force = [1000.0, 0.0, 0.0]
)");
  EXPECT_GE(divergence_bounds(scene).travel[0], 0.5 * 1000.0 * 4.0);
  int exact = 0;
  for (const RunRecord& r : every_run(scene)) {
    EXPECT_NE(r.status, RunStatus::Diverged) << r.backend << ": " << r.reason;
    if (r.backend != "reference") continue;
    ++exact;
    ASSERT_EQ(r.status, RunStatus::Ok) << r.reason;
    EXPECT_NEAR(r.trajectory.states.back()[0].position.x(), 0.5 * 1000.0 * 4.0, 1e-6);
  }
  EXPECT_EQ(exact, 1);
}

// The bounds of the push case (2 N s on a 1 kg and a 4 kg ball, no gravity) count what the
// impulses give, and stay of that order: ten times the reach, not a bound that never fires.
TEST(Runner, TheDivergenceBoundsCountTheImpulses) {
  const Scene scene = load_case(test::source_path("cases/push.toml"));
  const DivergenceBounds bounds = divergence_bounds(scene);
  // Each ball's reach: at least J / m times the run, ten times over, and of that order.
  for (double travel : bounds.travel) {
    EXPECT_GE(travel, 10.0 * 0.5 * scene.duration);
    EXPECT_LT(travel, 100.0 * (2.0 * scene.duration + 2.0));
  }
  // The energy the impulses can give: at least the light ball's 1/2 (2 m/s)^2 x 1 kg.
  EXPECT_GE(bounds.scale.impulses, 2.0);
  EXPECT_LT(bounds.scale.total(), 100.0);
}

}  // namespace
}  // namespace bb
