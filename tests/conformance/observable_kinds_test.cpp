// Each observable kind on every backend there is, as one row of a table: a scene observing
// it, the value a closed form gives from that scene, and how near each backend must come.
// A new kind is tested here by a row, not by a copied file; a backend that cannot run a row's
// scene skips with the reason, one not built as not built.
#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <tuple>

#include "observe/observables.hpp"
#include "support/conformance_support.hpp"
#include "support/test_support.hpp"

namespace bb {
namespace {

using test::kG;

/// A ball in free flight for `duration` s from height 0 at `velocity` (a TOML vector), no
/// ground, no air, watched by `observe` (the lines of an [[observe]] after its body).
std::string thrown(const std::string& velocity, double duration, const std::string& observe) {
  return std::string(R"(name = "thrown"
dims = 2
duration = )") +
         std::to_string(duration) + R"(
sample = 0.1
dt = [0.01, 0.001]
report_dt = 0.01
[[body]]
name = "ball"
radius = 0.1
mass = 1.0
velocity = )" +
         velocity +
         R"(
[[observe]]
body = "ball"
)" + observe +
         test::kEveryIntegrator;
}

/// One kind's check: a scene whose first [[observe]] is the kind, the value it must have
/// (from a closed form of that scene), and the tolerance (absolute) a backend has at `dt`.
struct KindRow {
  const char* name;  ///< the test's name
  std::string scene;
  double dt;  ///< the stepped backends' step (the reference runs at its samples)
  double (*expected)();
  double (*tolerance)(const std::string& backend, double dt);
};

/// The float engines' rounding, relative, and a double's over a run.
double rounding(const std::string& backend) {
  return test::single_precision(backend) ? 1e-5 : 1e-9;
}

const KindRow kRows[] = {
    // 20 m/s up: the largest speed at the samples is the first's, on every method.
    {"max_speed_of_an_upward_throw", thrown("[0.0, 20.0, 0.0]", 1.0, R"(kind = "max_speed")"), 0.01,
     [] { return 20.0; }, [](const std::string& b, double) { return rounding(b) * 20.0; }},
    // 3 m/s across, falling: sqrt(9 + (g t)^2) is largest at the end, t = 1 s; every method
    // integrates a constant acceleration's velocity exactly.
    {"max_speed_at_the_end_of_a_fall", thrown("[3.0, 0.0, 0.0]", 1.0, R"(kind = "max_speed")"),
     0.01, [] { return std::sqrt(9.0 + kG * kG); },
     [](const std::string& b, double) { return rounding(b) * std::sqrt(9.0 + kG * kG); }},
    // 10 m/s up from the origin, above 1 m from crossing it going up to crossing it going
    // down: 2 sqrt(2 (h_apex - 1) / g), h_apex = v^2 / 2g. A first-order method's height is
    // off by about g t dt / 2 at t, so its crossings by about g t dt / (2 v) with v the
    // speed there (about 9 m/s): within 2 dt over the flight.
    {"time_above_a_level_of_an_upward_throw",
     thrown("[0.0, 10.0, 0.0]", 2.5, "kind = \"time_above\"\nlevel = 1.0\n"), 0.001,
     [] { return 2.0 * std::sqrt(2.0 * (100.0 / (2.0 * kG) - 1.0) / kG); },
     [](const std::string& b, double dt) { return b == "reference" ? 1e-9 : 2.0 * dt; }},
};

class ObservableKinds : public ::testing::TestWithParam<std::tuple<const KindRow*, std::string>> {};

TEST_P(ObservableKinds, MeetTheirClosedFormOnEveryBackend) {
  const auto& [row, backend] = GetParam();
  const Scene scene = test::scene_from(row->scene);
  std::string skipped;
  const std::optional<RunRecord> run = test::run_backend(backend, scene, row->dt, skipped);
  if (!run) GTEST_SKIP() << skipped;
  ASSERT_EQ(run->status, RunStatus::Ok) << run->reason;
  const ObservableValue v = measure(scene, scene.observes[0], run->trajectory, nullptr);
  ASSERT_TRUE(v.value) << v.note;
  EXPECT_NEAR(*v.value, row->expected(), row->tolerance(backend, row->dt));
}

std::vector<const KindRow*> rows() {
  std::vector<const KindRow*> out;
  for (const KindRow& row : kRows) out.push_back(&row);
  return out;
}

INSTANTIATE_TEST_SUITE_P(EveryBackend, ObservableKinds,
                         ::testing::Combine(::testing::ValuesIn(rows()),
                                            ::testing::ValuesIn(test::every_backend())),
                         [](const auto& info) {
                           return std::string(std::get<0>(info.param)->name) + "_" +
                                  test::test_name(std::get<1>(info.param));
                         });

}  // namespace
}  // namespace bb
