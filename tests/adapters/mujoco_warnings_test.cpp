// MuJoCo 2.2.2 resets its data to the initial state when a position, velocity or acceleration
// is NaN or beyond 1e10 (mj_checkPos, mj_checkVel, mj_checkAcc: mjWARN_BADQPOS, BADQVEL,
// BADQACC), warns once and steps on. Issue 36: the rows stayed `ok`, with tiny_mass_fall's
// terminal velocity at 16,796 m/s (true 0.0105) and a 1e-9 kg ball pushed by 100 N moving at
// g dt. A reset is a divergence at the reset's time, with MuJoCo's warning as the reason, on
// every MuJoCo backend and in the stability search. A contact list that is full (nconmax, 100
// by default) drops what does not fit: a cap of the engine's, and the row says so.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <memory>
#include <string>

#include "observe/observables.hpp"
#include "run/accuracy_run.hpp"
#include "run/case_loading.hpp"
#include "run/stability.hpp"
#include "study/start_case.hpp"
#include "support/engine_support.hpp"
#include "support/test_support.hpp"

namespace bb {
namespace {

const char* const kMujocos[] = {"mujoco", "mujoco/rk4", "mujoco/implicit"};

/// The first step after which `backend`'s body 0, having flown off at a hundred times what
/// one step of gravity gives, is back at rest but for that one step: where MuJoCo's reset
/// put it (0 when it never was).
long first_return(const Backend& backend, const Scene& scene, double dt) {
  const auto sim = start_case(backend, scene, dt);
  State s(scene.bodies.size());
  const double one_step = scene.gravity.norm() * dt;
  bool flown = false;
  for (long n = 1; n <= static_cast<long>(std::lround(scene.duration / dt)); ++n) {
    sim->step();
    sim->read(s);
    const double speed = s[0].velocity.norm();
    if (flown && speed <= 2.0 * one_step) return n;
    flown = flown || speed > 100.0 * one_step;
  }
  return 0;
}

// The mote of tiny_mass_fall: at every step of the case, every MuJoCo row either finds the
// terminal velocity sqrt(2 m g / (rho Cd A)) to a percent or has diverged; where it diverged
// on a reset, the time is the reset's, seen in the state jumping back to the start.
TEST(MujocoWarnings, TheMoteIsRightOrDivergedNeverOkWithAResetsNumber) {
  const Scene scene = load_case(test::source_path("cases/tiny_mass_fall.toml"));
  const double terminal = *formula_value(scene, scene.observes.front());
  int resets = 0;
  for (const char* name : kMujocos) {
    const Backend* b = test::engine(name);
    if (b == nullptr) continue;
    for (double dt : scene.dt) {
      SCOPED_TRACE(std::string(name) + " at dt " + std::to_string(dt));
      const RunRecord run = run_accuracy(*b, scene, dt);
      if (run.status == RunStatus::Ok) {
        const auto v = measure(scene, scene.observes.front(), run.trajectory, nullptr).value;
        ASSERT_TRUE(v);
        EXPECT_NEAR(*v, terminal, 0.01 * terminal);
        continue;
      }
      ASSERT_EQ(run.status, RunStatus::Diverged) << run.reason;
      if (run.reason.find("MuJoCo reset its state") != 0) continue;
      ++resets;
      EXPECT_NE(run.reason.find("mjWARN_BADQACC"), std::string::npos) << run.reason;
      EXPECT_NE(run.reason.find("body 'mote'"), std::string::npos) << run.reason;
      const long back = first_return(*b, scene, dt);
      ASSERT_GT(back, 0);
      ASSERT_TRUE(run.diverged_at);
      EXPECT_EQ(*run.diverged_at, static_cast<double>(back - 1) * dt);
    }
  }
  // The committed report had three such rows per backend.
  if (test::engine("mujoco") != nullptr) {
    EXPECT_GT(resets, 0);
  }
}

// A 1e-9 kg ball pushed by 100 N accelerates at 1e11 m/s^2, past MuJoCo's 1e10 at its first
// step: every step resets it, and it only ever moves g dt. Diverged at t = 0, never ok.
TEST(MujocoWarnings, ABallPushedPastTheLimitDivergesAtTheStart) {
  const Scene scene = test::scene_from(R"(name = "pushed_mote"
dims = 2
duration = 1.0
sample = 0.1
dt = [0.01]
report_dt = 0.01
[[body]]
name = "mote"
radius = 0.01
mass = 1e-9
position = [0.0, 10.0, 0.0]
force = [100.0, 0.0, 0.0]
)");
  for (const char* name : kMujocos) {
    const Backend* b = test::engine(name);
    if (b == nullptr) continue;
    SCOPED_TRACE(name);
    const RunRecord run = run_accuracy(*b, scene, 0.01);
    ASSERT_EQ(run.status, RunStatus::Diverged) << run.reason;
    ASSERT_TRUE(run.diverged_at);
    EXPECT_EQ(*run.diverged_at, 0.0);
    EXPECT_EQ(run.reason.find("MuJoCo reset its state to the model's initial one (qpos0: a free "
                              "body at the origin, a hinged one where it started, all at rest) at "
                              "t = 0 s: mjWARN_BADQACC, an acceleration of body 'mote' NaN or "
                              "beyond 1e10"),
              0u)
        << run.reason;
    // The stability search's own trial: diverged on the reset, not stable.
    const StabilityTrial trial = try_step(*b, scene, 0.01);
    EXPECT_FALSE(trial.stable);
    EXPECT_EQ(trial.growth, "diverged");
    EXPECT_EQ(trial.reason, run.reason);
  }
}

// 120 balls resting on the ground at once: 120 contacts, past MuJoCo's list of 100. The 20
// it drops fall through the ground, and the row is capped with the cap named, not ok.
TEST(MujocoWarnings, AFullContactListIsACap) {
  std::string text = R"(name = "crowd"
dims = 2
duration = 0.5
sample = 0.05
dt = [0.01]
report_dt = 0.01
[ground]
restitution = 0.0
)";
  for (int i = 0; i < 120; ++i)
    text += "[[body]]\nname = \"b" + std::to_string(i) +
            "\"\nradius = 0.1\nmass = 1.0\nposition = [" + std::to_string(0.3 * i) +
            ", 0.1, 0.0]\n";
  const Scene scene = test::scene_from(text);
  for (const char* name : kMujocos) {
    const Backend* b = test::engine(name);
    if (b == nullptr) continue;
    SCOPED_TRACE(name);
    const RunRecord run = run_accuracy(*b, scene, 0.01);
    // Some ball sinks into the ground, the contacts past the hundredth dropped.
    double lowest = 1.0;
    for (const BodyState& ball : run.trajectory.states.back())
      lowest = std::min(lowest, ball.position.y());
    EXPECT_LT(lowest, 0.0);
    EXPECT_EQ(run.status, RunStatus::Capped) << run.reason;
    EXPECT_EQ(run.reason.find("MuJoCo held the contacts at its cap of 100 (nconmax) from t = 0 s: "
                              "mjWARN_CONTACTFULL"),
              0u)
        << run.reason;
  }
}

}  // namespace
}  // namespace bb
