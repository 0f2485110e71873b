// post_angular_velocity is signed, on every backend: two planks struck at opposite ends by
// the same blow spin opposite ways, omega = ((p - c) x J).z / I_zz about the case's z axis in
// 2D unless the [[observe]] gives -z, and about the [[observe]]'s axis in 3D. A backend
// spinning the wrong way is then 2 |omega| from the reference, not 0.
#include <gtest/gtest.h>

#include <cstdio>
#include <string>
#include <vector>

#include "observe/observables.hpp"
#include "support/conformance_support.hpp"
#include "support/test_support.hpp"

namespace bb {
namespace {

/// Two planks 5 m by 0.2 m of 1 kg, 10 m apart, without gravity, each struck at t = 0 by
/// -1 N s along y: "right_end" at its +x end, "left_end" at its -x end. `observes` are the
/// [[observe]] tables.
Scene struck_planks(int dims, const std::string& observes) {
  return test::scene_from("name = \"planks\"\ndims = " + std::to_string(dims) + R"(
duration = 0.5
sample = 0.0166666666666666667
dt = [0.0166666666666666667]
gravity = [0.0, 0.0, 0.0]
[[body]]
name = "right_end"
shape = "box"
half_extents = [2.5, 0.1, 0.1]
mass = 1.0
[[body]]
name = "left_end"
shape = "box"
half_extents = [2.5, 0.1, 0.1]
mass = 1.0
position = [0.0, 10.0, 0.0]
[[impulse]]
body = "right_end"
time = 0.0
impulse = [0.0, -1.0, 0.0]
point = [2.5, 0.0, 0.0]
[[impulse]]
body = "left_end"
time = 0.0
impulse = [0.0, -1.0, 0.0]
point = [-2.5, 10.0, 0.0]
)" + observes + test::kEveryIntegrator);
}

const char* kBoth = R"([[observe]]
kind = "post_angular_velocity"
body = "right_end"
[[observe]]
kind = "post_angular_velocity"
body = "left_end"
)";

class SignedSpin : public ::testing::TestWithParam<std::string> {
 protected:
  /// The spins observed on `scene`, in the order of its [[observe]], to `tolerance` (relative)
  /// of `expected`.
  void expect_spins(const Scene& scene, const std::vector<double>& expected) {
    std::string skipped;
    const std::optional<RunRecord> run =
        test::run_backend(GetParam(), scene, scene.dt.back(), skipped);
    if (!run) GTEST_SKIP() << skipped;
    ASSERT_EQ(run->status, RunStatus::Ok) << run->reason;
    const double tolerance = test::single_precision(GetParam()) ? 1e-6 : 1e-12;
    for (std::size_t k = 0; k < expected.size(); ++k) {
      const ObservableValue v = measure(scene, scene.observes[k], run->trajectory, nullptr);
      ASSERT_TRUE(v.value) << scene.observes[k].name << ": " << v.note;
      std::printf("%-28s %dD %-36s %+.9f rad/s\n", GetParam().c_str(), scene.dims,
                  scene.observes[k].name.c_str(), *v.value);
      EXPECT_NEAR(*v.value, expected[k], tolerance * std::abs(expected[k]))
          << scene.observes[k].name;
    }
  }
};

// omega = -/+ 2.5 m x 1 N s / (m (l^2 + w^2) / 12) = -/+ 1.19808 rad/s.
const double kSpin = 2.5 / ((25.0 + 0.04) / 12.0);

TEST_P(SignedSpin, PlanksStruckAtOppositeEndsSpinOppositeWaysAboutZ) {
  expect_spins(struck_planks(2, kBoth), {-kSpin, kSpin});
}

// Read about -z, a counterclockwise spin is negative: both planks' spins, read about opposite
// axes, have one sign.
TEST_P(SignedSpin, ReadAboutMinusZTheSpinHasTheOtherSign) {
  expect_spins(struck_planks(2, R"([[observe]]
kind = "post_angular_velocity"
body = "right_end"
[[observe]]
kind = "post_angular_velocity"
body = "left_end"
axis = [0.0, 0.0, -1.0]
)"),
               {-kSpin, -kSpin});
}

TEST_P(SignedSpin, In3DTheSpinIsSignedAboutTheStatedAxis) {
  expect_spins(struck_planks(3, R"([[observe]]
kind = "post_angular_velocity"
body = "right_end"
axis = [0.0, 0.0, 1.0]
[[observe]]
kind = "post_angular_velocity"
body = "left_end"
axis = [0.0, 0.0, 2.0]
)"),
               {-kSpin, kSpin});
}

INSTANTIATE_TEST_SUITE_P(EveryBackend, SignedSpin, ::testing::ValuesIn(test::every_backend()),
                         test::param_test_name);

}  // namespace
}  // namespace bb
