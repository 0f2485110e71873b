// docs/examples/student_case.toml, the case a student writes (issue 38, section 3): balls in
// the air with drag, a crate resting on a slope, a rope, a gate and a claim in a few lines.
// It loads, the reference follows the crate (not its fallback), and the crate holds or
// slides as tan(slope) against mu_s says.
#include <gtest/gtest.h>

#include <cmath>
#include <sstream>

#include "reference/sliding_modes.hpp"
#include "report/json_writer.hpp"
#include "run/sweep_runner.hpp"
#include "support/test_support.hpp"

namespace bb {
namespace {

const char* kStudentCase = "docs/examples/student_case.toml";

/// The example with its ground's two friction lines replaced by `mu_s` and `mu_k`.
std::string with_friction(const std::string& mu_s, const std::string& mu_k) {
  std::string text = test::bytes(test::source_path(kStudentCase));
  for (const auto& [key, value] :
       {std::pair<std::string, std::string>{"friction_static", mu_s}, {"friction_kinetic", mu_k}}) {
    // The value ends where the inline [ground] table goes on (a comma) or closes.
    const std::size_t at = text.find(key + " = ");
    text.replace(at, text.find_first_of(",}\n", at) - at, key + " = " + value + " ");
  }
  return text;
}

TEST(StudentCase, HoldsEveryPartInAFewLines) {
  std::istringstream lines(test::bytes(test::source_path(kStudentCase)));
  int written = 0;
  for (std::string line; std::getline(lines, line);) written += !line.empty() && line[0] != '#';
  EXPECT_LE(written, 30) << "a student's case, not the 180 lines of issue 38";
  const Scene s = load_case(test::source_path(kStudentCase));
  ASSERT_TRUE(s.ground && s.air && s.grid);
  EXPECT_EQ(s.grid->size[1], 1) << "a rope: a grid of one row";
  int balls_with_drag = 0;
  for (const Body& b : s.bodies) balls_with_drag += b.drag_coefficient > 0.0;
  EXPECT_GE(balls_with_drag, 2);
  EXPECT_FALSE(s.gates.empty());
  EXPECT_FALSE(s.claims.empty());
  EXPECT_EQ(box_slide_reason(s, s.body_index("crate")), "");
}

TEST(StudentCase, TheCrateHoldsOrSlidesAsTheSlopeAgainstStaticFrictionSays) {
  for (const auto& [mu_s, mu_k] : {std::pair<double, double>{0.7, 0.5}, {0.3, 0.2}}) {
    const Scene s = test::scene_from(with_friction(std::to_string(mu_s), std::to_string(mu_k)));
    const Vec3 n = s.ground->normal;
    const double slope = std::atan2(std::hypot(n.x(), n.z()), n.y());
    const double g = s.gravity.norm();
    // At rest if tan(slope) <= mu_s; else sliding from rest at g (sin - mu_k cos).
    const double expected =
        std::tan(slope) <= mu_s ? 0.0 : g * (std::sin(slope) - mu_k * std::cos(slope)) * s.duration;
    RunOptions options;
    options.cost = false;
    options.jobs = 2;
    options.backends = {"course/semi-implicit-euler"};
    options.dts = {s.report_dt};
    const auto runs = results_json(run_case(s, Registry::load(), options))["runs"];
    bool found = false;
    for (const auto& run : runs) {
      if (run["backend"] != "reference") continue;
      found = true;
      ASSERT_EQ(run["status"], "ok") << run["reason"];
      EXPECT_NEAR(run["observables"]["final_speed/crate"]["value"].get<double>(), expected, 1e-9)
          << "mu_s " << mu_s << ", tan(slope) " << std::tan(slope);
    }
    EXPECT_TRUE(found);
  }
}

}  // namespace
}  // namespace bb
