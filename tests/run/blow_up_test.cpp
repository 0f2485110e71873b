// A run that blew up is never `ok`, and a stability trial that ran away is never `stable`:
// both are judged against what the scene itself can put into motion (energy_scale.hpp),
// not against a bound far above it. The rope of tests/cases/rope.toml is the example.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "physics/energy.hpp"
#include "run/case_runner.hpp"
#include "run/divergence.hpp"
#include "run/stability.hpp"
#include "support/engine_support.hpp"
#include "support/test_support.hpp"

namespace bb {
namespace {

Scene rope() {
  return load_case(test::source_path("tests/cases/rope.toml"));
}

/// The fastest any body of `run` moves at its samples (m/s).
double fastest(const RunRecord& run) {
  double v = 0.0;
  for (const State& s : run.trajectory.states)
    for (const BodyState& b : s) v = std::max(v, b.velocity.norm());
  return v;
}

/// The runs of `scene` at report_dt, the reference's first, with their whole trajectories.
std::vector<RunRecord> runs_at_report_dt(const Scene& scene) {
  RunOptions options;
  options.cost = false;
  options.dts = {scene.report_dt};
  options.isolation = false;
  CaseResults results = run_case(scene, test::registry(), options);
  std::vector<RunRecord> out = {results.reference_run};
  for (RunRecord& r : results.runs) out.push_back(std::move(r));
  return out;
}

// The rope can release at most what its nodes' fall gives (each hangs straight below the
// pin at most, its springs stretched): more than the rigid rope's 0.1 g (0.5 + 1 + ... + 3),
// and of that order, not a bound a hundred times larger.
TEST(BlowUp, TheRopesScaleIsWhatItsFallCanRelease) {
  const Scene scene = rope();
  const EnergyScale scale = divergence_bounds(scene).scale;
  const double rigid = 0.1 * 9.81 * (0.5 + 1.0 + 1.5 + 2.0 + 2.5 + 3.0);
  EXPECT_GT(scale.gravity, rigid);
  EXPECT_LT(scale.total(), 3.0 * rigid) << scale.describe();
}

// At 1/60 s semi-implicit Euler's step is past 2 / omega of the rope's stiffest mode: its
// nodes fly off at hundreds of metres per second. That row is diverged, with the reason;
// and no row is `ok` whose bodies move ten times faster than the reference's ever do.
TEST(BlowUp, ARopeThatBlowsUpAtAGameFrameIsNotOk) {
  const Scene scene = rope();
  const std::vector<RunRecord> runs = runs_at_report_dt(scene);
  ASSERT_EQ(runs.front().backend, "reference");
  ASSERT_EQ(runs.front().status, RunStatus::Ok) << runs.front().reason;
  const double reference_speed = fastest(runs.front());
  bool semi_implicit = false;
  for (const RunRecord& r : runs) {
    SCOPED_TRACE(r.backend);
    if (r.status == RunStatus::Ok) {
      EXPECT_LT(fastest(r), 10.0 * reference_speed);
    }
    if (r.backend == "course/semi-implicit-euler") {
      semi_implicit = true;
      EXPECT_EQ(r.status, RunStatus::Diverged);
      EXPECT_NE(r.reason.find("the scene"), std::string::npos) << r.reason;
    }
  }
  EXPECT_TRUE(semi_implicit);
}

/// The search's result for the course variant `name` on `scene`.
StabilityResult stability_of(const Scene& scene, const std::string& name) {
  for (const Backend* b : backends_for(scene, test::registry()).all)
    if (b->name() == name) return find_stability(*b, scene);
  throw std::runtime_error("no backend " + name);
}

// Velocity Verlet and RK4 on the rope: a step whose energy rises to hundreds of times what
// the rope holds and levels off there (the springs fold) is not stable; the largest stable
// step found stays at the theory's limit for the stiffest mode (within 6 %: the rope's geometry
// is not linear).
TEST(BlowUp, ARopeIsNotCalledStableFarPastItsTheory) {
  const Scene scene = rope();
  for (const char* name : {"course/velocity-verlet", "course/rk4"}) {
    SCOPED_TRACE(name);
    const StabilityResult r = stability_of(scene, name);
    ASSERT_TRUE(r.theory) << r.theory_formula;
    ASSERT_TRUE(r.critical_dt) << r.status << ": " << r.reason;
    EXPECT_LT(*r.critical_dt, 1.06 * *r.theory) << r.stable_note;
  }
}

/// Three damped springs hanging from a pin, each node 1 kg, released stretched.
Scene chain() {
  return test::scene_from(R"(name = "chain"
dims = 2
duration = 10.0
sample = 0.01
dt = [0.01, 0.005]
report_dt = 0.01
[[body]]
name = "pin"
shape = "point"
mass = 1.0
fixed = true
position = [0.0, 10.0, 0.0]
[[body]]
name = "a"
shape = "point"
mass = 1.0
position = [0.0, 8.8, 0.0]
[[body]]
name = "b"
shape = "point"
mass = 1.0
position = [0.0, 7.6, 0.0]
[[body]]
name = "c"
shape = "point"
mass = 1.0
position = [0.3, 6.4, 0.0]
[[spring]]
bodies = ["pin", "a"]
stiffness = 400.0
damping = 0.4
rest_length = 1.0
[[spring]]
bodies = ["a", "b"]
stiffness = 400.0
damping = 0.4
rest_length = 1.0
[[spring]]
bodies = ["b", "c"]
stiffness = 400.0
damping = 0.4
rest_length = 1.0
[course]
integrators = ["explicit-euler", "rk4"]
[stability]
dt_min = 0.0001
dt_max = 0.4
)");
}

// A damped chain: explicit Euler's and RK4's slow growth just past their limits stays small
// over the case's 10 s; the trials past the theory's limit run longer and show it, so the
// step found stays within 10 % of the theory's.
TEST(BlowUp, SlowGrowthPastTheTheoryIsSeenByALongerTrial) {
  const Scene scene = chain();
  for (const char* name : {"course/explicit-euler", "course/rk4"}) {
    SCOPED_TRACE(name);
    const StabilityResult r = stability_of(scene, name);
    ASSERT_TRUE(r.theory) << r.theory_formula;
    ASSERT_GT(*r.theory, 0.0) << r.theory_formula;
    ASSERT_TRUE(r.critical_dt) << r.status << ": " << r.reason;
    EXPECT_LT(*r.critical_dt, 1.1 * *r.theory) << r.stable_note;
    EXPECT_GT(*r.critical_dt, 0.5 * *r.theory) << r.reason;
  }
}

}  // namespace
}  // namespace bb
