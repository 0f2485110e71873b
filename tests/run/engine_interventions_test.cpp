// What the runner makes of an engine's interventions (seam/backend.hpp): a reset ends the run
// as diverged at the reset's time with the engine's words, a cap lets it run to the end as
// `capped`; neither is a stable trial, a capped row passes no gate and a claim does not judge
// it, and the page shows the status with the reason under the table.
#include "run/engine_interventions.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <memory>
#include <string>
#include <utility>
#include <vector>

#include "report/summary_tables.hpp"
#include "run/accuracy_run.hpp"
#include "run/claims.hpp"
#include "run/gates.hpp"
#include "run/run_cache.hpp"
#include "run/stability.hpp"
#include "run/wire.hpp"
#include "support/test_support.hpp"

namespace bb {
namespace {

using Kind = EngineIntervention::Kind;

/// A test-only backend whose bodies stay where they start and whose engine reports `kind`
/// in the step after `after` steps, as an adapter latches it.
class InterveningBackend : public Backend {
 public:
  InterveningBackend(Kind kind, long after, std::string name = "intervening")
      : kind_(kind), after_(after), name_(std::move(name)) {}
  std::string name() const override { return name_; }
  FeatureSet supports() const override {
    return {Feature::Gravity, Feature::Drag, Feature::ThreeD, Feature::Wind};
  }
  std::unique_ptr<Simulation> start_run(const World& world, const BackendSettings&,
                                        double) const override {
    struct Sim : Simulation {
      State state;
      Kind kind = Kind::Reset;
      long after = 0, steps = 0;
      std::vector<EngineIntervention> seen;
      void step() override {
        if (++steps > after && seen.empty())
          seen.push_back({kind, after, "the engine did it to body 'ball'", "its own warning"});
      }
      void read(State& out) const override { out = state; }
      std::vector<EngineIntervention> interventions() const override { return seen; }
    };
    auto sim = std::make_unique<Sim>();
    for (const Body& b : world.bodies) sim->state.push_back({b.position, {}, b.orientation, {}});
    sim->kind = kind_;
    sim->after = after_;
    return sim;
  }

