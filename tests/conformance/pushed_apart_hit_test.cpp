// A hit a backend resolves by pushing the bodies apart over its steps is "not measured", said
// with what was seen, never "no two moving bodies collided": on plank_free (a ball at 2 m/s
// onto a free plank, no gravity) at every dt of its sweep, each contact observable of every
// backend has a value or a note that begins "not measured:". Bullet at 1/120 s and below
// slows the ball's approach from 2 m/s to a few cm/s over its steps without ever stopping it:
// it has no step where a contact can be timed.
#include <gtest/gtest.h>

#include <string>

#include "observe/observables.hpp"
#include "run/case_loading.hpp"
#include "support/conformance_support.hpp"
#include "support/test_support.hpp"

namespace bb {
namespace {

class PushedApartHit : public ::testing::TestWithParam<std::string> {};

TEST_P(PushedApartHit, EveryContactObservableHasAValueOrSaysItWasNotMeasured) {
  const Scene scene = load_case(test::source_path("cases/plank_free.toml"));
  for (const double dt : scene.dt) {
    std::string skipped;
    const std::optional<RunRecord> run = test::run_backend(GetParam(), scene, dt, skipped);
    if (!run) GTEST_SKIP() << skipped;
    ASSERT_EQ(run->status, RunStatus::Ok) << run->reason;
    for (const Observe& o : scene.observes) {
      const ObservableValue v = measure(scene, o, run->trajectory, nullptr);
      if (v.value) continue;
      EXPECT_EQ(v.note.rfind("not measured: ", 0), 0u)
          << "dt " << dt << ", " << o.name << ": " << v.note;
    }
  }
}

INSTANTIATE_TEST_SUITE_P(EveryBackend, PushedApartHit, ::testing::ValuesIn(test::every_backend()),
                         test::param_test_name);

}  // namespace
}  // namespace bb
