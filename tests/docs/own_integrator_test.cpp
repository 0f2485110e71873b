// docs/examples/own_integrator/ as a user builds it: configured and built out of tree against
// this build tree's package (find_package(beachball)), loaded with --plugin, run on two bundled
// cases; one of its numbers checked independently (the first apex of a dropped ball, from the
// test's own symplectic Euler steps and the bounce_apex definition, and its error from the
// closed form r + e^2 h); a gate on it checked; and `check --baseline` passing on the same
// plugin and failing on the one built -DWORSE (the position from the old velocity).
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>

#include "support/program.hpp"
#include "support/test_support.hpp"

namespace bb {
namespace {

namespace fs = std::filesystem;

using test::beachball;
using test::Outcome;

const std::string kBackend = "student/symplectic-euler";

/// The example built into `dir` with `flags` added: the plugin's path, or "" (said).
std::string build_example(const std::string& dir, const std::string& flags) {
  const std::string source = std::string(BEACHBALL_SOURCE_DIR) + "/docs/examples/own_integrator";
  // The compiler and flags of this build: under a sanitizer the plugin is built with it too.
  const Outcome configure = test::shell(
      "cmake -S " + source + " -B " + dir + " -DCMAKE_PREFIX_PATH=" + BEACHBALL_BUILD_DIR +
      " -DCMAKE_CXX_COMPILER=" + BEACHBALL_CXX_COMPILER +
      " '-DCMAKE_CXX_FLAGS=" + BEACHBALL_CXX_FLAGS + " " + flags +
      "' '-DCMAKE_MODULE_LINKER_FLAGS=" + BEACHBALL_MODULE_LINKER_FLAGS + "'");
  EXPECT_EQ(configure.exit_code, 0) << configure.out;
  const Outcome build = test::shell("cmake --build " + dir);
  EXPECT_EQ(build.exit_code, 0) << build.out;
  return dir + "/beachball-student.so";
}

/// A ball of radius 0.5 m dropped from 1 m above the floor (centre at 1.5 m), e = 0.5, and a
/// gate on the example's first apex.
std::string drop_case(double gate) {
  return "name = \"drop\"\ndims = 2\nduration = 1.6\nsample = 0.04\ndt = [0.02, 0.01]\n"
         "report_dt = 0.01\n\n[ground]\nrestitution = 0.5\n\n[[body]]\nname = \"ball\"\n"
         "radius = 0.5\nmass = 1.0\nposition = [0.0, 1.5, 0.0]\n\n[[observe]]\n"
         "kind = \"bounce_apex\"\nbody = \"ball\"\nn = 1\n\n[[gate]]\nbackend = \"" +
         kBackend + "\"\nmetric = \"bounce_apex/ball/1\"\nmax = " + std::to_string(gate) + "\n";
}

/// The first apex after the first bounce of that drop, by the example's rule (symplectic
/// Euler, a ball below the floor put back on it, its velocity reversed times e) and the
/// bounce_apex definition: the peak of the cubic through the two steps where it stops rising.
double own_apex(double dt) {
  const double g = 9.81, r = 0.5, e = 0.5;
  double y = 1.5, v = 0.0;
  bool bounced = false;
  for (int step = 0; step < 100000; ++step) {
    const double y0 = y, v0 = v;
    v -= g * dt;
    y += v * dt;
    if (y < r && v < 0.0) {
      y = r;
      v = -e * v;
      bounced = true;
      continue;
    }
    if (!bounced || !(v0 > 0.0 && v <= 0.0)) continue;
    // The Hermite cubic in u = (t - t0) / dt through (y0, v0) and (y, v): its slope
    // A u^2 + B u + C goes from positive at u = 0 to not at u = 1, through one root.
    const double A = 6.0 * (y0 - y) + 3.0 * dt * (v0 + v);
    const double B = 6.0 * (y - y0) - dt * (4.0 * v0 + 2.0 * v), C = dt * v0;
    double u = -C / B;
    if (std::abs(A) > 1e-15) {
      const double root = std::sqrt(B * B - 4.0 * A * C);
      u = (-B + root) / (2.0 * A);
      if (u < 0.0 || u > 1.0) u = (-B - root) / (2.0 * A);
    }
    const double h00 = 2 * u * u * u - 3 * u * u + 1, h10 = u * u * u - 2 * u * u + u;
    const double h01 = -2 * u * u * u + 3 * u * u, h11 = u * u * u - u * u;
    return h00 * y0 + h10 * dt * v0 + h01 * y + h11 * dt * v;
  }
  return NAN;
}

TEST(OwnIntegratorExample, BuildsOutOfTreeRunsChecksAndGates) {
  const std::string dir = test::fresh_dir("own_integrator");
  const std::string plugin = build_example(dir + "/build", "");
  ASSERT_TRUE(fs::exists(plugin));

  // Two bundled cases, its rows beside the built-in ones.
  const std::string cases = std::string(BEACHBALL_SOURCE_DIR) + "/cases/";
  const Outcome bundled = beachball("run " + cases + "pal_restitution.toml " + cases +
                                    "drag_fall.toml --plugin " + plugin + " --backends " +
                                    kBackend + " --no-cost --cache off --out " + dir + "/bundled");
  ASSERT_EQ(bundled.exit_code, 0) << bundled.out;
  int rows = 0;
  for (const auto& file : fs::directory_iterator(dir + "/bundled"))
    if (file.path().extension() == ".json") {
      const auto results = nlohmann::json::parse(std::ifstream(file.path()));
      for (const auto& run : results["runs"])
        if (run["backend"] == kBackend) {
          EXPECT_EQ(run["status"], "ok") << file.path() << run.dump();
          ++rows;
        }
    }
  EXPECT_GE(rows, 2 * 6) << bundled.out;  // each case's six dts at least

  // Its first apex at report_dt, computed here: the same value, and its error from r + e^2 h.
  const double apex = own_apex(0.01), exact = 0.5 + 0.5 * 0.5 * 1.0;
  const double error = std::abs(apex - exact);
  ASSERT_TRUE(std::isfinite(apex));
  const std::string c = test::write_case(dir, "drop.toml", drop_case(2.0 * error));
  const Outcome run = beachball("run " + c + " --plugin " + plugin +
                                " --no-cost --cache off --out " + dir + "/kept");
  ASSERT_EQ(run.exit_code, 0) << run.out;
  bool seen = false;
  const auto results = nlohmann::json::parse(std::ifstream(dir + "/kept/drop.json"));
  for (const auto& r : results["runs"])
    if (r["backend"] == kBackend && std::abs(r["dt"].get<double>() - 0.01) < 1e-12) {
      const auto& o = r["observables"]["bounce_apex/ball/1"];
      EXPECT_NEAR(o["value"].get<double>(), apex, 1e-9) << o.dump();
      EXPECT_NEAR(o["reference"].get<double>(), exact, 1e-6) << o.dump();
      EXPECT_NEAR(std::abs(o["error"].get<double>()), error, 1e-6) << o.dump();
      seen = true;
    }
  EXPECT_TRUE(seen) << run.out;

  // Its gate (twice its error) passes, and so does the baseline of the same plugin.
  const Outcome same =
      beachball("check " + c + " --plugin " + plugin + " --baseline " + dir + "/kept --cache off");
  EXPECT_EQ(same.exit_code, 0) << same.out;
  EXPECT_NE(same.out.find(kBackend), std::string::npos) << same.out;

  // Made worse on purpose: the baseline fails, naming the plugin's backend.
  const std::string worse = build_example(dir + "/worse", "-DWORSE");
  const Outcome regressed =
      beachball("check " + c + " --plugin " + worse + " --baseline " + dir + "/kept --cache off");
  EXPECT_EQ(regressed.exit_code, 1) << regressed.out;
  EXPECT_NE(regressed.out.find("worse"), std::string::npos) << regressed.out;
  EXPECT_NE(regressed.out.find(kBackend + " "), std::string::npos) << regressed.out;
}

}  // namespace
}  // namespace bb
