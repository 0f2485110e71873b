// A backend that crashes, aborts through an engine's error handler, runs out of memory or
// hangs becomes a result; every other run of the case is complete and unchanged.
#include <gtest/gtest.h>
#include <sys/mman.h>
#include <unistd.h>

#include <csignal>
#include <cstdio>
#include <cstdlib>
#include <new>

#include "run/case_runner.hpp"
#include "run/child_pool.hpp"
#include "study/start_case.hpp"
#include "support/engine_support.hpp"
#include "support/test_support.hpp"

namespace bb {
namespace {

enum class Fault { Segfault, EngineAbort, OutOfMemory, Hang };

/// A test-only backend that fails in `fault` on its first step.
class FailingBackend : public Backend {
 public:
  FailingBackend(std::string name, Fault fault) : name_(std::move(name)), fault_(fault) {}
  std::string name() const override { return name_; }
  FeatureSet supports() const override {
    return {Feature::Gravity, Feature::Drag, Feature::ThreeD};
  }
  std::unique_ptr<Simulation> start_run(const World&, const BackendSettings&,
                                        double) const override {
    struct Sim : Simulation {
      Fault fault;
      void step() override {
        switch (fault) {
          case Fault::Segfault:
            std::raise(SIGSEGV);
            break;
          case Fault::EngineAbort:
            // What an engine's own error handler does: say why on stderr, then abort.
            std::fprintf(stderr,
                         "ODE INTERNAL ERROR 1: assertion \"bNormalizationResult\" failed\n");
            std::abort();
          case Fault::OutOfMemory: {
            volatile char* block = new char[std::size_t{64} << 30];
            block[0] = 1;
            break;
          }
          case Fault::Hang:
            for (;;) pause();
        }
      }
      void read(State&) const override {}
    };
    auto sim = std::make_unique<Sim>();
    sim->fault = fault_;
    return sim;
  }

