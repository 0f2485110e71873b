// The runner: capability matching, the sample grid, divergence and backend failures, and
// what each child measures and brings back. (Without a reference: runner_fallback_test.cpp;
// the divergence bounds of a correct fast run: runner_bounds_test.cpp.)
#include <gtest/gtest.h>

#include <utility>
#include <vector>

#include "course/course_backend.hpp"
#include "metrics/errors.hpp"
#include "physics/energy.hpp"
#include "run/accuracy_run.hpp"
#include "run/case_runner.hpp"
#include "run/drawn_bodies.hpp"
#include "run/run_summary.hpp"
#include "study/case_error.hpp"
#include "support/slow_backend.hpp"
#include "support/test_support.hpp"

namespace bb {
namespace {

/// A test-only backend: a body that flies off exponentially once the run passes `blow_up_at`,
/// or that throws from step() when `throw_at` is reached.
class FaultyBackend : public Backend {
 public:
  FaultyBackend(std::string name, double blow_up_at, double throw_at = 1e9)
      : name_(std::move(name)), blow_up_at_(blow_up_at), throw_at_(throw_at) {}
  std::string name() const override { return name_; }
  FeatureSet supports() const override {
    return {Feature::Gravity, Feature::Drag, Feature::ThreeD, Feature::Wind};
  }
  std::unique_ptr<Simulation> start_run(const World& scene, const BackendSettings&,
                                        double dt) const override {
    struct Sim : Simulation {
      State state;
      double dt, t = 0, blow_up_at, throw_at;
      long n = 0;
      void step() override {
        t = static_cast<double>(++n) * dt;
        if (t >= throw_at) throw std::runtime_error("engine gave up");
        if (t > blow_up_at)
          for (auto& b : state) b.position.y() = b.position.y() * 2.0 + 1.0;
      }
      void read(State& out) const override { out = state; }
    };
    auto sim = std::make_unique<Sim>();
    sim->state.resize(scene.bodies.size());
    for (std::size_t i = 0; i < scene.bodies.size(); ++i)
      sim->state[i].position = scene.bodies[i].position;
    sim->dt = dt;
    sim->blow_up_at = blow_up_at_;
    sim->throw_at = throw_at_;
    return sim;
  }

