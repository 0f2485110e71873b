// The runner without a reference: each backend's errors are against its own finest run
// (or the next finest where that one fails), that run has no reference value of its own,
// and the notes say why the reference has no answer before anything else.
#include <gtest/gtest.h>

#include "course/course_backend.hpp"
#include "metrics/errors.hpp"
#include "report/summary_tables.hpp"
#include "run/accuracy_run.hpp"
#include "run/case_runner.hpp"
#include "run/run_summary.hpp"
#include "support/test_support.hpp"

namespace bb {
namespace {

// Without a reference, each backend is measured against its own finest run: that run has no
// difference from a reference in its observables (it was "(0)", itself against itself),
// while its coarser runs have one.
TEST(Runner, TheFallbacksFinestRunHasNoReferenceValueOfItsOwn) {
  const Scene scene = test::scene_from(std::string(test::kStackedBalls) +
                                       "[[observe]]\nkind = \"final_speed\"\nbody = \"high\"\n");
  RunOptions options;
  options.cost = false;
  options.backends = {"course/semi-implicit-euler"};
  const CaseResults results = run_case(scene, Registry::load(), options);
  ASSERT_EQ(results.runs.size(), 3u);
  for (const RunRecord& run : results.runs) {
    ASSERT_EQ(run.status, RunStatus::Ok) << run.reason;
    ASSERT_EQ(run.observables.size(), 1u);
    EXPECT_TRUE(run.observables[0].measured.value);
    const bool finest = *run.dt == scene.dt.back();
    EXPECT_EQ(run.observables[0].reference.has_value(), !finest) << *run.dt;
  }
}

// When the reference has no answer, the notes under the table (terminal and page) say why
// first, in words, and that no error can be measured without it.
TEST(Runner, AMissingReferenceIsExplainedFirstInTheNotes) {
  const Scene scene = test::scene_from(R"(name = "tumbling_crate"
dims = 2
duration = 1.0
sample = 0.1
dt = [0.01]
[ground]
restitution = 0.5
[[body]]
name = "crate"
shape = "box"
half_extents = [0.5, 0.25, 0.25]
mass = 1.0
position = [0.0, 2.0, 0.0]
)");
  RunOptions options;
  options.backends = {"course/semi-implicit-euler"};
  options.cost = false;
  options.isolation = false;
  const CaseResults results = run_case(scene, Registry::load(), options);
  ASSERT_NE(results.reference_run.status, RunStatus::Ok);
  const std::vector<std::string> notes = run_notes(results, scene.report_dt);
  ASSERT_FALSE(notes.empty());
  EXPECT_EQ(notes.front().rfind("reference: unsupported: ", 0), 0u) << notes.front();
  EXPECT_NE(notes.front().find("moving box"), std::string::npos) << notes.front();
  EXPECT_NE(notes.front().find("no error column"), std::string::npos) << notes.front();
}

// Two balls stacked on the ground touch at the start: the reference has no exact answer,
// so (the fallback of docs/design.md) each backend's errors are against its own finest-dt run, and
// reference.method, the notes and run_gates say so.
TEST(Runner, WithoutAReferenceErrorsAreAgainstTheFinestDt) {
  const Scene scene = test::scene_from(std::string(test::kStackedBalls) + R"([[gate]]
backend = "course/semi-implicit-euler"
metric = "position_max"
max = 10.0
)");
  RunOptions options;
  options.backends = {"course/semi-implicit-euler"};
  options.cost = false;
  options.isolation = false;
  const CaseResults results = run_case(scene, Registry::load(), options);
  ASSERT_EQ(results.reference_run.status, RunStatus::Unsupported);
  EXPECT_NE(results.reference.method.find("finest dt"), std::string::npos);
  ASSERT_EQ(results.runs.size(), 3u);
  // The two coarser runs are compared with the finest, which is its own reference.
  const RunRecord& finest = results.runs[2];
  EXPECT_FALSE(finest.errors.has_value());
  // It measured itself in its child too, after writing itself whole once for the others.
  EXPECT_TRUE(finest.summarised);
  EXPECT_TRUE(finest.trajectory.states.empty());
  for (int i = 0; i < 2; ++i) {
    const RunRecord& run = results.runs[i];
    ASSERT_TRUE(run.errors.has_value()) << *run.dt;
    // Measured in its child against the finest run, read from the file that run wrote.
    EXPECT_TRUE(run.summarised);
    EXPECT_EQ(run.trajectory.states.empty(), *run.dt != scene.report_dt);
    // Measured again here from the whole runs (the results keep only what the page plots).
    const RunRecord whole = run_accuracy(
        CourseBackend({"course/semi-implicit-euler", "semi-implicit-euler", "mirror", "clamp"}),
        scene, *run.dt);
    const RunRecord whole_finest = run_accuracy(
        CourseBackend({"course/semi-implicit-euler", "semi-implicit-euler", "mirror", "clamp"}),
        scene, *finest.dt);
    EXPECT_DOUBLE_EQ(run.errors->position_max,
                     compare(scene, whole.trajectory, whole_finest.trajectory).position_max);
    EXPECT_GT(run.errors->position_max, 0.0);
  }
  EXPECT_NE(run_notes(results, scene.report_dt).front().find("finest dt"), std::string::npos);
  // check runs report_dt and, for the fallback, the finest dt too, so the gate has a value.
  const CaseResults gated = run_gates(scene, Registry::load(), options);
  ASSERT_EQ(gated.gates.size(), 1u);
  EXPECT_TRUE(gated.gates[0].value.has_value());
  EXPECT_TRUE(gated.gates[0].passed);
}

/// The course's semi-implicit Euler, except that it refuses steps of `finest` and below.
class FinestFailsBackend : public Backend {
 public:
  explicit FinestFailsBackend(double finest) : finest_(finest) {}
  std::string name() const override { return "fails-finest"; }
  FeatureSet supports() const override { return inner_.supports(); }
  std::unique_ptr<Simulation> start_run(const World& world, const BackendSettings& settings,
                                        double dt) const override {
    if (dt <= finest_) throw std::runtime_error("no step this small");
    return inner_.start_run(world, settings, dt);
  }

