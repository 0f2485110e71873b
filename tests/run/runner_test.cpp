// The runner: capability matching, the sample grid, divergence and backend failures.
#include <gtest/gtest.h>

#include <cmath>
#include <utility>
#include <vector>

#include "course/course_backend.hpp"
#include "metrics/errors.hpp"
#include "physics/energy.hpp"
#include "report/summary_tables.hpp"
#include "run/accuracy_run.hpp"
#include "run/case_runner.hpp"
#include "run/divergence.hpp"
#include "run/drawn_bodies.hpp"
#include "run/run_summary.hpp"
#include "scene/case_error.hpp"
#include "scene/motion.hpp"
#include "support/engine_support.hpp"
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
// so (DESIGN.md's fallback) each backend's errors are against its own finest-dt run, and
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

// A case written from DESIGN.md's format alone (a ball thrown into the corner of two
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