 private:
  std::string name_;
  Fault fault_;
};

/// Whether the library runs under AddressSanitizer (the test's own code may be compiled
/// without it): its children then have no memory cap.
bool under_address_sanitizer() {
  return !children_memory_capped();
}

RunOptions quick_options() {
  RunOptions options;
  options.cost = false;
  options.timeout = 2.0;
  options.jobs = 2;
  return options;
}

TEST(Isolation, FailuresBecomeResultsAndTheOtherRunsAreUntouched) {
  const Scene scene = load_case(test::source_path("cases/drag_fall.toml"));
  RunOptions options = quick_options();
  options.dts = {scene.report_dt};
  const Registry clean = Registry::load();
  const CaseResults expected = run_case(scene, clean, options);

  Registry registry = Registry::load();
  registry.add_engine(std::make_unique<FailingBackend>("segfault", Fault::Segfault));
  registry.add_engine(std::make_unique<FailingBackend>("engine-abort", Fault::EngineAbort));
  registry.add_engine(std::make_unique<FailingBackend>("hang", Fault::Hang));
  if (!under_address_sanitizer())
    registry.add_engine(std::make_unique<FailingBackend>("out-of-memory", Fault::OutOfMemory));
  const CaseResults results = run_case(scene, registry, options);

  int checked = 0;
  std::vector<std::string> not_built;
  for (const RunRecord& run : results.runs) {
    if (test::described_but_not_built(run.backend)) {
      not_built.push_back(run.backend);
    } else if (run.backend == "segfault") {
      EXPECT_EQ(run.status, RunStatus::Crashed);
      // Under AddressSanitizer the sanitizer reports the SEGV itself and aborts.
      const bool named =
          run.reason.find("signal 11") != std::string::npos ||
          (under_address_sanitizer() && run.reason.find("SEGV") != std::string::npos);
      EXPECT_TRUE(named) << run.reason;
    } else if (run.backend == "engine-abort") {
      EXPECT_EQ(run.status, RunStatus::Crashed);
      EXPECT_NE(run.reason.find("signal 6"), std::string::npos) << run.reason;
      EXPECT_NE(run.reason.find("ODE INTERNAL ERROR 1"), std::string::npos) << run.reason;
    } else if (run.backend == "hang") {
      EXPECT_EQ(run.status, RunStatus::Timeout);
      EXPECT_NE(run.reason.find("time limit of 2"), std::string::npos) << run.reason;
    } else if (run.backend == "out-of-memory") {
      EXPECT_EQ(run.status, RunStatus::Crashed);
      EXPECT_NE(run.reason.find("out of memory"), std::string::npos) << run.reason;
    } else {
      // Every other run is exactly what it is without the failing backends.
      const auto same = std::find_if(
          expected.runs.begin(), expected.runs.end(),
          [&](const RunRecord& r) { return r.backend == run.backend && r.dt == run.dt; });
      ASSERT_NE(same, expected.runs.end()) << run.backend;
      EXPECT_EQ(run.status, same->status) << run.backend;
      ASSERT_TRUE(run.errors.has_value() == same->errors.has_value()) << run.backend;
      if (run.errors) {
        EXPECT_EQ(run.errors->position_max, same->errors->position_max) << run.backend;
      }
      EXPECT_EQ(run.trajectory.states.size(), static_cast<std::size_t>(scene.sample_count() + 1))
          << run.backend;
      ++checked;
    }
  }
  EXPECT_GE(checked, 4);
  BB_SKIP_IF_MISSING(test::not_built(not_built));
}

TEST(Isolation, OdesOwnErrorHandlerEndsInTheReason) {
  const Registry registry = Registry::load();
  const Backend* ode = nullptr;
  for (const Backend* b : registry.engines())
    if (b->name() == "ode") ode = b;
  BB_SKIP_IF_MISSING(test::not_built({"ode"}));
  const Scene scene = load_case(test::source_path("cases/drag_fall.toml"));
  ChildPool pool(1, true);
  ChildOutcome outcome;
  // A negative step is something only a caller bypassing the loader can ask for; ODE's own
  // check rejects it through its debug handler.
  pool.submit(
      "ode with a negative step",
      [&] {
        start_case(*ode, scene, -0.01)->step();
        return std::string();
      },
      10.0, [&](const ChildOutcome& o) { outcome = o; });
  pool.run();
  EXPECT_EQ(outcome.kind, ChildOutcome::Kind::Crashed);
  EXPECT_NE(outcome.reason.find("ODE error"), std::string::npos) << outcome.reason;
}

// The cap counts from what the child inherits: a parent that already holds 3 GiB of
// address space (the results of earlier runs, say) leaves each child its full 4 GiB.
TEST(Isolation, AChildsMemoryCapDoesNotCountWhatTheParentHolds) {
  if (!children_memory_capped()) GTEST_SKIP() << "no memory cap under AddressSanitizer";
  const std::size_t held = 3UL << 30;
  void* parent = mmap(nullptr, held, PROT_READ | PROT_WRITE,
                      MAP_PRIVATE | MAP_ANONYMOUS | MAP_NORESERVE, -1, 0);
  ASSERT_NE(parent, MAP_FAILED);
  ChildPool pool(1, true);
  ChildOutcome outcome;
  pool.submit(
      "two more GiB in the child",
      [] {
        void* more = mmap(nullptr, 2UL << 30, PROT_READ | PROT_WRITE,
                          MAP_PRIVATE | MAP_ANONYMOUS | MAP_NORESERVE, -1, 0);
        if (more == MAP_FAILED) throw std::bad_alloc();
        return std::string("mapped");
      },
      10.0, [&](const ChildOutcome& o) { outcome = o; });
  pool.run();
  munmap(parent, held);
  EXPECT_EQ(outcome.kind, ChildOutcome::Kind::Done) << outcome.reason;
  // Beyond the cap, the child still fails.
  pool.submit(
      "five GiB in the child",
      [] {
        void* more = mmap(nullptr, 5UL << 30, PROT_READ | PROT_WRITE,
                          MAP_PRIVATE | MAP_ANONYMOUS | MAP_NORESERVE, -1, 0);
        if (more == MAP_FAILED) throw std::bad_alloc();
        return std::string("mapped");
      },
      10.0, [&](const ChildOutcome& o) { outcome = o; });
  pool.run();
  EXPECT_NE(outcome.kind, ChildOutcome::Kind::Done);
}

TEST(Isolation, InProcessModeGivesTheSameResults) {
  const Scene scene = load_case(test::source_path("cases/magnus_throw.toml"));
  const Registry registry = Registry::load();
  RunOptions isolated = quick_options();
  RunOptions in_process = quick_options();
  in_process.isolation = false;
  const CaseResults a = run_case(scene, registry, isolated);
  const CaseResults b = run_case(scene, registry, in_process);
  ASSERT_EQ(a.runs.size(), b.runs.size());
  for (std::size_t i = 0; i < a.runs.size(); ++i) {
    EXPECT_EQ(a.runs[i].status, b.runs[i].status);
    if (a.runs[i].errors) {
      EXPECT_EQ(a.runs[i].errors->position_max, b.runs[i].errors->position_max);
    }
  }
}

}  // namespace
}  // namespace bb
