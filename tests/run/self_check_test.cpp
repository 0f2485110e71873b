// The reference's self-check: a second solve by another GSL method with other step control,
// 100 times tighter, compared with the reference in every state component.
#include <gtest/gtest.h>

#include "reference/gsl_reference.hpp"
#include "run/accuracy_run.hpp"
#include "run/case_runner.hpp"
#include "support/test_support.hpp"

namespace bb {
namespace {

std::string method_of(const RunRecord& run) {
  for (const auto& [key, value] : run.engine_settings)
    if (key == "method") return std::get<std::string>(value);
  return "";
}

CaseResults reference_only(const std::string& case_file) {
  const Scene scene = load_case(test::source_path(case_file));
  RunOptions options;
  options.backends = {"reference"};
  options.cost = false;
  options.sweep = false;
  return run_case(scene, Registry::load(), options);
}

// A box spinning in place: its position never changes, so a check of positions alone says
// 0; the orientation and the spin do differ between two solves, and by little.
TEST(SelfCheck, ComparesOrientationsAndSpinsNotOnlyPositions) {
  const CaseResults r = reference_only("cases/spinning_box.toml");
  ASSERT_TRUE(r.reference.self_check.has_value()) << r.reference.self_check_note;
  const StateDifference& d = *r.reference.self_check;
  EXPECT_EQ(d.position, 0.0);
  EXPECT_EQ(d.velocity, 0.0);
  EXPECT_GT(d.orientation, 0.0);
  EXPECT_GT(d.spin, 0.0);
  // Within ten times the tolerance through the flips (the world-frame equations were 2.9e-6
  // rad/s off here).
  EXPECT_LT(d.orientation, 1e-9);
  EXPECT_LT(d.spin, 1e-9);
}

// A bouncing, dragged ball: velocities are compared as well as positions.
TEST(SelfCheck, ComparesVelocities) {
  const CaseResults r = reference_only("cases/drag_fall.toml");
  ASSERT_TRUE(r.reference.self_check.has_value()) << r.reference.self_check_note;
  EXPECT_GT(r.reference.self_check->velocity, 0.0);
  EXPECT_LT(r.reference.self_check->velocity, 1e-8);
}

// The check shares no stepper and no step control with the reference: Cash-Karp's rkck
// where the reference uses rk8pd, error control on h y' as well as y, and bsimp where the
// reference turns to msbdf on a stiff scene; the results name it.
TEST(SelfCheck, SolvesWithAnotherMethodAndStepControl) {
  for (const char* name : {"cases/drag_fall.toml", "cases/tiny_mass_fall.toml"}) {
    const Scene scene = load_case(test::source_path(name));
    const RunRecord main = run_accuracy(ReferenceBackend(), scene, scene.sample);
    const RunRecord check = run_accuracy(ReferenceBackend().self_check(), scene, scene.sample);
    ASSERT_EQ(check.status, RunStatus::Ok) << check.reason;
    const std::string a = method_of(main), b = method_of(check);
    EXPECT_NE(a.find("rk8pd"), std::string::npos) << a;
    EXPECT_EQ(b.find("rk8pd"), std::string::npos) << b;
    EXPECT_EQ(b.find("msbdf"), std::string::npos) << b;
    EXPECT_NE(b.find("rkck"), std::string::npos) << b;
    if (std::string(name) == "cases/tiny_mass_fall.toml") {
      EXPECT_NE(a.find("msbdf"), std::string::npos) << a;
      EXPECT_NE(b.find("bsimp"), std::string::npos) << b;
    }
  }
  const CaseResults r = reference_only("cases/drag_fall.toml");
  EXPECT_NE(r.reference.self_check_method.find("rkck"), std::string::npos)
      << r.reference.self_check_method;
}

// A check of gates solves the reference once: gates and baselines use none of the
// self-check's floors, so every gate comes out as with it, and no second solve is run.
TEST(SelfCheck, AGatesCheckSolvesTheReferenceOnce) {
  const Scene scene = load_case(test::source_path("cases/drag_fall.toml"));
  ASSERT_FALSE(scene.gates.empty());
  const Registry registry = Registry::load();
  RunOptions options;
  options.jobs = 2;
  const CaseResults checked = run_gates(scene, registry, options, {});
  EXPECT_FALSE(checked.reference.self_check.has_value());
  EXPECT_NE(checked.reference.self_check_note.find("not solved"), std::string::npos)
      << checked.reference.self_check_note;
  EXPECT_EQ(checked.time_spent.self_check_steps, 0.0);
  // The same gates, run with the self-check, give the same values.
  RunOptions with_check = options;
  with_check.cost = false;
  with_check.sweep = false;
  with_check.dts = {scene.report_dt};
  for (const Gate& g : scene.gates) with_check.backends.push_back(g.backend);
  const CaseResults full = run_case(scene, registry, with_check);
  ASSERT_TRUE(full.reference.self_check.has_value()) << full.reference.self_check_note;
  ASSERT_EQ(checked.gates.size(), full.gates.size());
  for (std::size_t i = 0; i < full.gates.size(); ++i) {
    EXPECT_EQ(checked.gates[i].passed, full.gates[i].passed) << full.gates[i].gate.backend;
    EXPECT_EQ(checked.gates[i].value, full.gates[i].value) << full.gates[i].gate.backend;
  }
  // And one run fewer to count.
  RunOptions checking = options;
  checking.reference_self_check = false;
  EXPECT_EQ(progress_units(scene, registry, checking) + 1,
            progress_units(scene, registry, options));
}

}  // namespace
}  // namespace bb