 private:
  double finest_;
  CourseBackend inner_{{"fails-finest", "semi-implicit-euler", "mirror", "clamp"}};
};

// In the fallback, in child processes: each backend's finest run writes itself to a file
// that its other runs read in their children; where the finest run fails, the others come
// back whole and the next finest stands in, measured in the parent.
TEST(Runner, WithoutAReferenceTheNextFinestStandsInWhenTheFinestFails) {
  const Scene scene = test::scene_from(test::kStackedBalls);
  Registry registry = Registry::load();
  registry.add_engine(std::make_unique<FinestFailsBackend>(scene.dt.back()));
  RunOptions options;
  options.cost = false;
  const CaseResults results = run_case(scene, registry, options);
  ASSERT_NE(results.reference_run.status, RunStatus::Ok);
  const auto run_of = [&](const std::string& backend, double dt) {
    for (const RunRecord& run : results.runs)
      if (run.backend == backend && run.dt == dt) return &run;
    return static_cast<const RunRecord*>(nullptr);
  };
  const double coarse = scene.dt[0], middle = scene.dt[1], finest = scene.dt[2];
  ASSERT_EQ(run_of("fails-finest", finest)->status, RunStatus::Error);
  const RunRecord& stand_in = *run_of("fails-finest", middle);
  const RunRecord& measured = *run_of("fails-finest", coarse);
  ASSERT_EQ(stand_in.status, RunStatus::Ok);
  ASSERT_EQ(measured.status, RunStatus::Ok);
  EXPECT_FALSE(stand_in.summarised);
  EXPECT_FALSE(stand_in.errors.has_value());
  ASSERT_TRUE(measured.errors.has_value());
  // The same as course/semi-implicit-euler at these steps, measured against its middle run.
  const CourseBackend same({"x", "semi-implicit-euler", "mirror", "clamp"});
  EXPECT_DOUBLE_EQ(measured.errors->position_max,
                   compare(scene, run_accuracy(same, scene, coarse).trajectory,
                           run_accuracy(same, scene, middle).trajectory)
                       .position_max);
  // The course's own runs went through the file, and agree with the same measure here.
  const RunRecord& course = *run_of("course/semi-implicit-euler", coarse);
  EXPECT_TRUE(course.summarised);
  ASSERT_TRUE(course.errors.has_value());
  EXPECT_DOUBLE_EQ(course.errors->position_max,
                   compare(scene, run_accuracy(same, scene, coarse).trajectory,
                           run_accuracy(same, scene, finest).trajectory)
                       .position_max);
  // Kept: the report_dt run's states only.
  EXPECT_TRUE(stand_in.trajectory.states.empty());
  EXPECT_FALSE(measured.trajectory.states.empty());
}

}  // namespace
}  // namespace bb