 private:
  Kind kind_;
  long after_;
  std::string name_;
};

/// kMinimalCase, whose stability search begins at dt 0.05 s, run for 50 s: a stability trial's
/// kMinTrialSteps (1000) steps, so that the accuracy run at that step judges the trial too.
const Scene& scene() {
  static const Scene s = [] {
    std::string text = std::string(test::kMinimalCase) + "\n[stability]\ndt_min = 0.05\n";
    text.replace(text.find("duration = 1.0"), 14, "duration = 50.0");
    return test::scene_from(text);
  }();
  return s;
}

TEST(EngineInterventions, AResetEndsTheRunAsDivergedAtTheResetsTimeInTheEnginesWords) {
  const double dt = 0.05;
  const RunRecord run = run_accuracy(InterveningBackend(Kind::Reset, 7), scene(), dt, true);
  EXPECT_EQ(run.status, RunStatus::Diverged);
  ASSERT_TRUE(run.diverged_at);
  EXPECT_EQ(*run.diverged_at, 7.0 * dt);
  EXPECT_EQ(run.reason, "the engine did it to body 'ball' at t = 0.35 s: its own warning");
  // It ends at the sample whose steps hold the reset: the eighth step's, two steps a sample.
  EXPECT_EQ(run.trajectory.times.back(), 8.0 * dt);
  // The run at the search's first step judges its trial: the reset, not stable.
  ASSERT_EQ(dt, scene().stability.dt_min);
  ASSERT_TRUE(run.stability_trial);
  EXPECT_FALSE(run.stability_trial->stable);
  EXPECT_EQ(run.stability_trial->growth, "diverged");
  EXPECT_EQ(run.stability_trial->reason, run.reason);
}

TEST(EngineInterventions, ACapLetsTheRunGoToTheEndAndMakesItCappedWithTheCapNamed) {
  const double dt = 0.05;
  const RunRecord run = run_accuracy(InterveningBackend(Kind::Cap, 3), scene(), dt, true);
  EXPECT_EQ(run.status, RunStatus::Capped);
  EXPECT_FALSE(run.diverged_at);
  EXPECT_EQ(run.reason, "the engine did it to body 'ball' from t = 0.15 s: its own warning");
  EXPECT_EQ(static_cast<int>(run.trajectory.times.size()), scene().sample_count() + 1);
  ASSERT_TRUE(run.stability_trial);
  EXPECT_FALSE(run.stability_trial->stable);
  EXPECT_EQ(run.stability_trial->growth, "capped");
  // Kept and carried from a child like any run that finished.
  EXPECT_TRUE(RunCache::repeatable(run));
  EXPECT_EQ(wire::decode_run(wire::encode(run)).status, RunStatus::Capped);
  EXPECT_EQ(status_name(run.status), "capped");
}

TEST(EngineInterventions, TheSearchsOwnTrialsAreNotStableWhereTheEngineIntervened) {
  const StabilityTrial reset = try_step(InterveningBackend(Kind::Reset, 0), scene(), 0.1);
  EXPECT_FALSE(reset.stable);
  EXPECT_EQ(reset.growth, "diverged");
  EXPECT_EQ(reset.reason, "the engine did it to body 'ball' at t = 0 s: its own warning");
  const StabilityTrial capped = try_step(InterveningBackend(Kind::Cap, 4), scene(), 0.1);
  EXPECT_FALSE(capped.stable);
  EXPECT_EQ(capped.growth, "capped");
  EXPECT_NE(capped.reason.find("from t = 0.4 s"), std::string::npos) << capped.reason;
  // A backend held at its cap at every step tried is not "stable at every dt tried".
  const StabilityResult searched = find_stability(InterveningBackend(Kind::Cap, 0), scene());
  EXPECT_EQ(searched.status, "unstable at every dt tried");
  EXPECT_FALSE(searched.critical_dt);
  EXPECT_NE(searched.reason.find("the engine did it"), std::string::npos) << searched.reason;
  // Without an intervention the same bodies at rest are stable.
  EXPECT_TRUE(try_step(InterveningBackend(Kind::Cap, 1000), scene(), 0.1).stable);
}

TEST(EngineInterventions, ACappedRowPassesNoGateIsJudgedByNoClaimAndShowsItsReason) {
  static Scene case_scene;
  case_scene = test::scene_from(std::string(test::kMinimalCase) + R"(
[[observe]]
kind = "final_speed"
body = "ball"

[[gate]]
backend = "ode"
metric = "final_speed/ball"
max = 1e9

[[claim]]
text = "the ball ends slower than a bullet"
own = true
left = "ode:final_speed/ball"
op = "<"
right = 1000.0
)");
  CaseResults results;
  results.scene = &case_scene;
  results.reference_run.backend = "reference";
  results.reference_run.observables = {{"final_speed/ball", {0.0, ""}, 0.0}};
  for (double dt : case_scene.dt) {
    RunRecord run = run_accuracy(InterveningBackend(Kind::Cap, 1, "ode"), case_scene, dt);
    run.observables = {{"final_speed/ball", {0.0, ""}, 0.0}};
    results.runs.push_back(run);
  }
  // The value is there, and small enough, but a cap's number is not trusted.
  const std::vector<GateResult> gates = evaluate_gates(case_scene, results);
  ASSERT_EQ(gates.size(), 1u);
  EXPECT_FALSE(gates[0].passed);
  EXPECT_NE(gates[0].note.find("capped: the engine did it"), std::string::npos) << gates[0].note;
  const ClaimVerdict v = judge_claims(results)[0].verdicts[0];
  EXPECT_EQ(v.kind, VerdictKind::NotMeasured);
  EXPECT_EQ(v.verdict,
            "not measured (capped at dt 1/10, 1/20 s: the engine did it to body 'ball' from t = "
            "0.1 s: its own warning)");
  EXPECT_EQ(claim_standing(judge_claims(results)[0]), ClaimStanding::Neither);
  // The page: the status in its column, the reason under the table.
  const Table table = summary_table(results, case_scene.report_dt);
  const auto row = std::find_if(table.rows.begin(), table.rows.end(),
                                [](const auto& r) { return r[0] == "ode"; });
  ASSERT_NE(row, table.rows.end());
  EXPECT_EQ((*row)[1], "capped");
  const std::vector<std::string> notes = run_notes(results, case_scene.report_dt);
  EXPECT_NE(std::find(notes.begin(), notes.end(),
                      "ode: capped: the engine did it to body 'ball' from t = 0.05 s: "
                      "its own warning"),
            notes.end());
}

}  // namespace
}  // namespace bb