 private:
  std::string name_;
  double blow_up_at_, throw_at_;
};

TEST(Runner, SamplesOnTheGridWithTimeAsStepsTimesDt) {
  const Scene scene = load_case(test::source_path("cases/drag_fall.toml"));
  const CourseBackend backend({"course/rk4", "rk4", "mirror", "clamp"});
  const double dt = scene.dt.back();
  const RunRecord run = run_accuracy(backend, scene, dt);
  ASSERT_EQ(run.status, RunStatus::Ok);
  ASSERT_EQ(static_cast<int>(run.trajectory.times.size()), scene.sample_count() + 1);
  EXPECT_EQ(run.steps, static_cast<long>(scene.sample_count()) * scene.steps_per_sample(dt));
  for (std::size_t j = 0; j < run.trajectory.times.size(); ++j)
    EXPECT_EQ(run.trajectory.times[j], static_cast<double>(j * scene.steps_per_sample(dt)) * dt);
}

// A run times its blocks of steps between samples, for the report's floor: at least what its
// steps take.
TEST(Runner, TimesItsStepsBetweenSamples) {
  const Scene scene = test::scene_from(test::kMinimalCase);
  const RunRecord run = run_accuracy(test::SlowBackend(1e-4), scene, scene.report_dt);
  ASSERT_EQ(run.status, RunStatus::Ok) << run.reason;
  EXPECT_GT(run.steps, 0);
  EXPECT_GE(run.step_seconds, static_cast<double>(run.steps) * 1e-4);
}

TEST(Runner, DivergenceIsAResultWithItsTime) {
  const Scene scene = load_case(test::source_path("cases/drag_fall.toml"));
  const RunRecord run = run_accuracy(FaultyBackend("faulty", 2.0), scene, scene.report_dt);
  EXPECT_EQ(run.status, RunStatus::Diverged);
  ASSERT_TRUE(run.diverged_at.has_value());
  EXPECT_GT(*run.diverged_at, 2.0);
  // Found within a few samples of the blow-up, once the body passes the scene's bound.
  EXPECT_LT(*run.diverged_at, 2.0 + 5 * scene.sample);
  EXPECT_FALSE(run.reason.empty());
}

TEST(Runner, AnExceptionInsideABackendIsAnErrorResult) {
  const Scene scene = load_case(test::source_path("cases/drag_fall.toml"));
  const RunRecord run = run_accuracy(FaultyBackend("faulty", 1e9, 1.0), scene, scene.report_dt);
  EXPECT_EQ(run.status, RunStatus::Error);
  EXPECT_NE(run.reason.find("engine gave up"), std::string::npos);
}

TEST(Runner, MissingFeaturesAreNamed) {
  std::string text = test::kMinimalCase;
  text += "magnus = 0.01\nangular_velocity = [0.0, 0.0, 3.0]\n";
  const Scene scene = test::scene_from(text);
  const RunRecord run = run_accuracy(FaultyBackend("faulty", 1e9), scene, 0.05);
  EXPECT_EQ(run.status, RunStatus::Unsupported);
  EXPECT_EQ(run.reason, "does not support: magnus, rotation");
  EXPECT_EQ(run.steps, 0);
}

TEST(Runner, ADivergingBackendDoesNotStopTheOthers) {
  const Scene scene = load_case(test::source_path("cases/drag_fall.toml"));
  Registry registry = Registry::load();
  registry.add_engine(std::make_unique<FaultyBackend>("faulty", 1.0));
  RunOptions options;
  options.cost = false;
  options.dts = {scene.report_dt};
  const CaseResults results = run_case(scene, registry, options);
  int ok = 0, diverged = 0;
  for (const RunRecord& r : results.runs) {
    if (r.backend == "faulty") {
      EXPECT_EQ(r.status, RunStatus::Diverged);
      EXPECT_FALSE(r.errors.has_value());
      ++diverged;
    } else if (r.status == RunStatus::Ok) {
      EXPECT_TRUE(r.errors.has_value());
      ++ok;
    }
  }
  EXPECT_EQ(diverged, 1);
  EXPECT_GE(ok, 4);  // at least the four course integrators
}

TEST(Runner, OptionsNamingUnknownBackendsOrStepsAreBadInput) {
  const Scene scene = load_case(test::source_path("cases/drag_fall.toml"));
  const Registry registry = Registry::load();
  RunOptions options;
  options.cost = false;
  options.backends = {"physx"};
  EXPECT_THROW(run_case(scene, registry, options), CaseError);
  options.backends = {};
  options.dts = {0.0123};
  EXPECT_THROW(run_case(scene, registry, options), CaseError);
}

// A case written from docs/design.md's format alone (a ball thrown into the corner of two
// walls on a sloped floor, [[contact]] with friction_static and friction_kinetic) loads and
// runs with no change to the code: the reference and a course method both bounce it.
TEST(Runner, ACaseWrittenFromTheDesignAloneRuns) {
  const Scene scene = load_case(test::source_path("tests/cases/corner_throw.toml"));
  RunOptions options;
  options.backends = {"course/semi-implicit-euler"};
  options.dts = {scene.report_dt};
  options.cost = false;
  options.isolation = false;
  const CaseResults results = run_case(scene, Registry::load(), options);
  ASSERT_EQ(results.reference_run.status, RunStatus::Ok) << results.reference_run.reason;
  ASSERT_EQ(results.runs.front().status, RunStatus::Ok) << results.runs.front().reason;
  for (const RunRecord* run : {&results.reference_run, &results.runs.front()}) {
    const BodyEvents& ball = run->trajectory.events.bodies[0];
    EXPECT_GE(ball.contact_times.size(), 2u) << run->backend;
  }
  EXPECT_TRUE(results.runs.front().errors.has_value());
}

/// A second way of building the same physics that only differs where a scene has springs.
class SpringsByHandBackend : public FaultyBackend {
 public:
  SpringsByHandBackend() : FaultyBackend("faulty/force", 1e9) {}
  FeatureSet supports() const override {
    return {Feature::Gravity, Feature::ThreeD, Feature::Springs};
  }
  FeatureSet needs() const override { return {Feature::Springs}; }
};

TEST(Runner, AVariantThatNeedsSpringsTakesPartOnlyInSpringScenes) {
  Registry registry = Registry::load();
  registry.add_engine(std::make_unique<SpringsByHandBackend>());
  const auto names = [&](const Scene& scene) {
    std::vector<std::string> out;
    for (const Backend* b : backends_for(scene, registry).all) out.push_back(b->name());
    return out;
  };
  const Scene free_fall = test::scene_from(test::kMinimalCase);
  const Scene springs = load_case(test::source_path("cases/spring_pair.toml"));
  const auto without = names(free_fall), with = names(springs);
  EXPECT_EQ(std::count(without.begin(), without.end(), "faulty/force"), 0);
  EXPECT_EQ(std::count(with.begin(), with.end(), "faulty/force"), 1);
}

// Every child measures its own run against the reference it inherits at fork and brings
// back the summaries: the errors and observables are those of the whole run, while only the
// report_dt run keeps states, and only of the bodies the page plots.
TEST(Runner, EachChildMeasuresItsRunAndBringsBackOnlyWhatThePagePlots) {
  const Scene scene = load_case(test::source_path("cases/sproing_2d.toml"));
  ASSERT_GT(scene.bodies.size(), kPlottedBodies);
  RunOptions options;
  options.cost = false;
  options.backends = {"course/semi-implicit-euler"};
  options.dts = {scene.report_dt, scene.dt.back()};
  const CaseResults results = run_case(scene, Registry::load(), options);
  ASSERT_EQ(results.reference_run.status, RunStatus::Ok);
  ASSERT_EQ(results.reference_run.trajectory.states.front().size(), scene.bodies.size());
  ASSERT_EQ(results.runs.size(), 2u);
  const CourseBackend backend(
      {"course/semi-implicit-euler", "semi-implicit-euler", "mirror", "clamp"});
  const std::size_t samples = static_cast<std::size_t>(scene.sample_count()) + 1;
  for (const RunRecord& run : results.runs) {
    ASSERT_EQ(run.status, RunStatus::Ok) << run.reason;
    EXPECT_TRUE(run.summarised);
    // The same run whole, in this process, measured here.
    const RunRecord whole = run_accuracy(backend, scene, *run.dt);
    const ErrorMetrics here = compare(scene, whole.trajectory, results.reference_run.trajectory);
    ASSERT_TRUE(run.errors.has_value());
    EXPECT_EQ(run.errors->position_max, here.position_max);
    EXPECT_EQ(run.errors->energy_max, here.energy_max);
    ASSERT_EQ(run.observables.size(), scene.observes.size());
    for (std::size_t k = 0; k < scene.observes.size(); ++k)
      EXPECT_EQ(run.observables[k].measured.value,
                measure(scene, scene.observes[k], whole.trajectory, nullptr).value)
          << run.observables[k].name;
    ASSERT_EQ(run.energy.size(), samples);
    ASSERT_EQ(run.distance.size(), samples);
    EXPECT_EQ(run.energy.back(), total_energy(scene, whole.trajectory.states.back()));
    EXPECT_EQ(run.trajectory.times.size(), samples);
    if (*run.dt == scene.report_dt) {
      ASSERT_EQ(run.trajectory.states.size(), samples);
      EXPECT_EQ(run.trajectory.states.back().size(), drawn_bodies(scene).size());
      EXPECT_EQ(run.trajectory.states.back()[0].position,
                whole.trajectory.states.back()[0].position);
    } else {
      EXPECT_TRUE(run.trajectory.states.empty());
    }
  }
}

}  // namespace
}  // namespace bb
